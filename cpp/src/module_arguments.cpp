#include "ubii/module_arguments.hpp"

#include <charconv>
#include <system_error>

#include "ubii/error.hpp"

namespace ubii
{

namespace
{

template <class T> T parse_number(std::string_view key, const std::string &text, const char *kind)
{
    T value{};
    const char *end = text.data() + text.size();
    const auto [stop, error] = std::from_chars(text.data(), end, value);
    if (text.empty() || error != std::errc() || stop != end)
        throw InvalidArgument("module argument " + std::string(key) + "=\"" + text + "\" is not " +
                              kind);
    return value;
}

} // namespace

void ModuleArguments::set(std::string key, std::string value)
{
    values_.insert_or_assign(std::move(key), std::move(value));
}

bool ModuleArguments::contains(std::string_view key) const noexcept
{
    return values_.find(key) != values_.end();
}

std::vector<std::string> ModuleArguments::keys() const
{
    std::vector<std::string> keys;
    for (const auto &entry : values_)
        keys.push_back(entry.first);
    return keys;
}

const std::string *ModuleArguments::find(std::string_view key) const
{
    read_.emplace(key);
    const auto found = values_.find(key);
    return found == values_.end() ? nullptr : &found->second;
}

std::string ModuleArguments::get(std::string_view key, std::string fallback) const
{
    const std::string *text = find(key);
    return text != nullptr ? *text : fallback;
}

double ModuleArguments::get(std::string_view key, double fallback) const
{
    const std::string *text = find(key);
    return text != nullptr ? parse_number<double>(key, *text, "a number") : fallback;
}

int ModuleArguments::get(std::string_view key, int fallback) const
{
    const std::string *text = find(key);
    return text != nullptr ? parse_number<int>(key, *text, "an integer") : fallback;
}

bool ModuleArguments::get(std::string_view key, bool fallback) const
{
    const std::string *text = find(key);
    if (text == nullptr)
        return fallback;
    for (const char *yes : {"true", "yes", "on", "1"})
        if (*text == yes)
            return true;
    for (const char *no : {"false", "no", "off", "0"})
        if (*text == no)
            return false;
    throw InvalidArgument("module argument " + std::string(key) + "=\"" + *text +
                          "\" is not true or false");
}

std::vector<std::string> ModuleArguments::unread() const
{
    std::vector<std::string> unread;
    for (const auto &entry : values_)
        if (read_.find(entry.first) == read_.end())
            unread.push_back(entry.first);
    return unread;
}

} // namespace ubii

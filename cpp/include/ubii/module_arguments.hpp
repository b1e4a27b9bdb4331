#ifndef UBII_MODULE_ARGUMENTS_HPP
#define UBII_MODULE_ARGUMENTS_HPP

// ubii::ModuleArguments: the settings a processing module's factory is made with, as text (from
// `ubii-node run --module-arg NAME:key=value`, or from a program's own configuration).
//
//     ubii::ModuleRegistry modules;
//     modules.add([](const ubii::ModuleArguments &args) {
//         return std::make_unique<Scale>(args.get("factor", 2.0));
//     });
//     modules.configure("scale", {{"factor", "0.5"}});
//
// A factory reads every argument it takes; ModuleRegistry::configure refuses arguments no factory
// read (a misspelt key is an error, not a silent default).

#include <initializer_list>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace ubii
{

class ModuleArguments
{
  public:
    ModuleArguments() = default;
    ModuleArguments(std::initializer_list<std::pair<const std::string, std::string>> values)
        : values_(values)
    {
    }

    // Replaces the value of `key`.
    void set(std::string key, std::string value);
    bool contains(std::string_view key) const noexcept;
    bool empty() const noexcept
    {
        return values_.empty();
    }
    // Every key, sorted.
    std::vector<std::string> keys() const;

    // The value of `key`, or `fallback` without one. As a number or flag, ubii::InvalidArgument
    // (naming the key and the text) when the whole text is not one: "1.5", "-3", "true"/"false",
    // "yes"/"no", "on"/"off", "1"/"0".
    std::string get(std::string_view key, std::string fallback) const;
    std::string get(std::string_view key, const char *fallback) const
    {
        return get(key, std::string(fallback));
    }
    double get(std::string_view key, double fallback) const;
    int get(std::string_view key, int fallback) const;
    bool get(std::string_view key, bool fallback) const;

    // The keys no get() asked for yet.
    std::vector<std::string> unread() const;

  private:
    const std::string *find(std::string_view key) const;

    std::map<std::string, std::string, std::less<>> values_;
    // What the factory asked for: a factory runs on one thread at a time.
    mutable std::set<std::string, std::less<>> read_;
};

} // namespace ubii

#endif

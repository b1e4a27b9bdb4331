#include "ubii/module_registry.hpp"

namespace ubii
{

namespace
{

std::string quoted(std::string_view name)
{
    return "\"" + std::string(name) + "\"";
}

std::string joined(const std::vector<std::string> &words)
{
    std::string text;
    for (const std::string &word : words)
        text += (text.empty() ? "" : ", ") + word;
    return text;
}

} // namespace

const std::string &ModuleRegistry::add(ModuleFactory factory)
{
    if (!factory)
        throw InvalidArgument("ModuleRegistry::add without a factory");
    const std::unique_ptr<ProcessingModule> sample = factory(ModuleArguments());
    if (!sample)
        throw InvalidArgument("a module factory made no module");
    const std::string &name = sample->name();
    if (name.empty())
        throw InvalidArgument("a module factory made a module without a name");
    if (contains(name))
        throw InvalidArgument("a processing module named " + quoted(name) +
                              " is registered already");
    return entries_.emplace(name, Entry{std::move(factory), sample->spec(), {}}).first->first;
}

const ModuleRegistry::Entry &ModuleRegistry::entry(std::string_view name) const
{
    const auto found = entries_.find(name);
    if (found == entries_.end())
        throw NotFound("no processing module named " + quoted(name) + " is registered");
    return found->second;
}

std::unique_ptr<ProcessingModule> ModuleRegistry::make(std::string_view name, const Entry &entry,
                                                       const ModuleArguments &arguments) const
{
    std::unique_ptr<ProcessingModule> module = entry.factory(arguments);
    if (!module || module->name() != name)
        throw InvalidArgument("the factory of processing module " + quoted(name) + " made " +
                              (module ? quoted(module->name()) : "nothing"));
    return module;
}

void ModuleRegistry::configure(std::string_view name, ModuleArguments arguments)
{
    const auto found = entries_.find(name);
    if (found == entries_.end())
        throw NotFound("no processing module named " + quoted(name) + " is registered");
    const std::unique_ptr<ProcessingModule> sample = make(name, found->second, arguments);
    const std::vector<std::string> unread = arguments.unread();
    if (!unread.empty())
        throw InvalidArgument("processing module " + quoted(name) + " takes no argument " +
                              joined(unread));
    found->second.spec = sample->spec();
    found->second.arguments = std::move(arguments);
}

const ModuleArguments &ModuleRegistry::arguments(std::string_view name) const
{
    return entry(name).arguments;
}

bool ModuleRegistry::contains(std::string_view name) const noexcept
{
    return entries_.find(name) != entries_.end();
}

std::vector<std::string> ModuleRegistry::names() const
{
    std::vector<std::string> names;
    for (const auto &entry : entries_)
        names.push_back(entry.first);
    return names;
}

std::vector<ProcessingModuleSpec> ModuleRegistry::specs() const
{
    std::vector<ProcessingModuleSpec> specs;
    for (const auto &entry : entries_)
        specs.push_back(entry.second.spec);
    return specs;
}

const ProcessingModuleSpec &ModuleRegistry::spec(std::string_view name) const
{
    return entry(name).spec;
}

void ModuleRegistry::retain(const std::vector<std::string> &names)
{
    for (const std::string &name : names)
        entry(name);
    for (auto it = entries_.begin(); it != entries_.end();) {
        bool named = false;
        for (const std::string &name : names)
            named = named || name == it->first;
        it = named ? std::next(it) : entries_.erase(it);
    }
}

std::unique_ptr<ProcessingModule> ModuleRegistry::create(std::string_view name) const
{
    const Entry &found = entry(name);
    return make(name, found, found.arguments);
}

} // namespace ubii

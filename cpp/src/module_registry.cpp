#include "ubii/module_registry.hpp"

namespace ubii
{

void ModuleRegistry::add(ModuleFactory factory)
{
    if (!factory)
        throw InvalidArgument("ModuleRegistry::add without a factory");
    const std::unique_ptr<ProcessingModule> sample = factory();
    if (!sample)
        throw InvalidArgument("a module factory made no module");
    const std::string &name = sample->name();
    if (contains(name))
        throw InvalidArgument("a processing module named \"" + name + "\" is registered already");
    entries_.emplace(name, Entry{std::move(factory), sample->spec()});
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

std::unique_ptr<ProcessingModule> ModuleRegistry::create(std::string_view name) const
{
    const auto found = entries_.find(name);
    if (found == entries_.end())
        throw NotFound("no processing module named \"" + std::string(name) + "\" is registered");
    std::unique_ptr<ProcessingModule> module = found->second.factory();
    if (!module || module->name() != name)
        throw InvalidArgument("the factory of processing module \"" + std::string(name) +
                              "\" made " + (module ? "\"" + module->name() + "\"" : "nothing"));
    return module;
}

} // namespace ubii

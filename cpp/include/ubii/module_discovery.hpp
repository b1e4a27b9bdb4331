#ifndef UBII_MODULE_DISCOVERY_HPP
#define UBII_MODULE_DISCOVERY_HPP

// Where a program's processing modules come from besides its own ModuleRegistry::add calls:
// modules linked into the program that register themselves, and plugins (ubii/plugin.hpp) loaded
// from directories.
//
//     // in a module's source file, linked into the program:
//     UBII_REGISTER_MODULE(Sum)
//
//     ubii::ModuleRegistry modules;
//     report(ubii::add_linked_modules(modules));
//     for (const auto &dir : ubii::module_search_path())
//         for (const auto &plugin : ubii::load_plugins(modules, dir))
//             report(plugin);
//
// Nothing here throws for a bad module or plugin: it is refused, with a message naming the file,
// and the rest still loads. A registrar in a static library is linked only when something else of
// its object file is: register modules in the program's own sources (or link with --whole-archive).

#include <filesystem>
#include <string>
#include <vector>

#include "ubii/module_registry.hpp"

namespace ubii
{

// What loading one plugin (or the linked modules: file "(linked)") did.
struct PluginReport {
    std::filesystem::path file;
    // The plugin's name from its manifest ("" when it was refused before).
    std::string plugin;
    // The modules added to the registry.
    std::vector<std::string> modules;
    // Why the plugin or one of its modules was refused, each message naming the file.
    std::vector<std::string> errors;
};

// Loads the plugin `path`, or every "*.so" file in the directory `path` (sorted by name), into
// `registry`. A file that is not a loadable library, lacks the entry point, was built for another
// ABI or libubii version, or whose factory list throws is refused whole; a module whose factory
// throws or makes a name already taken is refused alone. ubii::NotFound if `path` does not exist.
// Plugins stay loaded until the process ends: modules made from them may outlive the registry.
std::vector<PluginReport> load_plugins(ModuleRegistry &registry, const std::filesystem::path &path);

// Adds every module registered with UBII_REGISTER_MODULE in this process.
PluginReport add_linked_modules(ModuleRegistry &registry);

// The directories plugins are looked for in: each of UBII_MODULE_PATH (':'-separated), then the
// installation's own <libdir>/ubii/modules (beside the libubii_cpp library). Only those that exist.
std::vector<std::filesystem::path> module_search_path();

namespace detail
{
struct ModuleRegistrar {
    explicit ModuleRegistrar(ModuleFactory factory) noexcept;
};
} // namespace detail

} // namespace ubii

#define UBII_MODULE_REGISTRAR_NAME2(line) ubii_module_registrar_##line
#define UBII_MODULE_REGISTRAR_NAME(line) UBII_MODULE_REGISTRAR_NAME2(line)
// Registers module class `module_class` (see ubii::module_factory) for add_linked_modules.
#define UBII_REGISTER_MODULE(module_class)                                                         \
    static const ::ubii::detail::ModuleRegistrar UBII_MODULE_REGISTRAR_NAME(__LINE__)(             \
        ::ubii::module_factory<module_class>());

#endif

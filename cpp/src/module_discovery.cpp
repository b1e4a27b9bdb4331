#include "ubii/module_discovery.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>
#include <exception>
#include <system_error>

#include "exception_text.hpp"
#include "ubii/plugin.hpp"

namespace ubii
{

namespace
{

// The factories UBII_REGISTER_MODULE collected, in the order the program's static objects were
// initialised. A function-local static: registrars run before main, in any order of files.
std::vector<ModuleFactory> &linked_factories()
{
    static std::vector<ModuleFactory> factories;
    return factories;
}

// Adds each factory, refusing the ones that throw or collide; `source` names where they came from.
void add_each(ModuleRegistry &registry, const std::vector<ModuleFactory> &factories,
              PluginReport &report)
{
    const std::string source = report.file.string();
    for (std::size_t index = 0; index < factories.size(); ++index) {
        try {
            report.modules.push_back(registry.add(factories[index]));
        } catch (...) {
            report.errors.push_back(source + ": module " + std::to_string(index + 1) + " of " +
                                    std::to_string(factories.size()) +
                                    " refused: " + detail::what_of(std::current_exception()));
        }
    }
}

std::string version_text(std::uint32_t major, std::uint32_t minor)
{
    return std::to_string(major) + "." + std::to_string(minor);
}

// Why `manifest` cannot be used by this build, or "".
std::string mismatch(const PluginManifest &manifest)
{
    if (manifest.plugin_abi != UBII_PLUGIN_ABI_VERSION)
        return "built for plugin ABI " + std::to_string(manifest.plugin_abi) + ", this is " +
               std::to_string(UBII_PLUGIN_ABI_VERSION);
    if (manifest.cxx_abi != UBII_PLUGIN_CXX_ABI)
        return "built for C++ ABI " + std::to_string(manifest.cxx_abi) + ", this is " +
               std::to_string(UBII_PLUGIN_CXX_ABI);
    if (manifest.ubii_major != UBII_VERSION_MAJOR || manifest.ubii_minor != UBII_VERSION_MINOR)
        return "built against libubii " + version_text(manifest.ubii_major, manifest.ubii_minor) +
               ", this is " + version_text(UBII_VERSION_MAJOR, UBII_VERSION_MINOR);
    if (manifest.factories == nullptr)
        return "its manifest has no factory list";
    return "";
}

PluginReport load_plugin(ModuleRegistry &registry, const std::filesystem::path &file)
{
    PluginReport report;
    report.file = file;
    const std::string source = file.string();
    // RTLD_NODELETE: modules made from the plugin may live longer than anything here.
    void *library = dlopen(source.c_str(), RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
    if (library == nullptr) {
        const char *reason = dlerror();
        report.errors.push_back(
            source + ": cannot be loaded: " + (reason != nullptr ? reason : "unknown reason"));
        return report;
    }
    // dlsym returns an object pointer; POSIX guarantees it converts to a function pointer.
    const auto entry =
        reinterpret_cast<ubii_plugin_entry_point>(dlsym(library, UBII_PLUGIN_ENTRY_POINT));
    if (entry == nullptr) {
        report.errors.push_back(source + ": not a libubii plugin (no " UBII_PLUGIN_ENTRY_POINT
                                         " entry point; UBII_PLUGIN defines it)");
        dlclose(library);
        return report;
    }
    const PluginManifest *manifest = entry();
    const std::string refused =
        manifest == nullptr ? "its entry point returned no manifest" : mismatch(*manifest);
    if (!refused.empty()) {
        report.errors.push_back(source + ": refused: " + refused);
        dlclose(library);
        return report;
    }
    report.plugin = manifest->name != nullptr ? manifest->name : "";
    std::vector<ModuleFactory> factories;
    try {
        factories = manifest->factories();
    } catch (...) {
        report.errors.push_back(source + ": refused: its factory list threw: " +
                                detail::what_of(std::current_exception()));
        dlclose(library);
        return report;
    }
    add_each(registry, factories, report);
    // Nothing of it in use: let it go (RTLD_NODELETE keeps it mapped, which is harmless).
    if (report.modules.empty())
        dlclose(library);
    return report;
}

// The directory libubii_cpp was loaded from.
std::filesystem::path library_directory()
{
    Dl_info info{};
    if (dladdr(reinterpret_cast<void *>(&module_search_path), &info) == 0 ||
        info.dli_fname == nullptr)
        return {};
    std::error_code error;
    const std::filesystem::path library = std::filesystem::canonical(info.dli_fname, error);
    return error ? std::filesystem::path() : library.parent_path();
}

} // namespace

namespace detail
{
ModuleRegistrar::ModuleRegistrar(ModuleFactory factory) noexcept
{
    linked_factories().push_back(std::move(factory));
}
} // namespace detail

std::vector<PluginReport> load_plugins(ModuleRegistry &registry, const std::filesystem::path &path)
{
    std::error_code error;
    if (!std::filesystem::exists(path, error))
        throw NotFound("no plugin or plugin directory " + path.string());
    if (!std::filesystem::is_directory(path, error))
        return {load_plugin(registry, path)};
    std::vector<std::filesystem::path> files;
    for (const auto &item : std::filesystem::directory_iterator(path, error))
        if (item.path().extension() == ".so" && !item.is_directory(error))
            files.push_back(item.path());
    std::sort(files.begin(), files.end());
    std::vector<PluginReport> reports;
    for (const auto &file : files)
        reports.push_back(load_plugin(registry, file));
    return reports;
}

PluginReport add_linked_modules(ModuleRegistry &registry)
{
    PluginReport report;
    report.file = "(linked)";
    add_each(registry, linked_factories(), report);
    return report;
}

std::vector<std::filesystem::path> module_search_path()
{
    std::vector<std::filesystem::path> dirs;
    std::error_code error;
    const auto add_existing = [&](const std::filesystem::path &dir) {
        if (!dir.empty() && std::filesystem::is_directory(dir, error) &&
            std::find(dirs.begin(), dirs.end(), dir) == dirs.end())
            dirs.push_back(dir);
    };
    if (const char *variable = std::getenv("UBII_MODULE_PATH")) {
        std::string list = variable;
        std::size_t start = 0;
        while (start <= list.size()) {
            const std::size_t end = std::min(list.find(':', start), list.size());
            add_existing(list.substr(start, end - start));
            start = end + 1;
        }
    }
    const std::filesystem::path libdir = library_directory();
    if (!libdir.empty())
        add_existing(libdir / "ubii" / "modules");
    return dirs;
}

} // namespace ubii

#ifndef UBII_PLUGIN_HPP
#define UBII_PLUGIN_HPP

// A plugin: a shared library of processing modules that `ubii-node run` (or any program, through
// ubii::load_plugins) finds in a directory and offers to masters. Its one source line of glue:
//
//     #include "ubii/plugin.hpp"
//     UBII_PLUGIN("my-modules", ubii::module_factory<Sum>(), ubii::module_factory<Scale>())
//
// and in CMake: add_library(my_modules MODULE sum.cpp) with target_link_libraries(my_modules
// PRIVATE ubii::ubii_cpp). The macro defines the plugin's one entry point, the C function
// ubii_plugin_v1, which returns a manifest: the ABI the plugin was built for, then its factories.
// A loader refuses a plugin built for another plugin ABI, another C++ ABI or another libubii
// version (major.minor: the C++ layer's classes cross the boundary), before calling any of it.

#include <cstdint>
#include <vector>

#include "ubii/module_registry.hpp"
#include "ubii/version.h"

// Changes whenever PluginManifest or the way factories are called changes.
#define UBII_PLUGIN_ABI_VERSION 1u

#if defined(__GXX_ABI_VERSION)
#define UBII_PLUGIN_CXX_ABI static_cast<std::uint32_t>(__GXX_ABI_VERSION)
#else
#define UBII_PLUGIN_CXX_ABI 0u
#endif

namespace ubii
{

// The first member is read before any other: a future ABI may change everything after it.
struct PluginManifest {
    std::uint32_t plugin_abi;
    std::uint32_t cxx_abi;
    std::uint32_t ubii_major;
    std::uint32_t ubii_minor;
    const char *name;
    std::vector<ModuleFactory> (*factories)();
};

// The manifest of the build including this header (what UBII_PLUGIN fills in).
#define UBII_PLUGIN_MANIFEST(plugin_name, factory_list)                                            \
    ::ubii::PluginManifest                                                                         \
    {                                                                                              \
        UBII_PLUGIN_ABI_VERSION, UBII_PLUGIN_CXX_ABI, UBII_VERSION_MAJOR, UBII_VERSION_MINOR,      \
            plugin_name, factory_list                                                              \
    }

} // namespace ubii

// The entry point's name and type: one per plugin ABI version.
#define UBII_PLUGIN_ENTRY_POINT "ubii_plugin_v1"
extern "C" {
typedef const ::ubii::PluginManifest *(*ubii_plugin_entry_point)(void);
}

#define UBII_PLUGIN(plugin_name, ...)                                                              \
    static std::vector<::ubii::ModuleFactory> ubii_plugin_factories()                              \
    {                                                                                              \
        return {__VA_ARGS__};                                                                      \
    }                                                                                              \
    extern "C" __attribute__((visibility("default"))) const ::ubii::PluginManifest *               \
    ubii_plugin_v1(void)                                                                           \
    {                                                                                              \
        static const ::ubii::PluginManifest manifest =                                             \
            UBII_PLUGIN_MANIFEST(plugin_name, ubii_plugin_factories);                              \
        return &manifest;                                                                          \
    }

#endif

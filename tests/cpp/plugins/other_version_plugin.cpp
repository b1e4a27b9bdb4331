// A plugin built against another libubii minor version, whose C++ classes may differ.
#include "ubii/plugin.hpp"

extern "C" __attribute__((visibility("default"))) const ubii::PluginManifest *ubii_plugin_v1(void)
{
    static const ubii::PluginManifest manifest{
        UBII_PLUGIN_ABI_VERSION, UBII_PLUGIN_CXX_ABI,
        UBII_VERSION_MAJOR,      UBII_VERSION_MINOR + 1,
        "test-other-version",    [] { return std::vector<ubii::ModuleFactory>{}; }};
    return &manifest;
}

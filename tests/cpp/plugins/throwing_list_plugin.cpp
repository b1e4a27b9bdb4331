// A plugin whose factory list itself throws while it is asked for.
#include <stdexcept>
#include <vector>

#include "ubii/plugin.hpp"

namespace
{
std::vector<ubii::ModuleFactory> no_factories()
{
    throw std::runtime_error("cannot read my configuration");
}
} // namespace

extern "C" __attribute__((visibility("default"))) const ubii::PluginManifest *ubii_plugin_v1(void)
{
    static const ubii::PluginManifest manifest =
        UBII_PLUGIN_MANIFEST("test-throwing-list", no_factories);
    return &manifest;
}

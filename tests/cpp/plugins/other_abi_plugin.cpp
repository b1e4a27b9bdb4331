// A plugin from a future libubii: its manifest says plugin ABI 99 (and may differ after that).
#include "ubii/plugin.hpp"

extern "C" __attribute__((visibility("default"))) const ubii::PluginManifest *ubii_plugin_v1(void)
{
    static const ubii::PluginManifest manifest{
        99, UBII_PLUGIN_CXX_ABI, UBII_VERSION_MAJOR, UBII_VERSION_MINOR, "test-other-abi", nullptr};
    return &manifest;
}

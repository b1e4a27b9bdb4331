// One plugin with a good module, a module whose name the good plugin took already, and a factory
// that throws: only the first may load.
#include <stdexcept>

#include "scale_module.hpp"
#include "ubii/plugin.hpp"

namespace
{

std::unique_ptr<ubii::ProcessingModule> make_unique_name(const ubii::ModuleArguments &arguments)
{
    return std::make_unique<ubii_plugin_test::Scale>(arguments, "plugin_mixed_scale");
}

std::unique_ptr<ubii::ProcessingModule> make_taken_name(const ubii::ModuleArguments &arguments)
{
    return std::make_unique<ubii_plugin_test::Scale>(arguments, "plugin_scale");
}

std::unique_ptr<ubii::ProcessingModule> make_nothing_but_trouble(const ubii::ModuleArguments &)
{
    throw std::runtime_error("no licence for this module");
}

} // namespace

UBII_PLUGIN("test-mixed", make_unique_name, make_taken_name, make_nothing_but_trouble)

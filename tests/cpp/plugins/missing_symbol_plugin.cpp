// A plugin that needs a function no library provides: the loader cannot bind it.
#include "scale_module.hpp"
#include "ubii/plugin.hpp"

extern "C" double ubii_test_function_nobody_defines(double);

namespace
{

class Missing : public ubii::ProcessingModule
{
  public:
    Missing()
        : ProcessingModule({"plugin_missing", "", {}, {ubii::output<double>("y")}, ubii::Free{}})
    {
    }
    void on_processing(ubii::Pass &pass) override
    {
        pass.set_output("y", ubii_test_function_nobody_defines(1.0));
    }
};

} // namespace

UBII_PLUGIN("test-missing-symbol", ubii::module_factory<Missing>())

// A plugin as a user writes one: two modules, one of them taking arguments.
#include "scale_module.hpp"
#include "ubii/plugin.hpp"

namespace
{

class Negate : public ubii::ProcessingModule
{
  public:
    Negate()
        : ProcessingModule({"plugin_negate",
                            "negated = -value",
                            {ubii::input<double>("value")},
                            {ubii::output<double>("negated")},
                            ubii::TriggerOnInput{}})
    {
    }
    void on_processing(ubii::Pass &pass) override
    {
        pass.set_output("negated", -pass.input<double>("value"));
    }
};

} // namespace

UBII_PLUGIN("test-good", ubii::module_factory<ubii_plugin_test::Scale>(),
            ubii::module_factory<Negate>())

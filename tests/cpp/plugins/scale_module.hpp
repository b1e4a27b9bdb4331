#ifndef UBII_TEST_SCALE_MODULE_HPP
#define UBII_TEST_SCALE_MODULE_HPP

// A module with an argument, for the plugin and CLI tests: scaled = factor * value on every value.

#include <memory>
#include <string>

#include "ubii/ubii.hpp"

namespace ubii_plugin_test
{

class Scale : public ubii::ProcessingModule
{
  public:
    explicit Scale(const ubii::ModuleArguments &arguments, std::string name = "plugin_scale")
        : ProcessingModule({std::move(name),
                            "scaled = factor * value (argument factor, default 2)",
                            {ubii::input<double>("value")},
                            {ubii::output<double>("scaled")},
                            ubii::TriggerOnInput{}}),
          factor_(arguments.get("factor", 2.0))
    {
        if (factor_ == 0)
            throw ubii::InvalidArgument("factor 0 would scale everything away");
    }
    void on_processing(ubii::Pass &pass) override
    {
        pass.set_output("scaled", factor_ * pass.input<double>("value"));
    }

  private:
    double factor_;
};

} // namespace ubii_plugin_test

#endif

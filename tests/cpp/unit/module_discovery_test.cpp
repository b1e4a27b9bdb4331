// Module arguments, the registry's configuration, self-registered modules and plugins loaded from
// directories (tests/cpp/plugins: one good plugin, and a directory of every kind of refusal).

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "../plugins/scale_module.hpp"
#include "ubii/ubii.hpp"

namespace
{

const std::filesystem::path good_dir = UBII_TEST_PLUGIN_DIR "/good";
const std::filesystem::path bad_dir = UBII_TEST_PLUGIN_DIR "/bad";

class Linked : public ubii::ProcessingModule
{
  public:
    Linked()
        : ProcessingModule({"linked_module", "", {}, {ubii::output<double>("y")}, ubii::Free{}})
    {
    }
    void on_processing(ubii::Pass &pass) override
    {
        pass.set_output("y", 1.0);
    }
};

} // namespace

UBII_REGISTER_MODULE(Linked)

namespace
{

bool contains_text(const std::vector<std::string> &lines, const std::string &text)
{
    return std::any_of(lines.begin(), lines.end(), [&](const std::string &line) {
        return line.find(text) != std::string::npos;
    });
}

const ubii::PluginReport &report_of(const std::vector<ubii::PluginReport> &reports,
                                    const std::string &file_name)
{
    for (const auto &report : reports)
        if (report.file.filename() == file_name)
            return report;
    throw std::runtime_error("no report for " + file_name);
}

double scaled_by(const ubii::ModuleRegistry &registry, const std::string &name, double value)
{
    ubii::Scheduler scheduler;
    const std::string id = scheduler.add(registry.create(name));
    scheduler.start(id);
    double result = 0;
    scheduler.on_output([&](const ubii::ProcessingModule &, const ubii::PassOutput &output) {
        result = output.value.as<double>();
        return ubii::Status::ok;
    });
    scheduler.feed(id, "value", std::make_shared<const ubii::Record>("/in", ubii::Value(value)));
    scheduler.run_due();
    return result;
}

} // namespace

TEST(ModuleArguments, ParsesNumbersAndFlagsWholeOrRefusesNamingTheKey)
{
    const ubii::ModuleArguments arguments{
        {"factor", "0.5"}, {"count", "-3"}, {"fast", "yes"}, {"lang", "deu"}, {"bad", "1.5x"}};
    EXPECT_DOUBLE_EQ(arguments.get("factor", 2.0), 0.5);
    EXPECT_EQ(arguments.get("count", 0), -3);
    EXPECT_TRUE(arguments.get("fast", false));
    EXPECT_EQ(arguments.get("lang", "eng"), "deu");
    EXPECT_EQ(arguments.get("absent", "eng"), "eng");
    EXPECT_DOUBLE_EQ(arguments.get("absent2", 7.0), 7.0);
    try {
        arguments.get("bad", 1.0);
        FAIL() << "1.5x read as a number";
    } catch (const ubii::InvalidArgument &error) {
        EXPECT_NE(std::string(error.what()).find("bad=\"1.5x\""), std::string::npos)
            << error.what();
    }
    EXPECT_THROW(arguments.get("factor", 1), ubii::InvalidArgument); // 0.5 is not an integer
    EXPECT_THROW(arguments.get("lang", true), ubii::InvalidArgument);
}

TEST(ModuleArguments, KnowsWhichKeysWereNeverRead)
{
    const ubii::ModuleArguments arguments{{"factor", "3"}, {"fator", "4"}};
    arguments.get("factor", 1.0);
    EXPECT_EQ(arguments.unread(), std::vector<std::string>{"fator"});
}

TEST(ModuleRegistryArguments, ConfiguredArgumentsReachEveryInstance)
{
    ubii::ModuleRegistry registry;
    registry.add<ubii_plugin_test::Scale>();
    EXPECT_DOUBLE_EQ(scaled_by(registry, "plugin_scale", 21), 42);
    registry.configure("plugin_scale", {{"factor", "-1"}});
    EXPECT_DOUBLE_EQ(scaled_by(registry, "plugin_scale", 21), -21);
    EXPECT_EQ(registry.arguments("plugin_scale").get("factor", ""), "-1");
}

TEST(ModuleRegistryArguments, RefusesMisspeltRefusedAndUnknownArgumentsAndKeepsTheOldOnes)
{
    ubii::ModuleRegistry registry;
    registry.add<ubii_plugin_test::Scale>();
    registry.configure("plugin_scale", {{"factor", "3"}});
    try {
        registry.configure("plugin_scale", {{"factr", "4"}});
        FAIL() << "a misspelt key was taken";
    } catch (const ubii::InvalidArgument &error) {
        EXPECT_NE(std::string(error.what()).find("takes no argument factr"), std::string::npos)
            << error.what();
    }
    EXPECT_THROW(registry.configure("plugin_scale", {{"factor", "0"}}), ubii::InvalidArgument);
    EXPECT_THROW(registry.configure("plugin_scale", {{"factor", "three"}}), ubii::InvalidArgument);
    EXPECT_THROW(registry.configure("no_such_module", {}), ubii::NotFound);
    EXPECT_DOUBLE_EQ(scaled_by(registry, "plugin_scale", 1), 3);
}

TEST(ModuleRegistryArguments, RetainKeepsOnlyTheNamedModulesOrNothingChanges)
{
    ubii::ModuleRegistry registry;
    registry.add<ubii_plugin_test::Scale>();
    registry.add<Linked>();
    EXPECT_THROW(registry.retain({"plugin_scale", "typo"}), ubii::NotFound);
    EXPECT_EQ(registry.size(), 2u);
    registry.retain({"plugin_scale"});
    EXPECT_EQ(registry.names(), std::vector<std::string>{"plugin_scale"});
}

TEST(LinkedModules, ARegisteredModuleIsAddedAndASecondAddIsRefused)
{
    ubii::ModuleRegistry registry;
    const ubii::PluginReport first = ubii::add_linked_modules(registry);
    EXPECT_EQ(first.modules, std::vector<std::string>{"linked_module"});
    EXPECT_TRUE(first.errors.empty());
    const ubii::PluginReport second = ubii::add_linked_modules(registry);
    EXPECT_TRUE(second.modules.empty());
    ASSERT_EQ(second.errors.size(), 1u);
    EXPECT_NE(second.errors[0].find("registered already"), std::string::npos) << second.errors[0];
}

TEST(Plugins, AGoodPluginsModulesAreMadeWithTheirArguments)
{
    ubii::ModuleRegistry registry;
    const auto reports = ubii::load_plugins(registry, good_dir);
    ASSERT_EQ(reports.size(), 1u);
    EXPECT_EQ(reports[0].plugin, "test-good");
    EXPECT_TRUE(reports[0].errors.empty()) << reports[0].errors[0];
    EXPECT_EQ(registry.names(), (std::vector<std::string>{"plugin_negate", "plugin_scale"}));
    EXPECT_EQ(registry.spec("plugin_scale").language(), ubii::ProcessingModuleSpec::CPP);
    registry.configure("plugin_scale", {{"factor", "10"}});
    EXPECT_DOUBLE_EQ(scaled_by(registry, "plugin_scale", 4.2), 42);
}

TEST(Plugins, EveryKindOfRefusalNamesItsFileAndTheGoodModulesStillLoad)
{
    ubii::ModuleRegistry registry;
    ubii::load_plugins(registry, good_dir);
    const auto reports = ubii::load_plugins(registry, bad_dir);
    ASSERT_EQ(reports.size(), 7u);
    for (const auto &report : reports)
        for (const auto &error : report.errors)
            EXPECT_EQ(error.rfind(report.file.string() + ": ", 0), 0u) << error;

    const auto &mixed = report_of(reports, "mixed_plugin.so");
    EXPECT_EQ(mixed.modules, std::vector<std::string>{"plugin_mixed_scale"});
    ASSERT_EQ(mixed.errors.size(), 2u);
    EXPECT_TRUE(contains_text(mixed.errors, "module 2 of 3 refused: a processing module named "
                                            "\"plugin_scale\" is registered already"));
    EXPECT_TRUE(contains_text(mixed.errors, "module 3 of 3 refused: no licence for this module"));

    EXPECT_TRUE(contains_text(report_of(reports, "other_abi_plugin.so").errors,
                              "refused: built for plugin ABI 99, this is 1"));
    EXPECT_TRUE(contains_text(report_of(reports, "other_version_plugin.so").errors,
                              "refused: built against libubii"));
    EXPECT_TRUE(contains_text(report_of(reports, "no_entry_plugin.so").errors,
                              "not a libubii plugin (no ubii_plugin_v1"));
    EXPECT_TRUE(contains_text(report_of(reports, "missing_symbol_plugin.so").errors,
                              "ubii_test_function_nobody_defines"));
    EXPECT_TRUE(contains_text(report_of(reports, "throwing_list_plugin.so").errors,
                              "its factory list threw: cannot read my configuration"));
    EXPECT_TRUE(contains_text(report_of(reports, "text_file.so").errors, "cannot be loaded"));

    EXPECT_EQ(registry.names(),
              (std::vector<std::string>{"plugin_mixed_scale", "plugin_negate", "plugin_scale"}));
}

TEST(Plugins, OneFileLoadsAndAMissingPathIsNotFound)
{
    ubii::ModuleRegistry registry;
    const auto reports = ubii::load_plugins(registry, good_dir / "good_plugin.so");
    ASSERT_EQ(reports.size(), 1u);
    EXPECT_EQ(reports[0].modules.size(), 2u);
    EXPECT_THROW(ubii::load_plugins(registry, good_dir / "absent"), ubii::NotFound);
}

TEST(Plugins, TheSearchPathTakesUbiiModulePathsThatExistInOrder)
{
    const std::string list = bad_dir.string() + "::/nonexistent/dir:" + good_dir.string();
    ASSERT_EQ(setenv("UBII_MODULE_PATH", list.c_str(), 1), 0);
    const auto dirs = ubii::module_search_path();
    unsetenv("UBII_MODULE_PATH");
    ASSERT_GE(dirs.size(), 2u);
    EXPECT_EQ(dirs[0], bad_dir);
    EXPECT_EQ(dirs[1], good_dir);
}

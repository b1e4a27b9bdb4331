// Testing one's own processing module against a real master with ubii::testing: copy this file
// and CMakeLists.txt beside your module, and `ctest` runs it (README.md here).
#include <memory>

#include "ubii/testing.hpp"

using namespace std::chrono_literals;

// The module under test: scaled = factor * value.
class Scale : public ubii::ProcessingModule
{
  public:
    explicit Scale(double factor = 2)
        : ProcessingModule({"scale",
                            "scaled = factor * value",
                            {ubii::input<double>("value")},
                            {ubii::output<double>("scaled")},
                            ubii::TriggerOnInput{}}),
          factor_(factor)
    {
    }
    void on_processing(ubii::Pass &pass) override
    {
        pass.set_output("scaled", factor_ * pass.input<double>("value"));
    }

  private:
    double factor_;
};

class ScaleTest : public ubii::testing::MasterTest
{
};

TEST_F(ScaleTest, ScalesEveryValueThatArrivesThroughTheMaster)
{
    auto running = run_module(
        std::make_unique<Scale>(3.0),
        ubii::Wiring().input("value", "/scale-test/in").output("scaled", "/scale-test/out"));
    auto out = probe("/scale-test/out");
    for (double value : {1.0, -2.5, 14.0}) {
        node().publish("/scale-test/in", value);
        EXPECT_DOUBLE_EQ(out.next<double>(5s), 3 * value);
    }
}

TEST_F(ScaleTest, AnotherNodeSeesWhatTheTestPublishes)
{
    ubii::Node &other = add_node("observer");
    std::vector<std::string> seen;
    auto subscription = other.subscribe<std::string>(
        "/scale-test/text",
        [&](const std::string &text, const ubii::RecordInfo &) { seen.push_back(text); });
    EXPECT_TRUE(run_until([&] { return !other.subscriptions_pending(); }, 5s));
    node().publish("/scale-test/text", std::string("hello"));
    EXPECT_TRUE(run_until([&] { return !seen.empty(); }, 5s));
    EXPECT_EQ(seen, std::vector<std::string>{"hello"});
}

TEST_F(ScaleTest, RunsInASessionTheMasterAssigns)
{
    if (!master().assigns_sessions)
        GTEST_SKIP() << "the npm master runs session modules itself; UBII_MASTER_SOURCE=DIR runs "
                        "the current master, which assigns them to nodes";
    ubii::ModuleRegistry modules;
    modules.add([] { return std::make_unique<Scale>(5.0); });
    ubii::Session session;
    session.set_name("scale-session");
    session.add_processing_modules()->set_name("scale");
    ubii::IOMapping *mapping = session.add_io_mappings();
    mapping->set_processing_module_name("scale");
    auto *input = mapping->add_input_mappings();
    input->set_input_name("value");
    input->set_topic("/scale-session/in");
    auto *output = mapping->add_output_mappings();
    output->set_output_name("scaled");
    output->set_topic("/scale-session/out");

    auto out = probe("/scale-session/out");
    ASSERT_FALSE(start_session(std::move(modules), session).empty());
    node().publish("/scale-session/in", 8.4);
    EXPECT_DOUBLE_EQ(out.next<double>(5s), 42.0);
}

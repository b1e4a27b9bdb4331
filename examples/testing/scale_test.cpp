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

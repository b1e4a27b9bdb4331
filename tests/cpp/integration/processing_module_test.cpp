// Processing modules on a ubii::Node against the real master: inputs from and outputs to the
// official Node.js node, a worker pass that does not stall the node, errors reported by name.
#include <atomic>
#include <optional>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <poll.h>
#include <unistd.h>

#include "child_process.h"
#include "cpp_test_support.hpp"
#include "test_node.h"

using namespace std::chrono_literals;

namespace
{

std::string run_id(const char *what)
{
    return std::string(what) + std::to_string(getpid());
}

std::unique_ptr<ubii::ProcessingModule> sum_module(ubii::ProcessingMode mode)
{
    return ubii::make_module({"sum",
                              "adds a and b",
                              {ubii::input<double>("a"), ubii::input<double>("b")},
                              {ubii::output<double>("sum")},
                              mode},
                             [](ubii::Pass &pass) {
                                 pass.set_output("sum",
                                                 pass.input<double>("a") + pass.input<double>("b"));
                             });
}

TEST(ProcessingModuleOnMaster, SumsWhatTheNodeJsNodePublishesAndTheNodeJsNodeReceivesIt)
{
    ubii::Node node(ubii_cpp_test::options_for("cpp-pm-sum"));
    std::vector<std::string> errors;
    node.on_error([&](ubii::Status, std::string_view detail) { errors.emplace_back(detail); });
    node.connect(10s);
    const std::string run = run_id("sum");
    const std::string prefix = "/pm/" + run + "/";
    ubii::RunningModule sum =
        node.run(sum_module(ubii::TriggerOnInput{0ms, true}), ubii::Wiring()
                                                                  .input("a", prefix + "a")
                                                                  .input("b", prefix + "b")
                                                                  .output("sum", prefix + "sum"));
    EXPECT_EQ(sum.status(), ubii::ProcessingStatus::processing);
    node.run_for(300ms); // the subscriptions reach the master

    ubii_test::ChildProcess peer({"node", UBII_CPP_SUM_PEER, UBII_NODEJS_CLIENT,
                                  ubii_test::service_url(), ubii_test::topic_zmq_url(), run, "4"});
    ASSERT_TRUE(peer.started());
    const bool done = node.run_until(
        [&] {
            for (const auto &line : peer.lines()) {
                if (line == "PEER done")
                    return true;
                if (line.rfind("PEER error", 0) == 0)
                    ADD_FAILURE() << line;
            }
            return false;
        },
        30s);
    std::string seen;
    for (const auto &line : peer.lines())
        seen += line + "\n";
    ASSERT_TRUE(done) << "the Node.js node did not receive every sum:\n" << seen;
    // 0 + 0 first: an output the Node.js node's own modules would not publish.
    EXPECT_NE(seen.find("PEER sum 0\n"), std::string::npos) << seen;
    EXPECT_NE(seen.find("PEER sum 33\n"), std::string::npos) << seen;
    const ubii::Timing timing = sum.timing();
    EXPECT_GE(timing.passes, 4u);
    EXPECT_EQ(timing.errors, 0u);
    EXPECT_EQ(timing.outputs_failed, 0u);
    EXPECT_TRUE(errors.empty()) << errors.front();
    EXPECT_EQ(peer.stop(SIGTERM, 5s), 0);
}

TEST(ProcessingModuleOnMaster, AWorkerPassOf300msDoesNotStallTheNodesRoundTrips)
{
    ubii::Node node(ubii_cpp_test::options_for("cpp-pm-worker"));
    node.connect(10s);
    const std::string topic = "/pm/" + run_id("worker") + "/slow";
    std::atomic<int> passes{0};
    ubii::ModuleDescription description{"slow",       "sleeps 300 ms per pass",
                                        {},           {ubii::output<double>("done")},
                                        ubii::Free{}, ubii::Executor::worker};
    ubii::RunningModule slow =
        node.run(ubii::make_module(description,
                                   [&](ubii::Pass &pass) {
                                       std::this_thread::sleep_for(300ms);
                                       pass.set_output("done", double(++passes));
                                   }),
                 ubii::Wiring().output("done", topic));
    int outputs = 0;
    auto subscription =
        node.subscribe<double>(topic, [&](double, const ubii::RecordInfo &) { ++outputs; });

    // Round trips while passes run: a stalled loop would take 300 ms for one.
    std::vector<std::chrono::milliseconds> round_trips;
    const auto end = std::chrono::steady_clock::now() + 2s;
    while (std::chrono::steady_clock::now() < end) {
        const auto sent = std::chrono::steady_clock::now();
        node.wait(node.master().server_configuration(), 2s);
        round_trips.push_back(std::chrono::duration_cast<std::chrono::milliseconds>(
            std::chrono::steady_clock::now() - sent));
    }
    node.run_until([&] { return outputs >= 3; }, 3s);
    EXPECT_GE(passes.load(), 5);
    EXPECT_GE(outputs, 3) << "the worker's outputs were not published";
    ASSERT_GE(round_trips.size(), 20u);
    const auto slowest = *std::max_element(round_trips.begin(), round_trips.end());
    EXPECT_LT(slowest, 150ms) << "a round trip waited for a worker pass";
    EXPECT_EQ(slow.timing().errors, 0u);
    slow.remove();
    EXPECT_EQ(slow.status(), ubii::ProcessingStatus::destroyed);
}

TEST(ProcessingModuleOnMaster, AnExceptionInAPassIsReportedAndTheNextPassRuns)
{
    ubii::Node node(ubii_cpp_test::options_for("cpp-pm-throws"));
    std::vector<std::string> errors;
    node.on_error([&](ubii::Status status, std::string_view detail) {
        if (status == ubii::Status::callback_threw)
            errors.emplace_back(detail);
    });
    node.connect(10s);
    const std::string prefix = "/pm/" + run_id("throws") + "/";
    ubii::ModuleDescription description{"picky",
                                        "refuses odd numbers",
                                        {ubii::input<double>("x")},
                                        {ubii::output<double>("half")},
                                        ubii::TriggerOnInput{}};
    ubii::RunningModule picky =
        node.run(ubii::make_module(description,
                                   [](ubii::Pass &pass) {
                                       const double x = pass.input<double>("x");
                                       if (static_cast<int>(x) % 2 != 0)
                                           throw std::invalid_argument("odd: " + std::to_string(x));
                                       pass.set_output("half", x / 2);
                                   }),
                 ubii::Wiring().input("x", prefix + "x").output("half", prefix + "half"));
    std::vector<double> halves;
    auto subscription = node.subscribe<double>(
        prefix + "half", [&](double half, const ubii::RecordInfo &) { halves.push_back(half); });
    node.run_for(300ms);
    node.publish(prefix + "x", 3.0);
    ASSERT_TRUE(node.run_until([&] { return !errors.empty(); }, 5s));
    EXPECT_NE(errors[0].find("processing module \"picky\""), std::string::npos) << errors[0];
    EXPECT_NE(errors[0].find("odd: 3"), std::string::npos) << errors[0];
    node.publish(prefix + "x", 8.0);
    ASSERT_TRUE(node.run_until([&] { return !halves.empty(); }, 5s));
    EXPECT_EQ(halves[0], 4.0);
    EXPECT_EQ(picky.timing().errors, 1u);
    EXPECT_EQ(picky.status(), ubii::ProcessingStatus::processing);
}

TEST(ProcessingModuleOnMaster, AFrequencyModulePublishesAtItsRateThroughTheMaster)
{
    ubii::Node node(ubii_cpp_test::options_for("cpp-pm-frequency"));
    node.connect(10s);
    const std::string topic = "/pm/" + run_id("frequency") + "/tick";
    ubii::ModuleDescription description{
        "ticker", "counts", {}, {ubii::output<std::int32_t>("count")}, ubii::Frequency{50}};
    std::int32_t count = 0;
    ubii::RunningModule ticker =
        node.run(ubii::make_module(description,
                                   [&](ubii::Pass &pass) { pass.set_output("count", count++); }),
                 ubii::Wiring().output("count", topic));
    std::vector<std::int32_t> received;
    auto subscription = node.subscribe<std::int32_t>(
        topic, [&](std::int32_t value, const ubii::RecordInfo &) { received.push_back(value); });
    node.run_for(1500ms);
    const ubii::Timing timing = ticker.timing();
    // About 75 passes; the bounds only say the module ran at its rate, not how precisely (bench/).
    EXPECT_GT(timing.passes, 50u);
    EXPECT_LT(timing.passes, 100u);
    ASSERT_GT(received.size(), 30u);
    for (std::size_t i = 1; i < received.size(); ++i)
        EXPECT_EQ(received[i], received[i - 1] + 1) << "a pass's output went missing";
    ASSERT_TRUE(timing.interval_performance);
    EXPECT_NEAR(timing.intervals.mean.count(), 0.02, 0.005);
}

TEST(ProcessingModuleOnMaster, AMuxInputKeepsTheLatestRecordPerTopicWithItsIdentity)
{
    ubii::Node node(ubii_cpp_test::options_for("cpp-pm-mux"));
    std::vector<std::string> errors;
    node.on_error([&](ubii::Status, std::string_view detail) { errors.emplace_back(detail); });
    node.connect(10s);
    const std::string prefix = "/pm/" + run_id("mux") + "/";
    std::vector<std::vector<std::pair<std::string, double>>> seen;
    ubii::ModuleDescription description{
        "mux", "reads every hand", {ubii::input<double>("hands")}, {}, ubii::TriggerOnInput{}};
    ubii::RunningModule mux = node.run(
        ubii::make_module(description,
                          [&](ubii::Pass &pass) {
                              std::vector<std::pair<std::string, double>> hands;
                              for (const ubii::MuxedRecord &hand : pass.muxed("hands"))
                                  hands.emplace_back(hand.identity, hand.record->as<double>());
                              seen.push_back(std::move(hands));
                          }),
        ubii::Wiring().mux_input("hands", "^" + prefix + "hand/", "hand/([a-z]+)$"));
    node.run_for(300ms);
    node.publish(prefix + "hand/left", 1.0);
    node.publish(prefix + "hand/right", 2.0);
    node.publish(prefix + "hand/left", 3.0);
    node.publish(prefix + "hand/label", std::string("not a double: filtered"));
    ASSERT_TRUE(node.run_until(
        [&] { return !seen.empty() && seen.back().size() == 2 && seen.back()[0].second == 3.0; },
        5s));
    const std::vector<std::pair<std::string, double>> expected = {{"left", 3.0}, {"right", 2.0}};
    EXPECT_EQ(seen.back(), expected);
    EXPECT_EQ(mux.timing().type_mismatches, 0u);
    EXPECT_TRUE(errors.empty()) << errors.front();
}

TEST(ProcessingModuleOnMaster, WiringAnUnknownInputIsRefusedAndNothingRuns)
{
    ubii::Node node(ubii_cpp_test::options_for("cpp-pm-wiring"));
    node.connect(10s);
    EXPECT_THROW(node.run(sum_module(ubii::TriggerOnInput{}), ubii::Wiring().input("c", "/c")),
                 ubii::NotFound);
    EXPECT_TRUE(node.scheduler().ids().empty());
}

TEST(ProcessingModuleOnMaster, AnExternalLoopWaitsOnTheNodesFdsUntilTheNextPassIsDue)
{
    ubii::Node node(ubii_cpp_test::options_for("cpp-pm-external-loop"));
    node.connect(10s);
    EXPECT_FALSE(node.next_timeout() && *node.next_timeout() < 1ms)
        << "without modules the deadline is the core's own";
    int passes = 0;
    ubii::ModuleDescription description{"ticker", "counts", {}, {}, ubii::Frequency{20}};
    ubii::RunningModule ticker =
        node.run(ubii::make_module(description, [&](ubii::Pass &) { ++passes; }));
    node.poll(0ms); // the first pass is due at once
    ASSERT_EQ(passes, 1);
    const std::optional<std::chrono::nanoseconds> timeout = node.next_timeout();
    ASSERT_TRUE(timeout);
    EXPECT_GT(*timeout, 40ms);
    EXPECT_LE(*timeout, 50ms);

    // A frame loop of the application's own: poll(2) on the node's descriptors with the node's
    // deadline, then poll(0) on the node. Passes keep their rate without the node ever waiting.
    std::vector<ubii_pollfd> fds(16);
    const auto end = std::chrono::steady_clock::now() + 1s;
    while (std::chrono::steady_clock::now() < end) {
        const int count = node.pollfds(fds.data(), static_cast<int>(fds.size()));
        ASSERT_LE(count, static_cast<int>(fds.size()));
        std::vector<pollfd> waiting;
        for (int i = 0; i < count; ++i)
            waiting.push_back({fds[static_cast<std::size_t>(i)].fd,
                               static_cast<short>(fds[static_cast<std::size_t>(i)].events), 0});
        const auto wait = node.next_timeout().value_or(100ms);
        const auto wait_ms = std::chrono::ceil<std::chrono::milliseconds>(wait);
        ::poll(waiting.data(), waiting.size(), static_cast<int>(wait_ms.count()));
        node.poll(0ms);
    }
    EXPECT_GE(passes, 19);
    EXPECT_LE(passes, 23);
}

// The npm 0.4.0 master never assigns modules to nodes (docs/PROTOCOL.md §6), but a node that
// serves sessions must still work with it: its registration, with the modules offered, is
// accepted, and its start/stop subscriptions and master check raise nothing.
TEST(ServingSessions, TheNpmMasterTakesTheOfferedModulesAndAssignsNone)
{
    ubii::NodeOptions options = ubii_cpp_test::options_for("serving-on-npm");
    options.is_dedicated_processing_node = true;
    ubii::Node node(options);
    std::vector<std::string> errors;
    node.on_error([&](ubii::Status, std::string_view detail) { errors.emplace_back(detail); });
    ubii::ModuleRegistry modules;
    modules.add([] {
        return ubii::make_module({"noop", "does nothing", {ubii::input<double>("x")}, {}},
                                 [](ubii::Pass &) {});
    });
    node.serve_sessions(std::move(modules));
    node.connect(10s);
    node.run_for(500ms);
    EXPECT_TRUE(node.usable(ubii::Behaviour::processing_modules));
    EXPECT_TRUE(node.session_modules().empty());
    EXPECT_TRUE(errors.empty()) << errors.front();
    EXPECT_TRUE(node.stop_wait());
}

} // namespace

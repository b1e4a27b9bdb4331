// The scheduler's semantics on simulated time (ubii::ManualClock): every mode, the timing metric,
// latest-wins inputs, errors, and the worker executor (a real thread, the clock still simulated).
#include <atomic>
#include <condition_variable>
#include <mutex>
#include <random>
#include <thread>

#include <gtest/gtest.h>

#include "ubii/scheduler.hpp"
#include "ubii/standalone_module.hpp"

using namespace std::chrono_literals;
using ubii::Pass;
using ubii::Record;

namespace
{

struct Published {
    std::string module, output;
    ubii::Value value;
    std::thread::id thread;
};

class SchedulerTest : public ::testing::Test
{
  protected:
    SchedulerTest() : scheduler(clock)
    {
        scheduler.on_output(
            [this](const ubii::ProcessingModule &module, const ubii::PassOutput &output) {
                published.push_back(
                    {module.name(), output.name, output.value, std::this_thread::get_id()});
                return ubii::Status::ok;
            });
        scheduler.on_error([this](ubii::Status status, std::string_view detail) {
            errors.emplace_back(status, std::string(detail));
        });
    }
    std::shared_ptr<const Record> record(const std::string &topic, ubii::Value value)
    {
        return std::make_shared<const Record>(topic, std::move(value));
    }
    // A module of `mode` whose passes call `fn` (sum of a and b by default).
    std::string add(ubii::ProcessingMode mode, std::function<void(Pass &)> fn = {},
                    ubii::Executor executor = ubii::Executor::loop, unsigned halt_after = 0)
    {
        if (!fn)
            fn = [](Pass &pass) {
                pass.set_output("sum", pass.input<double>("a") + pass.input<double>("b"));
            };
        ubii::ModuleDescription description{"sum",
                                            "adds a and b",
                                            {ubii::input<double>("a"), ubii::input<double>("b")},
                                            {ubii::output<double>("sum")},
                                            mode,
                                            executor};
        description.halt_after_errors = halt_after;
        const std::string id = scheduler.add(ubii::make_module(description, std::move(fn)));
        scheduler.start(id);
        return id;
    }
    // Runs what is due at `when` (the clock moves there first).
    void run_at(ubii::Clock::time_point when)
    {
        clock.sleep_until(when);
        scheduler.run_due();
    }

    ubii::ManualClock clock;
    ubii::Scheduler scheduler;
    std::vector<Published> published;
    std::vector<std::pair<ubii::Status, std::string>> errors;
};

TEST_F(SchedulerTest, FrequencyKeepsAbsoluteDeadlinesWithoutDriftOver10000Passes)
{
    std::vector<ubii::Clock::time_point> starts;
    const auto t0 = clock.now();
    add(ubii::Frequency{60}, [&](Pass &) { starts.push_back(clock.now()); });
    // The loop wakes up to 300 us late every time: with relative delays that would add up to
    // 3 s over 10 000 passes; with absolute deadlines it never accumulates.
    std::mt19937 random(7);
    std::uniform_int_distribution<int> lateness_us(0, 300);
    while (starts.size() < 10000) {
        const auto due = scheduler.next_due();
        ASSERT_TRUE(due);
        run_at(*due + std::chrono::microseconds(lateness_us(random)));
    }
    for (std::size_t k : {std::size_t(1), std::size_t(5000), std::size_t(9999)}) {
        const auto deadline =
            t0 + std::chrono::nanoseconds(std::llround(static_cast<double>(k) * 1e9 / 60));
        EXPECT_GE(starts[k], deadline) << "pass " << k;
        EXPECT_LE(starts[k] - deadline, 300us) << "pass " << k;
    }
    const ubii::Timing timing = scheduler.timing(scheduler.ids().front());
    EXPECT_EQ(timing.passes, 10000u);
    EXPECT_EQ(timing.skipped_ticks, 0u);
    EXPECT_NEAR(timing.intervals.mean.count(), 1.0 / 60, 1e-4);
    ASSERT_TRUE(timing.interval_performance);
}

TEST_F(SchedulerTest, ALateFrequencyPassRunsOnceAndCountsTheTicksItMissed)
{
    const auto t0 = clock.now();
    std::vector<ubii::Clock::time_point> starts;
    add(ubii::Frequency{100}, [&](Pass &) {
        starts.push_back(clock.now());
        if (starts.size() == 1)
            clock.advance(35ms); // the first pass overruns three and a half periods
    });
    scheduler.run_due();
    ASSERT_EQ(starts.size(), 1u);
    // Deadlines 10, 20 and 30 ms have passed: one late pass now, not three.
    scheduler.run_due();
    scheduler.run_due();
    ASSERT_EQ(starts.size(), 2u);
    EXPECT_EQ(starts[1], t0 + 35ms);
    const std::string id = scheduler.ids().front();
    EXPECT_EQ(scheduler.timing(id).skipped_ticks, 2u);
    EXPECT_EQ(scheduler.next_due(), t0 + 40ms); // back on the original grid
    run_at(t0 + 40ms);
    EXPECT_EQ(starts.size(), 3u);
}

TEST_F(SchedulerTest, TriggerOnInputRunsWhenAnyInputUpdates)
{
    const std::string id = add(ubii::TriggerOnInput{}, [&](Pass &pass) {
        EXPECT_TRUE(pass.updated("a"));
        EXPECT_FALSE(pass.updated("b"));
        EXPECT_EQ(pass.record("b"), nullptr);
        pass.set_output("sum", pass.input<double>("a"));
    });
    EXPECT_FALSE(scheduler.next_due());
    scheduler.run_due();
    EXPECT_TRUE(published.empty());
    scheduler.feed(id, "a", record("/a", 2.0));
    EXPECT_EQ(scheduler.next_due(), clock.now());
    scheduler.run_due();
    ASSERT_EQ(published.size(), 1u);
    EXPECT_EQ(published[0].value.as<double>(), 2.0);
    EXPECT_FALSE(scheduler.next_due()); // consumed: no second pass without a new record
}

// Pass::log lines reach on_log after the pass, in order, on the polling thread, from passes that
// returned and from passes that threw; without a handler they go nowhere and nothing fails.
TEST_F(SchedulerTest, LinesAPassLogsReachTheLogHandlerInOrderEvenWhenThePassThrew)
{
    std::vector<std::pair<std::string, std::string>> logged;
    std::vector<std::thread::id> threads;
    scheduler.on_log([&](const ubii::ProcessingModule &module, std::string_view line) {
        logged.emplace_back(module.name(), std::string(line));
        threads.push_back(std::this_thread::get_id());
    });
    const std::string id = add(
        ubii::TriggerOnInput{},
        [](Pass &pass) {
            pass.log("first of pass " + std::to_string(pass.number()));
            pass.log("second");
            if (pass.input<double>("a") < 0)
                throw std::runtime_error("negative");
            pass.set_output("sum", pass.input<double>("a"));
        },
        ubii::Executor::worker);
    const auto wait_for_lines = [&](std::size_t count) {
        for (int i = 0; i < 2000 && logged.size() < count; ++i) {
            std::this_thread::sleep_for(1ms);
            scheduler.run_due();
        }
    };
    scheduler.feed(id, "a", record("/a", 1.0));
    scheduler.run_due();
    wait_for_lines(2);
    scheduler.feed(id, "a", record("/a", -1.0));
    scheduler.run_due();
    wait_for_lines(4);
    ASSERT_EQ(logged.size(), 4u);
    EXPECT_EQ(logged[0], std::make_pair(std::string("sum"), std::string("first of pass 1")));
    EXPECT_EQ(logged[1].second, "second");
    EXPECT_EQ(logged[2].second, "first of pass 2");
    for (const auto thread : threads)
        EXPECT_EQ(thread, std::this_thread::get_id());
    ASSERT_EQ(errors.size(), 1u); // the throw is reported as before
    scheduler.on_log({});
    scheduler.feed(id, "a", record("/a", 2.0));
    scheduler.run_due();
    for (int i = 0; i < 2000 && published.size() < 2; ++i) {
        std::this_thread::sleep_for(1ms);
        scheduler.run_due();
    }
    EXPECT_EQ(published.size(), 2u);
    EXPECT_EQ(logged.size(), 4u);
}

TEST_F(SchedulerTest, AllInputsNeedUpdateWaitsForEveryInput)
{
    const std::string id = add(ubii::TriggerOnInput{0ms, true});
    scheduler.feed(id, "a", record("/a", 1.0));
    scheduler.feed(id, "a", record("/a", 2.0));
    EXPECT_FALSE(scheduler.next_due());
    scheduler.run_due();
    EXPECT_TRUE(published.empty());
    scheduler.feed(id, "b", record("/b", 5.0));
    scheduler.run_due();
    ASSERT_EQ(published.size(), 1u);
    EXPECT_EQ(published[0].value.as<double>(), 7.0);
    // b again, a not: still waiting for a.
    scheduler.feed(id, "b", record("/b", 6.0));
    scheduler.run_due();
    EXPECT_EQ(published.size(), 1u);
}

TEST_F(SchedulerTest, ATriggerInsideMinDelayRunsExactlyAtItsEnd)
{
    std::vector<std::chrono::nanoseconds> deltas;
    const std::string id = add(ubii::TriggerOnInput{50ms, false}, [&](Pass &pass) {
        deltas.push_back(pass.delta_time());
        pass.set_output("sum", pass.input<double>("a"));
    });
    const auto t0 = clock.now();
    scheduler.feed(id, "a", record("/a", 1.0));
    scheduler.run_due();
    ASSERT_EQ(published.size(), 1u);

    run_at(t0 + 10ms);
    scheduler.feed(id, "a", record("/a", 2.0));
    EXPECT_EQ(scheduler.next_due(), t0 + 50ms);
    run_at(t0 + 49ms);
    EXPECT_EQ(published.size(), 1u) << "ran inside the minimum delay";
    run_at(t0 + 50ms);
    ASSERT_EQ(published.size(), 2u) << "the trigger was dropped";
    EXPECT_EQ(published[1].value.as<double>(), 2.0);
    EXPECT_EQ(deltas.back(), 50ms);
    EXPECT_DOUBLE_EQ(*scheduler.timing(id).interval_performance, 1.0);
}

TEST_F(SchedulerTest, TheLatestRecordWinsAndTheReplacedOnesAreCounted)
{
    const std::string id = add(ubii::TriggerOnInput{10ms, false},
                               [](Pass &pass) { pass.set_output("sum", pass.input<double>("a")); });
    scheduler.feed(id, "a", record("/a", 1.0));
    scheduler.run_due();
    scheduler.feed(id, "a", record("/a", 2.0));
    scheduler.feed(id, "a", record("/a", 3.0));
    scheduler.feed(id, "a", record("/a", 4.0));
    run_at(clock.now() + 10ms);
    ASSERT_EQ(published.size(), 2u);
    EXPECT_EQ(published[1].value.as<double>(), 4.0);
    EXPECT_EQ(scheduler.timing(id).inputs_dropped, 2u);
}

TEST_F(SchedulerTest, ARecordOfTheWrongTypeIsCountedReportedAndNotTaken)
{
    const std::string id = add(ubii::TriggerOnInput{});
    scheduler.feed(id, "a", record("/a", std::string("text")));
    EXPECT_FALSE(scheduler.next_due());
    EXPECT_EQ(scheduler.timing(id).type_mismatches, 1u);
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_EQ(errors[0].first, ubii::Status::wrong_type);
    EXPECT_NE(errors[0].second.find("input \"a\" takes double"), std::string::npos)
        << errors[0].second;
    EXPECT_THROW(scheduler.feed(id, "c", record("/c", 1.0)), ubii::NotFound);
}

TEST_F(SchedulerTest, LockstepRunsOnlyWhenSteppedAndReturnsItsOutputs)
{
    std::chrono::nanoseconds delta{};
    const std::string id = add(ubii::Lockstep{}, [&](Pass &pass) {
        delta = pass.delta_time();
        pass.set_output("sum", pass.input<double>("a") + pass.input<double>("b"));
    });
    EXPECT_FALSE(scheduler.next_due());
    scheduler.run_due();
    EXPECT_TRUE(published.empty());

    const std::vector<Record> outputs =
        scheduler.step(id, {Record("a", 1.5), Record("b", 2.0)}, 16ms);
    ASSERT_EQ(outputs.size(), 1u);
    EXPECT_EQ(outputs[0].topic(), "sum");
    EXPECT_EQ(outputs[0].as<double>(), 3.5);
    EXPECT_EQ(delta, 16ms);
    EXPECT_TRUE(published.empty()) << "a lockstep pass hands its outputs to the driver";

    // The message shape: the ids named, the records by input name.
    ubii::LockstepProcessingRequest request;
    request.add_processing_module_ids(id);
    request.set_delta_time_ms(20);
    *request.add_records() = ubii::message_from_record(Record("a", 10.0));
    *request.add_records() = ubii::message_from_record(Record("unrelated", 1.0));
    const ubii::LockstepProcessingReply reply = scheduler.step(request);
    ASSERT_EQ(reply.records_size(), 1);
    EXPECT_EQ(reply.records(0).topic(), "sum");
    EXPECT_EQ(reply.records(0).double_(), 12.0); // b kept its last record
    EXPECT_EQ(reply.processing_module_ids(0), id);
    EXPECT_EQ(delta, 20ms);
    EXPECT_EQ(scheduler.timing(id).passes, 2u);
}

TEST_F(SchedulerTest, SteppingAModuleOfAnotherModeIsRefused)
{
    const std::string id = add(ubii::Free{});
    EXPECT_THROW(scheduler.step(id, {}, 1ms), ubii::StateError);
}

TEST_F(SchedulerTest, AFreeModuleRunsOncePerTurnOfTheLoop)
{
    int passes = 0;
    add(ubii::Free{}, [&](Pass &) { ++passes; });
    EXPECT_EQ(scheduler.next_due(), clock.now());
    for (int turn = 0; turn < 5; ++turn)
        scheduler.run_due(); // the caller's I/O goes between these
    EXPECT_EQ(passes, 5);
}

TEST_F(SchedulerTest, OutputsOfZeroFalseAndEmptyArePublished)
{
    ubii::ModuleDescription description{"falsy",
                                        "",
                                        {},
                                        {ubii::output<double>("zero"), ubii::output<bool>("no"),
                                         ubii::output<std::string>("empty")},
                                        ubii::Free{}};
    const std::string id = scheduler.add(ubii::make_module(description, [](Pass &pass) {
        pass.set_output("zero", 0.0);
        pass.set_output("no", false);
        pass.set_output("empty", std::string());
    }));
    scheduler.start(id);
    scheduler.run_due();
    ASSERT_EQ(published.size(), 3u);
    EXPECT_EQ(published[0].value.as<double>(), 0.0);
    EXPECT_EQ(published[1].value.as<bool>(), false);
    EXPECT_EQ(published[2].value.as<std::string>(), "");
}

TEST_F(SchedulerTest, SettingAnUndeclaredOrMistypedOutputFailsThePass)
{
    int pass_number = 0;
    add(ubii::Free{}, [&](Pass &pass) {
        ++pass_number;
        if (pass_number == 1)
            pass.set_output("product", 1.0);
        else
            pass.set_output("sum", std::int32_t{1});
    });
    scheduler.run_due();
    scheduler.run_due();
    ASSERT_EQ(errors.size(), 2u);
    EXPECT_NE(errors[0].second.find("no output \"product\""), std::string::npos)
        << errors[0].second;
    EXPECT_NE(errors[1].second.find("takes double"), std::string::npos) << errors[1].second;
}

TEST_F(SchedulerTest, AnExceptionIsReportedWithTheModuleNameAndTheNextPassRuns)
{
    int passes = 0;
    const std::string id = add(ubii::Free{}, [&](Pass &pass) {
        ++passes;
        pass.set_output("sum", 1.0);
        if (passes == 1)
            throw std::runtime_error("first pass fails");
    });
    scheduler.run_due();
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_EQ(errors[0].first, ubii::Status::callback_threw);
    EXPECT_NE(errors[0].second.find("processing module \"sum\""), std::string::npos);
    EXPECT_NE(errors[0].second.find("first pass fails"), std::string::npos);
    EXPECT_TRUE(published.empty()) << "a failed pass's outputs were published";
    scheduler.run_due();
    EXPECT_EQ(passes, 2);
    EXPECT_EQ(published.size(), 1u);
    EXPECT_EQ(scheduler.timing(id).errors, 1u);
    EXPECT_EQ(scheduler.module(id).status(), ubii::ProcessingStatus::processing);
}

TEST_F(SchedulerTest, AModuleHaltsAfterTheConfiguredErrorsInARow)
{
    int passes = 0;
    const std::string id = add(
        ubii::Free{},
        [&](Pass &) {
            if (++passes != 2)
                throw std::runtime_error("fails");
        },
        ubii::Executor::loop, 3);
    for (int turn = 0; turn < 10; ++turn)
        scheduler.run_due();
    // 1 fails, 2 succeeds (resets the run), 3, 4, 5 fail: halted after pass 5.
    EXPECT_EQ(passes, 5);
    EXPECT_EQ(scheduler.module(id).status(), ubii::ProcessingStatus::halted);
    EXPECT_NE(errors.back().second.find("halted after 3 passes in a row threw"), std::string::npos);
}

TEST_F(SchedulerTest, OutputsThatCannotBePublishedAreCountedAndReported)
{
    scheduler.on_output([](const ubii::ProcessingModule &, const ubii::PassOutput &) {
        return ubii::Status::would_block;
    });
    const std::string id = add(ubii::Free{}, [](Pass &pass) { pass.set_output("sum", 1.0); });
    scheduler.run_due();
    EXPECT_EQ(scheduler.timing(id).outputs_failed, 1u);
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_EQ(errors[0].first, ubii::Status::would_block);
    EXPECT_NE(errors[0].second.find("output \"sum\" not published"), std::string::npos);
}

// A pass that blocks until the test lets it go.
class Gate
{
  public:
    void wait()
    {
        std::unique_lock<std::mutex> lock(mutex_);
        entered_ = true;
        changed_.notify_all();
        changed_.wait(lock, [this] { return open_; });
        open_ = false;
    }
    void open()
    {
        std::lock_guard<std::mutex> lock(mutex_);
        open_ = true;
        changed_.notify_all();
    }
    void await_entered()
    {
        std::unique_lock<std::mutex> lock(mutex_);
        changed_.wait(lock, [this] { return entered_; });
        entered_ = false;
    }

  private:
    std::mutex mutex_;
    std::condition_variable changed_;
    bool open_ = false;
    bool entered_ = false;
};

TEST_F(SchedulerTest, AWorkerPassRunsOffThePollThreadAndItsOutputsComeBackThroughRunDue)
{
    Gate gate;
    std::atomic<int> wakes{0};
    std::thread::id pass_thread;
    scheduler.set_waker([&] { ++wakes; });
    const std::string id = add(
        ubii::TriggerOnInput{},
        [&](Pass &pass) {
            pass_thread = std::this_thread::get_id();
            gate.wait();
            pass.set_output("sum", pass.input<double>("a"));
        },
        ubii::Executor::worker);
    scheduler.feed(id, "a", record("/a", 1.0));
    scheduler.run_due(); // hands the pass over and returns
    gate.await_entered();
    EXPECT_FALSE(scheduler.next_due()) << "a busy worker with a waker needs no polling";
    // Latest wins while the worker is busy: 2 and 3 are replaced by 4.
    scheduler.feed(id, "a", record("/a", 2.0));
    scheduler.feed(id, "a", record("/a", 3.0));
    scheduler.feed(id, "a", record("/a", 4.0));
    scheduler.run_due();
    EXPECT_TRUE(published.empty());

    gate.open();
    while (wakes.load() == 0)
        std::this_thread::yield();
    EXPECT_EQ(scheduler.next_due(), clock.now());
    scheduler.run_due(); // collects pass 1 and hands pass 2 (value 4) over
    ASSERT_EQ(published.size(), 1u);
    EXPECT_EQ(published[0].value.as<double>(), 1.0);
    EXPECT_EQ(published[0].thread, std::this_thread::get_id());
    EXPECT_NE(pass_thread, std::this_thread::get_id());

    gate.await_entered();
    gate.open();
    while (wakes.load() < 2)
        std::this_thread::yield();
    scheduler.run_due();
    ASSERT_EQ(published.size(), 2u);
    EXPECT_EQ(published[1].value.as<double>(), 4.0);
    EXPECT_EQ(scheduler.timing(id).inputs_dropped, 2u);
}

TEST_F(SchedulerTest, WithoutAWakerABusyWorkerIsLookedAtEveryMillisecond)
{
    Gate gate;
    const std::string id = add(
        ubii::Free{}, [&](Pass &) { gate.wait(); }, ubii::Executor::worker);
    scheduler.run_due();
    gate.await_entered();
    EXPECT_EQ(scheduler.next_due(), clock.now() + 1ms);
    gate.open();
    scheduler.remove(id);
}

TEST_F(SchedulerTest, HaltWaitsForTheWorkerPassAndPublishesItsOutputs)
{
    Gate gate;
    const std::string id = add(
        ubii::Free{},
        [&](Pass &pass) {
            gate.wait();
            pass.set_output("sum", 9.0);
        },
        ubii::Executor::worker);
    scheduler.run_due();
    gate.await_entered();
    std::thread opener([&] {
        std::this_thread::sleep_for(20ms);
        gate.open();
    });
    scheduler.halt(id);
    opener.join();
    EXPECT_EQ(scheduler.module(id).status(), ubii::ProcessingStatus::halted);
    ASSERT_EQ(published.size(), 1u);
    EXPECT_EQ(published[0].value.as<double>(), 9.0);
}

class Lifecycle : public ubii::ProcessingModule
{
  public:
    Lifecycle(std::vector<std::string> &log, bool fail_creation)
        : ProcessingModule({"lifecycle", "records its hooks", {}, {}, ubii::Free{}}), log_(log),
          fail_creation_(fail_creation)
    {
    }
    ~Lifecycle() override
    {
        log_.push_back("~");
    }

  protected:
    void on_created() override
    {
        log_.push_back("created");
        if (fail_creation_)
            throw std::runtime_error("no camera");
    }
    void on_processing(Pass &) override
    {
        log_.push_back("pass");
    }
    void on_halted() override
    {
        log_.push_back("halted");
    }
    void on_destroyed() override
    {
        log_.push_back("destroyed");
    }

  private:
    std::vector<std::string> &log_;
    bool fail_creation_;
};

TEST_F(SchedulerTest, TheLifecycleRunsItsHooksInOrder)
{
    std::vector<std::string> log;
    std::vector<std::string> states;
    auto module = std::make_unique<Lifecycle>(log, false);
    module->lifecycle().on_every_transition([&](ubii::Transition<ubii::ProcessingStatus> &t) {
        states.emplace_back(ubii::to_string(t.to()));
    });
    const std::string id = scheduler.add(std::move(module));
    EXPECT_EQ(id, "lifecycle#1");
    EXPECT_EQ(scheduler.module(id).status(), ubii::ProcessingStatus::created);
    scheduler.run_due();
    scheduler.start(id);
    scheduler.run_due();
    scheduler.halt(id);
    scheduler.run_due();
    scheduler.remove(id);
    EXPECT_EQ(log, (std::vector<std::string>{"created", "pass", "halted", "destroyed", "~"}));
    EXPECT_EQ(states, (std::vector<std::string>{"created", "processing", "halted", "destroyed"}));
    EXPECT_FALSE(scheduler.contains(id));
}

TEST_F(SchedulerTest, AModuleWhoseCreationThrowsIsNotAdded)
{
    std::vector<std::string> log;
    EXPECT_THROW(scheduler.add(std::make_unique<Lifecycle>(log, true)), std::runtime_error);
    EXPECT_TRUE(scheduler.ids().empty());
    EXPECT_EQ(log, (std::vector<std::string>{"created", "~"}));
}

TEST(ProcessingModule, SpecDescribesTheModuleAsUbiInteractDoes)
{
    ubii::ModuleDescription description{"sum",
                                        "adds a and b",
                                        {ubii::input<double>("a"), ubii::input<ubii::Vector3>("v")},
                                        {ubii::output<double>("sum")},
                                        ubii::TriggerOnInput{25ms, true}};
    description.tags = {"math"};
    description.authors = {"libubii"};
    const auto module = ubii::make_module(description, [](Pass &) {});
    const ubii::ProcessingModuleSpec spec = module->spec();
    EXPECT_EQ(spec.name(), "sum");
    EXPECT_EQ(spec.description(), "adds a and b");
    EXPECT_EQ(spec.language(), ubii::ProcessingModuleSpec::CPP);
    EXPECT_EQ(spec.status(), ubii::ProcessingModuleSpec::INITIALIZED);
    ASSERT_EQ(spec.inputs_size(), 2);
    EXPECT_EQ(spec.inputs(1).internal_name(), "v");
    EXPECT_EQ(spec.inputs(1).message_format(), "ubii.dataStructure.Vector3");
    EXPECT_EQ(spec.outputs(0).message_format(), "double");
    EXPECT_EQ(spec.processing_mode().trigger_on_input().min_delay_ms(), 25);
    EXPECT_TRUE(spec.processing_mode().trigger_on_input().all_inputs_need_update());
    EXPECT_EQ(spec.tags(0), "math");
    EXPECT_EQ(spec.authors(0), "libubii");
}

TEST(ProcessingModule, ADescriptionThatCannotWorkIsRefused)
{
    const auto nothing = [](Pass &) {};
    EXPECT_THROW(ubii::make_module({"", "", {}, {}, ubii::Free{}}, nothing), ubii::InvalidArgument);
    EXPECT_THROW(
        ubii::make_module(
            {"m", "", {ubii::input<double>("a"), ubii::input<bool>("a")}, {}, ubii::Free{}},
            nothing),
        ubii::InvalidArgument);
    EXPECT_THROW(ubii::make_module(
                     {"m", "", {{"a", "ubii.dataStructure.NoSuch"}}, {}, ubii::Free{}}, nothing),
                 ubii::InvalidArgument);
    EXPECT_THROW(ubii::make_module({"m", "", {}, {}, ubii::Frequency{0}}, nothing),
                 ubii::InvalidArgument);
    EXPECT_THROW(ubii::make_module({"m", "", {}, {}, ubii::TriggerOnInput{-1ms}}, nothing),
                 ubii::InvalidArgument);
}

TEST(TimingMetric, PerformanceIsOneWithinThePeriodAndFallsWithTheRelativeError)
{
    EXPECT_DOUBLE_EQ(ubii::performance(ubii::Seconds(0.004), ubii::Seconds(0.005)), 1.0);
    EXPECT_DOUBLE_EQ(ubii::performance(ubii::Seconds(0.006), ubii::Seconds(0.005)), 0.8);
    EXPECT_DOUBLE_EQ(ubii::performance(ubii::Seconds(0.015), ubii::Seconds(0.005)), -1.0);
}

TEST(TimingMetric, TheWindowKeepsTheLast30Durations)
{
    ubii::DurationWindow window;
    for (int i = 1; i <= 40; ++i)
        window.add(std::chrono::milliseconds(i));
    const ubii::DurationStats stats = window.stats();
    EXPECT_EQ(stats.count, 30u);
    EXPECT_DOUBLE_EQ(stats.min.count(), 0.011);
    EXPECT_DOUBLE_EQ(stats.max.count(), 0.040);
    EXPECT_NEAR(stats.mean.count(), 0.0255, 1e-12);
    EXPECT_NEAR(stats.stddev.count(), 0.0086554, 1e-6);
}

} // namespace

namespace
{

// A module run without a node: its worker passes end on their thread and run_until hands their
// outputs on in this one; a wait for something that never comes ends at its timeout.
TEST(StandaloneModuleTest, RunsWorkerPassesAndWaitsAtMostItsTimeout)
{
    ubii::ModuleDescription description{"twice",
                                        "doubles a",
                                        {ubii::input<double>("a")},
                                        {ubii::output<double>("twice")},
                                        ubii::TriggerOnInput{},
                                        ubii::Executor::worker};
    ubii::StandaloneModule module(ubii::make_module(description, [](Pass &pass) {
        std::this_thread::sleep_for(20ms);
        pass.set_output("twice", 2 * pass.input<double>("a"));
    }));
    std::vector<double> outputs;
    std::vector<std::thread::id> threads;
    module.scheduler().on_output([&](const ubii::ProcessingModule &, const ubii::PassOutput &out) {
        outputs.push_back(out.value.as<double>());
        threads.push_back(std::this_thread::get_id());
        return ubii::Status::ok;
    });
    module.feed("a", std::make_shared<const Record>("/a", 21.0));
    ASSERT_TRUE(module.run_until([&] { return !outputs.empty(); }, 5s));
    EXPECT_EQ(outputs, std::vector<double>{42.0});
    EXPECT_EQ(threads.front(), std::this_thread::get_id());
    EXPECT_EQ(module.timing().passes, 1u);

    const auto began = std::chrono::steady_clock::now();
    EXPECT_FALSE(module.run_until([&] { return outputs.size() > 1; }, 100ms));
    const auto waited = std::chrono::steady_clock::now() - began;
    EXPECT_GE(waited, 100ms);
    EXPECT_LT(waited, 2s);
}

} // namespace

#ifndef UBII_SCHEDULER_HPP
#define UBII_SCHEDULER_HPP

// ubii::Scheduler: runs processing modules in their modes, in the thread that calls run_due()
// (ubii::Node calls it from poll(); a game engine or test may own one directly).
//
//     ubii::Scheduler scheduler;                       // steady clock; ManualClock in tests
//     scheduler.on_output([&](const ubii::ProcessingModule &, const ubii::PassOutput &output) {
//         ...; return ubii::Status::ok; });
//     const std::string id = scheduler.add(std::make_unique<Sum>());
//     scheduler.start(id);
//     for (;;) { wait_until(scheduler.next_due()); scheduler.run_due(); }
//
// Frequency mode keeps absolute deadlines (start + k/hertz), so a late pass never shifts the ones
// after it. Passes on the worker executor run on the module's own thread; their outputs are handed
// to the output sink from run_due(), never from the worker. Not thread-safe: one thread uses it.

#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "ubii/error.hpp"
#include "ubii/messages.hpp"
#include "ubii/processing_module.hpp"
#include "ubii/record.hpp"
#include "ubii/timing.hpp"
#include "ubii/value.hpp"

namespace ubii
{

class Scheduler
{
  public:
    // Publishes one output a pass set (each demultiplexed element on its own): Status::ok, or why
    // not (counted as Timing::outputs_failed and reported).
    using OutputSink =
        std::function<Status(const ProcessingModule &module, const PassOutput &output)>;
    // Errors of modules: passes that threw (Status::callback_threw), records of the wrong type
    // (Status::wrong_type), outputs not published; the detail names the module.
    using ErrorHandler = std::function<void(Status status, std::string_view detail)>;
    // The lines a pass logged (Pass::log), in order, after the pass; none without a handler.
    using LogHandler = std::function<void(const ProcessingModule &module, std::string_view line)>;

    explicit Scheduler(Clock &clock = steady_clock());
    ~Scheduler(); // destroys every module
    Scheduler(const Scheduler &) = delete;
    Scheduler &operator=(const Scheduler &) = delete;

    Clock &clock() const noexcept;
    void on_output(OutputSink sink);
    void on_error(ErrorHandler handler);
    void on_log(LogHandler handler);
    // Called from a worker thread when a pass ended, so that a thread waiting for I/O wakes to
    // hand its outputs on (ubii::Node sets its port's wake-up). Without one, next_due() is at most
    // a millisecond away while a worker pass runs.
    void set_waker(std::function<void()> wake);

    // Takes `module` and runs its on_created (CREATED); what that throws propagates and the module
    // is dropped. Returns its id (the module's own, or "<name>#<n>"); ubii::InvalidArgument if a
    // module with that id is here already.
    std::string add(std::unique_ptr<ProcessingModule> module);
    // CREATED or HALTED -> PROCESSING: frequency deadlines count from now.
    void start(std::string_view id);
    // PROCESSING -> HALTED, after a worker pass in flight ended (its outputs are handed on).
    void halt(std::string_view id);
    // Halts the module if it runs, runs on_destroyed (DESTROYED) and drops it.
    void remove(std::string_view id);
    bool contains(std::string_view id) const noexcept;
    bool empty() const noexcept;
    std::vector<std::string> ids() const;
    // ubii::NotFound for an unknown id.
    ProcessingModule &module(std::string_view id);
    Timing timing(std::string_view id) const;

    // A record for `input` of module `id` (latest wins: a record no pass read yet is replaced
    // and counted as dropped). A record of another member than the input's message format is
    // counted and reported, not taken. ubii::NotFound for an unknown module or input.
    void feed(std::string_view id, std::string_view input, std::shared_ptr<const Record> record);
    // A record for a mux input, kept as the latest of its topic with `identity`.
    void feed_muxed(std::string_view id, std::string_view input, std::string identity,
                    std::shared_ptr<const Record> record);

    // When run_due() has work next: now or in the past if it has now; none while no module
    // waits for anything but a record or a lockstep driver.
    std::optional<Clock::time_point> next_due() const;
    // Runs every pass due (each module at most once per call, so that the caller's I/O runs
    // between the passes of a free or late module) and hands on what worker passes finished.
    void run_due();

    // Lockstep: one pass of module `id` (a Lockstep module that is PROCESSING) on `inputs`
    // (each record's topic names an input), with `delta` as its delta time, run in this thread
    // whatever its executor. Returns its outputs as records whose topic names the output. What
    // the pass throws is counted and propagates.
    std::vector<Record> step(std::string_view id, const std::vector<Record> &inputs,
                             std::chrono::nanoseconds delta);
    // The same in the shape of Ubi-Interact's lockstep messages: every module the request names
    // (every lockstep module if it names none) gets the records its inputs name; the reply
    // carries each module's outputs in the order of its ids.
    LockstepProcessingReply step(const LockstepProcessingRequest &request);

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// Converts between ubii::Record and the schema's TopicDataRecord (for lockstep messages).
Record record_from_message(const TopicDataRecord &message);
TopicDataRecord message_from_record(const Record &record);

} // namespace ubii

#endif

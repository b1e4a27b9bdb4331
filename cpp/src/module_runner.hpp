#ifndef UBII_CPP_MODULE_RUNNER_HPP
#define UBII_CPP_MODULE_RUNNER_HPP

// One processing module under a Scheduler: its input slots, when its next pass is due, its
// timing, and (for the worker executor) its thread. Everything but the worker's pass runs on the
// scheduler's thread.

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "ubii/processing_module.hpp"
#include "ubii/scheduler.hpp"
#include "ubii/timing.hpp"

namespace ubii::detail
{

class ModuleRunner
{
  public:
    struct Context {
        Clock &clock;
        Scheduler::OutputSink &output;
        Scheduler::ErrorHandler &error;
        Scheduler::LogHandler &log;
        std::function<void()> &wake;
    };

    ModuleRunner(std::unique_ptr<ProcessingModule> module, std::string id, Context context);
    ~ModuleRunner();
    ModuleRunner(const ModuleRunner &) = delete;
    ModuleRunner &operator=(const ModuleRunner &) = delete;

    ProcessingModule &module() noexcept
    {
        return *module_;
    }
    const std::string &id() const noexcept
    {
        return module_->id_;
    }

    void create();
    void start();
    void halt();
    void destroy() noexcept;

    void feed(std::string_view input, std::shared_ptr<const Record> record);
    void feed_muxed(std::string_view input, std::string identity,
                    std::shared_ptr<const Record> record);

    // When the next pass is due, `now` at the latest (or a finished worker pass is to be
    // collected); none if the module waits for records, a driver, or a worker pass still running.
    std::optional<Clock::time_point> next_due_at(Clock::time_point now) const;
    bool worker_busy() const noexcept
    {
        return in_flight_;
    }
    void run_due();
    std::vector<PassOutput> step(const std::vector<Record> &inputs, std::chrono::nanoseconds delta);
    Timing timing() const;

  private:
    struct MuxEntry {
        std::string topic;
        MuxedRecord record;
        bool fresh = false;
    };
    struct Slot {
        const ModuleIO *io;
        std::shared_ptr<const Record> latest;
        bool fresh = false;
        std::vector<MuxEntry> muxed;
    };
    struct Finished {
        std::vector<PassOutput> outputs;
        std::vector<std::string> log;
        std::exception_ptr error;
        Clock::duration execution{};
    };
    struct Worker;

    void hand_on_log(const std::vector<std::string> &lines) noexcept;
    Slot &slot(std::string_view input);
    bool accepts(const Slot &slot, const Record &record);
    bool triggered() const noexcept;
    // Frequency mode: when tick number `tick` is due.
    Clock::time_point deadline(std::uint64_t tick) const noexcept;
    Pass begin_pass(Clock::time_point now, std::optional<std::chrono::nanoseconds> delta);
    Finished execute(Pass &pass) noexcept;
    void finish(Finished finished);
    void collect();
    void report(Status status, const std::string &detail) noexcept;
    std::string who() const;

    std::unique_ptr<ProcessingModule> module_;
    Context context_;
    std::vector<Slot> slots_;
    std::unique_ptr<Worker> worker_;
    bool in_flight_ = false;

    // Frequency: deadline k is start_ + round(k * period_); next_tick_ is the next k to run.
    Clock::time_point start_{};
    double period_ns_ = 0;
    std::uint64_t next_tick_ = 0;
    std::optional<Clock::time_point> last_pass_start_;

    DurationWindow intervals_;
    DurationWindow executions_;
    std::uint64_t passes_ = 0;
    std::uint64_t skipped_ticks_ = 0;
    std::uint64_t inputs_dropped_ = 0;
    std::uint64_t type_mismatches_ = 0;
    std::uint64_t errors_ = 0;
    std::uint64_t outputs_failed_ = 0;
    unsigned errors_in_a_row_ = 0;
};

} // namespace ubii::detail

#endif

#ifndef UBII_TIMING_HPP
#define UBII_TIMING_HPP

// Clocks the scheduler runs on, and the timing metric of a processing module: the thesis's
// measure of how well a node keeps time (eq. 3.1), over the last 30 passes like the Python node,
// with the counters that say what was lost.

#include <array>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <optional>

namespace ubii
{

// A monotonic clock. now() may be called from worker threads.
class Clock
{
  public:
    using duration = std::chrono::nanoseconds;
    using time_point = std::chrono::time_point<std::chrono::steady_clock, duration>;

    virtual ~Clock() = default;
    virtual time_point now() const noexcept = 0;
    // Blocks until `deadline` (a simulated clock moves there instead).
    virtual void sleep_until(time_point deadline) = 0;
};

// std::chrono::steady_clock: CLOCK_MONOTONIC on Linux, the clock the Linux port's timeouts run on.
class SteadyClock final : public Clock
{
  public:
    time_point now() const noexcept override;
    void sleep_until(time_point deadline) override;
};
// The process's one SteadyClock.
Clock &steady_clock() noexcept;

// Simulated time for tests: it moves only when told (or slept on).
class ManualClock final : public Clock
{
  public:
    explicit ManualClock(time_point start = time_point(std::chrono::seconds(1000)))
        : now_(start.time_since_epoch().count())
    {
    }
    time_point now() const noexcept override
    {
        return time_point(duration(now_.load()));
    }
    void sleep_until(time_point deadline) override
    {
        if (deadline > now())
            now_.store(deadline.time_since_epoch().count());
    }
    void advance(duration by) noexcept
    {
        now_.fetch_add(by.count());
    }

  private:
    std::atomic<duration::rep> now_;
};

using Seconds = std::chrono::duration<double>;

// Summary of a window of durations.
struct DurationStats {
    std::size_t count = 0;
    Seconds mean{0};
    Seconds stddev{0}; // population standard deviation
    Seconds min{0};
    Seconds max{0};
};

// The last `capacity` durations (30: the thesis's DELTA_TIME_CACHE_SIZE).
class DurationWindow
{
  public:
    static constexpr std::size_t capacity = 30;
    void add(Clock::duration value) noexcept;
    DurationStats stats() const noexcept;
    std::size_t size() const noexcept
    {
        return size_;
    }

  private:
    std::array<Clock::duration, capacity> values_{};
    std::size_t next_ = 0;
    std::size_t size_ = 0;
};

// The thesis's PM_perf (eq. 3.1) for a window's mean against the period the mode asks for:
// 1 while the mean stays below it, then 1 - (mean - period) / period (negative past twice it).
double performance(Seconds mean, Seconds period) noexcept;

struct Timing {
    // Between the starts of consecutive passes, and how long on_processing took.
    DurationStats intervals;
    DurationStats execution;
    // PM_perf of each against the mode's period (frequency: 1/hertz; trigger on input:
    // min_delay); none for a mode without one.
    std::optional<double> interval_performance;
    std::optional<double> execution_performance;
    std::uint64_t passes = 0;
    // Frequency mode: deadlines that passed while a late pass ran (run once, never queued).
    std::uint64_t skipped_ticks = 0;
    // Input records replaced by a newer one before any pass read them (latest wins).
    std::uint64_t inputs_dropped = 0;
    // Input records of another member than the input's message format (not taken).
    std::uint64_t type_mismatches = 0;
    // Passes whose on_processing threw, and outputs the node could not publish.
    std::uint64_t errors = 0;
    std::uint64_t outputs_failed = 0;
};

} // namespace ubii

#endif

#include "ubii/timing.hpp"

#include <algorithm>
#include <cmath>
#include <thread>

namespace ubii
{

Clock::time_point SteadyClock::now() const noexcept
{
    return std::chrono::time_point_cast<duration>(std::chrono::steady_clock::now());
}

void SteadyClock::sleep_until(time_point deadline)
{
    std::this_thread::sleep_until(deadline);
}

Clock &steady_clock() noexcept
{
    static SteadyClock clock;
    return clock;
}

void DurationWindow::add(Clock::duration value) noexcept
{
    values_[next_] = value;
    next_ = (next_ + 1) % capacity;
    size_ = std::min(size_ + 1, capacity);
}

DurationStats DurationWindow::stats() const noexcept
{
    DurationStats stats;
    stats.count = size_;
    if (size_ == 0)
        return stats;
    double sum = 0;
    double low = std::chrono::duration_cast<Seconds>(values_[0]).count();
    double high = low;
    for (std::size_t i = 0; i < size_; ++i) {
        const double value = std::chrono::duration_cast<Seconds>(values_[i]).count();
        sum += value;
        low = std::min(low, value);
        high = std::max(high, value);
    }
    const double mean = sum / static_cast<double>(size_);
    double squares = 0;
    for (std::size_t i = 0; i < size_; ++i) {
        const double deviation = std::chrono::duration_cast<Seconds>(values_[i]).count() - mean;
        squares += deviation * deviation;
    }
    stats.mean = Seconds(mean);
    stats.stddev = Seconds(std::sqrt(squares / static_cast<double>(size_)));
    stats.min = Seconds(low);
    stats.max = Seconds(high);
    return stats;
}

double performance(Seconds mean, Seconds period) noexcept
{
    if (period.count() <= 0 || mean <= period)
        return 1.0;
    return 1.0 - (mean - period) / period;
}

} // namespace ubii

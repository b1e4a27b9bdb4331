#include "frame_timing.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>

namespace ubii::bench
{

FrameStats summarise(std::vector<double> times_ms)
{
    FrameStats stats;
    if (times_ms.empty())
        return stats;
    stats.count = static_cast<int>(times_ms.size());
    const double n = static_cast<double>(times_ms.size());
    stats.mean_ms = std::accumulate(times_ms.begin(), times_ms.end(), 0.0) / n;
    double squares = 0.0;
    for (const double t : times_ms)
        squares += (t - stats.mean_ms) * (t - stats.mean_ms);
    stats.relative_std = times_ms.size() > 1 ? std::sqrt(squares / (n - 1.0)) / stats.mean_ms : 0.0;
    std::sort(times_ms.begin(), times_ms.end());
    const std::size_t middle = times_ms.size() / 2;
    stats.median_ms = times_ms.size() % 2 == 1 ? times_ms[middle]
                                               : (times_ms[middle - 1] + times_ms[middle]) / 2.0;
    return stats;
}

namespace
{

double time_one_ms(const std::function<void()> &frame)
{
    const auto start = std::chrono::steady_clock::now();
    frame();
    const std::chrono::duration<double, std::milli> took = std::chrono::steady_clock::now() - start;
    return took.count();
}

} // namespace

std::pair<FrameStats, FrameStats> time_frames_interleaved(int warm_up, int count,
                                                          const std::function<void()> &first,
                                                          const std::function<void()> &second)
{
    for (int i = 0; i < warm_up; ++i) {
        first();
        second();
    }
    std::vector<double> first_ms, second_ms;
    for (int i = 0; i < count; ++i) {
        first_ms.push_back(time_one_ms(first));
        second_ms.push_back(time_one_ms(second));
    }
    return {summarise(std::move(first_ms)), summarise(std::move(second_ms))};
}

FrameStats time_frames(int warm_up, int count, const std::function<void()> &frame)
{
    for (int i = 0; i < warm_up; ++i)
        frame();
    std::vector<double> times_ms;
    times_ms.reserve(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) {
        const auto start = std::chrono::steady_clock::now();
        frame();
        const std::chrono::duration<double, std::milli> took =
            std::chrono::steady_clock::now() - start;
        times_ms.push_back(took.count());
    }
    return summarise(std::move(times_ms));
}

} // namespace ubii::bench

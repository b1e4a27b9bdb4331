#ifndef UBII_BENCH_OCR_FRAME_TIMING_HPP
#define UBII_BENCH_OCR_FRAME_TIMING_HPP

#include <functional>
#include <utility>
#include <vector>

namespace ubii::bench
{

// Per-frame times in the thesis's table format.
struct FrameStats {
    int count = 0;
    double mean_ms = 0.0;
    double relative_std = 0.0; // standard deviation / mean
    double median_ms = 0.0;
};

FrameStats summarise(std::vector<double> times_ms);

// Runs `frame` `warm_up` times unmeasured (the first Recognize after Init is ~2x slower), then
// `count` times measured with a steady clock.
FrameStats time_frames(int warm_up, int count, const std::function<void()> &frame);

// Times `first` and `second` alternately, frame by frame, so that neither profits from running
// later in the process (warmer caches and allocator, CPU clock changes): for ratios near 1.
std::pair<FrameStats, FrameStats> time_frames_interleaved(int warm_up, int count,
                                                          const std::function<void()> &first,
                                                          const std::function<void()> &second);

} // namespace ubii::bench

#endif

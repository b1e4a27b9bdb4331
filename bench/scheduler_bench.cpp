// scheduler_bench: how well ubii::Node keeps a processing module's time, beside the thesis's
// Python node (Table 3.1), and what a pass costs. Prints figures; asserts nothing.
//
//   scheduler_bench SERVICE_URL TOPIC_URL [SECONDS_PER_RATE [LOAD_MSG_PER_S]]
//
// For 10, 60, 120, 200 and 1000 Hz: an empty frequency module on a connected node for the given
// seconds, every pass start recorded; the frequencies implied by the intervals are summarised as
// the thesis does (mean, std, relstd, min, median), with the p99 of |interval - period|. Each
// rate also runs as "bare": on a Scheduler alone that sleeps to each deadline, the machine's own
// timing floor, beside which the node's rows show what its I/O costs. Then the same at 200 and
// 1000 Hz while a second node (own thread) publishes LOAD_MSG_PER_S records that
// the measured node receives. Last, free mode: empty passes per second and CPU time per pass, on
// the node and on a bare Scheduler.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

#include <sys/resource.h>

#include "ubii/ubii.hpp"

using namespace std::chrono_literals;

namespace
{

struct Row {
    double hertz;
    std::size_t count;
    double mean, std, min, median, p99_error_us;
    double interval_std_us; // of the intervals themselves: not inflated by catch-up passes
    std::uint64_t skipped;
    long received;
};

double cpu_seconds()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
           static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) / 1e6;
}

ubii::NodeOptions options(const std::string &service, const std::string &topic,
                          const std::string &name)
{
    ubii::NodeOptions result;
    result.service_url = service;
    result.topic_url = topic;
    result.name = name;
    return result;
}

// Runs `hertz` for `duration` on `node`, or without one on a bare Scheduler that sleeps to each
// deadline (the machine's own timing floor, for comparison).
Row measure(ubii::Node *node, double hertz, std::chrono::seconds duration, long *received)
{
    std::vector<std::chrono::steady_clock::time_point> starts;
    starts.reserve(static_cast<std::size_t>(hertz * static_cast<double>(duration.count()) * 1.2) +
                   16);
    ubii::ModuleDescription description{"tick", "empty", {}, {}, ubii::Frequency{hertz}};
    auto module = ubii::make_module(
        description, [&](ubii::Pass &) { starts.push_back(std::chrono::steady_clock::now()); });
    const long received_before = received != nullptr ? *received : 0;
    const auto end = std::chrono::steady_clock::now() + duration;
    ubii::Timing timing;
    if (node != nullptr) {
        ubii::RunningModule tick = node->run(std::move(module));
        while (std::chrono::steady_clock::now() < end)
            node->poll(100ms);
        timing = tick.timing();
    } else {
        ubii::Scheduler scheduler;
        const std::string id = scheduler.add(std::move(module));
        scheduler.start(id);
        while (std::chrono::steady_clock::now() < end) {
            ubii::steady_clock().sleep_until(*scheduler.next_due());
            scheduler.run_due();
        }
        timing = scheduler.timing(id);
    }

    std::vector<double> frequencies, errors_us;
    const double period = 1.0 / hertz;
    for (std::size_t i = 1; i < starts.size(); ++i) {
        const double interval = std::chrono::duration<double>(starts[i] - starts[i - 1]).count();
        frequencies.push_back(1.0 / interval);
        errors_us.push_back(std::abs(interval - period) * 1e6);
    }
    Row row{hertz,
            frequencies.size(),
            0,
            0,
            0,
            0,
            0,
            0,
            timing.skipped_ticks,
            received != nullptr ? *received - received_before : 0};
    if (frequencies.empty())
        return row;
    double sum = 0;
    for (double f : frequencies)
        sum += f;
    row.mean = sum / static_cast<double>(frequencies.size());
    double squares = 0;
    for (double f : frequencies)
        squares += (f - row.mean) * (f - row.mean);
    row.std = std::sqrt(squares / static_cast<double>(frequencies.size() - 1));
    double interval_squares = 0;
    for (std::size_t i = 1; i < starts.size(); ++i) {
        const double deviation =
            std::chrono::duration<double>(starts[i] - starts[i - 1]).count() - period;
        interval_squares += deviation * deviation;
    }
    row.interval_std_us =
        std::sqrt(interval_squares / static_cast<double>(frequencies.size())) * 1e6;
    std::sort(frequencies.begin(), frequencies.end());
    row.min = frequencies.front();
    row.median = frequencies[frequencies.size() / 2];
    std::sort(errors_us.begin(), errors_us.end());
    row.p99_error_us = errors_us[errors_us.size() * 99 / 100];
    return row;
}

void print_row(const char *label, const Row &row)
{
    std::printf(
        "%-10s %7.0f %7zu %10.3f %9.3f %7.2f%% %9.3f %9.3f %9.1f %8.1f %6.2f%% %7llu %9ld\n", label,
        row.hertz, row.count, row.mean, row.std, 100 * row.std / row.mean, row.min, row.median,
        row.p99_error_us, row.interval_std_us, row.interval_std_us * row.hertz / 1e4,
        static_cast<unsigned long long>(row.skipped), row.received);
}

} // namespace

int main(int argc, char **argv)
try {
    if (argc < 3) {
        std::fprintf(stderr,
                     "usage: scheduler_bench SERVICE_URL TOPIC_URL [SECONDS_PER_RATE [LOAD]]\n");
        return 2;
    }
    const std::string service = argv[1], topic_url = argv[2];
    const auto seconds = std::chrono::seconds(argc > 3 ? std::atol(argv[3]) : 10);
    const long load = argc > 4 ? std::atol(argv[4]) : 2000;

    ubii::Node node(options(service, topic_url, "scheduler-bench"));
    node.connect(10s);

    std::printf("# %lld s per rate; frequencies implied by the intervals between pass starts\n",
                static_cast<long long>(seconds.count()));
    std::printf("%-10s %7s %7s %10s %9s %8s %9s %9s %9s %8s %7s %7s %9s\n", "run", "target",
                "count", "mean_hz", "std_hz", "relstd", "min_hz", "median", "p99_err_us",
                "ival_std_us", "ival_rel", "skipped", "received");
    for (double hertz : {10.0, 60.0, 120.0, 200.0, 1000.0}) {
        print_row("bare", measure(nullptr, hertz, seconds, nullptr));
        print_row("node", measure(&node, hertz, seconds, nullptr));
    }

    // A second node publishes `load` records per second that this node receives.
    std::atomic<long> received{0};
    long received_seen = 0;
    auto subscription = node.subscribe("/libubii/bench/load", [&](const ubii::Record &) {
        received.fetch_add(1, std::memory_order_relaxed);
    });
    node.run_for(300ms);
    std::atomic<bool> publishing{true};
    std::thread publisher([&] {
        ubii::Node sender(options(service, topic_url, "scheduler-bench-load"));
        sender.connect(10s);
        const auto period = std::chrono::nanoseconds(1'000'000'000 / std::max(1L, load));
        auto next = std::chrono::steady_clock::now();
        double value = 0;
        while (publishing.load()) {
            next += period;
            if (sender.try_publish("/libubii/bench/load", value += 1) != ubii::Status::ok)
                sender.poll(1ms);
            sender.poll(0ms);
            std::this_thread::sleep_until(next);
        }
        sender.stop_wait();
    });
    node.run_for(1s);
    for (double hertz : {200.0, 1000.0}) {
        received_seen = received.load();
        Row row = measure(&node, hertz, seconds, nullptr);
        row.received = received.load() - received_seen;
        char label[32];
        std::snprintf(label, sizeof label, "load%ld", load);
        print_row(label, row);
    }
    publishing = false;
    publisher.join();

    // Free mode: empty passes on the node (each poll does its I/O, then one pass) and on a bare
    // scheduler, for the per-pass cost without the port.
    {
        std::uint64_t passes = 0;
        ubii::ModuleDescription description{"free", "empty", {}, {}, ubii::Free{}};
        ubii::RunningModule free_module =
            node.run(ubii::make_module(description, [&](ubii::Pass &) { ++passes; }));
        const double cpu0 = cpu_seconds();
        const auto t0 = std::chrono::steady_clock::now();
        while (std::chrono::steady_clock::now() - t0 < 3s)
            node.poll(0ms);
        const double wall =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        const double cpu = cpu_seconds() - cpu0;
        std::printf("free-node      passes_per_s=%.0f cpu_us_per_pass=%.2f\n",
                    static_cast<double>(passes) / wall, cpu * 1e6 / static_cast<double>(passes));
    }
    {
        ubii::Scheduler scheduler;
        std::uint64_t passes = 0;
        ubii::ModuleDescription description{"free", "empty", {}, {}, ubii::Free{}};
        const std::string id =
            scheduler.add(ubii::make_module(description, [&](ubii::Pass &) { ++passes; }));
        scheduler.start(id);
        const double cpu0 = cpu_seconds();
        const auto t0 = std::chrono::steady_clock::now();
        while (std::chrono::steady_clock::now() - t0 < 2s)
            scheduler.run_due();
        const double wall =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        const double cpu = cpu_seconds() - cpu0;
        std::printf("free-scheduler passes_per_s=%.0f cpu_us_per_pass=%.3f\n",
                    static_cast<double>(passes) / wall, cpu * 1e6 / static_cast<double>(passes));
    }
    std::printf("# thesis Table 3.1 (Python node, asyncio, adjusted): 10 Hz mean 9.977 std 0.026; "
                "60 Hz 58.7 std 0.938; 120 Hz 120.4 std 6.163; 200 Hz 203.9 std 15.868 "
                "(relstd 7.8 %%); free ~4000 passes/s\n");
    node.stop_wait();
    return 0;
} catch (const std::exception &error) {
    std::fprintf(stderr, "scheduler_bench: %s\n", error.what());
    return 1;
}

// cpp_pubsub_bench: pubsub_bench.c's measurement with the C++ layer (ubii::Node, a lent
// ubii::Record per arrival read with as<double>(), try_publish), so that bench/cpp_overhead.sh can
// put the layer's cost beside the C core's, same master, same modes, same transport.
//
//   cpp_pubsub_bench SERVICE_URL TOPIC_URL [ROUNDS [MESSAGES [WINDOW [FRAME_US]]]]
#include <algorithm>
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
using Clock = std::chrono::steady_clock;

namespace
{

const std::string topic = "/libubii/bench/echo";

struct Cpu {
    double user, system;
    long switches;
};

Cpu cpu_now()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return {static_cast<double>(usage.ru_utime.tv_sec) +
                static_cast<double>(usage.ru_utime.tv_usec) / 1e6,
            static_cast<double>(usage.ru_stime.tv_sec) +
                static_cast<double>(usage.ru_stime.tv_usec) / 1e6,
            usage.ru_nvcsw + usage.ru_nivcsw};
}

double seconds_since(Clock::time_point start)
{
    return std::chrono::duration<double>(Clock::now() - start).count();
}

} // namespace

int main(int argc, char **argv)
try {
    if (argc < 3) {
        std::fprintf(stderr, "usage: cpp_pubsub_bench SERVICE_URL TOPIC_URL [ROUNDS [MESSAGES "
                             "[WINDOW [FRAME_US]]]]\n");
        return 2;
    }
    const int rounds = argc > 3 ? std::atoi(argv[3]) : 2000;
    const long messages = argc > 4 ? std::atol(argv[4]) : 20000;
    const long window = argc > 5 ? std::atol(argv[5]) : 100;
    const long frame_us = argc > 6 ? std::atol(argv[6]) : 0;

    ubii::NodeOptions options;
    options.service_url = argv[1];
    options.topic_url = argv[2];
    options.name = "libubii-cpp-bench";
    options.stamp_records = false; // as pubsub_bench.c
    ubii::Node node(options);
    node.on_error([](ubii::Status status, std::string_view detail) {
        std::fprintf(stderr, "cpp_pubsub_bench: %s: %.*s\n", ubii::describe(status),
                     static_cast<int>(detail.size()), detail.data());
    });
    long received = 0;
    double sum = 0; // the value is read, as an application would
    auto subscription = node.subscribe(topic, [&](const ubii::Record &record) {
        sum += record.as<double>();
        ++received;
    });
    node.connect(10s);
    if (!node.run_until(
            [&] {
                node.try_publish(topic, 0.0);
                node.poll(10ms);
                return received > 0;
            },
            10s)) {
        std::fprintf(stderr, "cpp_pubsub_bench: no echo from the master\n");
        return 1;
    }
    auto poll_until = [&](long target, double timeout) {
        const auto start = Clock::now();
        while (received < target) {
            if (seconds_since(start) > timeout)
                return false;
            node.poll(1ms);
        }
        return true;
    };
    poll_until(received + 1000000, 0.2);

    std::vector<double> rtt(static_cast<std::size_t>(rounds));
    for (int i = 0; i < rounds; ++i) {
        const long target = received + 1;
        const auto start = Clock::now();
        node.try_publish(topic, static_cast<double>(i));
        if (!poll_until(target, 5.0)) {
            std::fprintf(stderr, "cpp_pubsub_bench: round %d lost\n", i);
            return 1;
        }
        rtt[static_cast<std::size_t>(i)] = seconds_since(start) * 1e6;
    }
    std::sort(rtt.begin(), rtt.end());

    const long base = received;
    const Cpu before = cpu_now();
    const auto start = Clock::now();
    long sent = 0;
    while (sent < messages) {
        while (sent < messages && sent - (received - base) < window) {
            if (node.try_publish(topic, static_cast<double>(sent)) != ubii::Status::ok)
                break;
            ++sent;
        }
        if (frame_us > 0) {
            node.poll(0ms);
            const double frame = static_cast<double>(frame_us) / 1e6;
            const double wait = frame - std::fmod(seconds_since(start), frame);
            std::this_thread::sleep_for(std::chrono::duration<double>(wait));
        } else {
            node.poll(1ms);
        }
    }
    if (!poll_until(base + messages, 30.0)) {
        std::fprintf(stderr, "cpp_pubsub_bench: %ld of %ld came back\n", received - base, messages);
        return 1;
    }
    const double elapsed = seconds_since(start);
    const Cpu after = cpu_now();
    const double user = after.user - before.user, system = after.system - before.system;
    const double count = static_cast<double>(messages);
    std::printf("rtt_p50_us=%.1f rtt_p99_us=%.1f messages_per_s=%.0f cpu_us_per_message=%.2f "
                "user_us_per_message=%.2f system_us_per_message=%.2f switches_per_message=%.2f\n",
                rtt[static_cast<std::size_t>(rounds / 2)],
                rtt[static_cast<std::size_t>(rounds * 99 / 100)], count / elapsed,
                (user + system) * 1e6 / count, user * 1e6 / count, system * 1e6 / count,
                static_cast<double>(after.switches - before.switches) / count);
    if (!node.stop_wait())
        std::fprintf(stderr, "cpp_pubsub_bench: the node did not deregister cleanly\n");
    return sum >= 0 ? 0 : 1;
} catch (const std::exception &error) {
    std::fprintf(stderr, "cpp_pubsub_bench: %s\n", error.what());
    return 1;
}

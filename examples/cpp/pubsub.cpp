// pubsub, in C++: two nodes in one process, one topic. The publisher sends a counter and a
// rotating vector; the subscriber prints what arrives (examples/c/pubsub.c is its C twin).
//
//   pubsub_cpp [SERVICE_URL [TOPIC_URL [SECONDS]]]   defaults: tcp://127.0.0.1:8101
//                                                    tcp://127.0.0.1:8103 3
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include "ubii/ubii.hpp"

using namespace std::chrono_literals;

int main(int argc, char **argv)
try {
    ubii::NodeOptions options;
    options.service_url = argc > 1 ? argv[1] : "tcp://127.0.0.1:8101";
    options.topic_url = argc > 2 ? argv[2] : "tcp://127.0.0.1:8103";
    const double seconds = argc > 3 ? std::stod(argv[3]) : 3.0;

    options.name = "libubii-cpp-example-publisher";
    ubii::Node publisher(options);
    options.name = "libubii-cpp-example-subscriber";
    ubii::Node subscriber(options);
    publisher.connect(10s);
    subscriber.connect(10s);
    std::printf("publisher %s and subscriber %s are connected\n", publisher.client_id().c_str(),
                subscriber.client_id().c_str());

    // Topics are scoped by the publisher's client id, so that runs side by side do not mix.
    const std::string base = "/" + publisher.client_id() + "/example";
    int received = 0;
    auto counter = subscriber.subscribe<std::int32_t>(
        base + "/counter", [&](std::int32_t count, const ubii::RecordInfo &info) {
            std::printf("subscriber: %s = %d\n", std::string(info.topic).c_str(), count);
            ++received;
        });
    auto vectors = subscriber.subscribe_regex<ubii::Vector3>(
        "^" + base + "/vec", [&](const ubii::Vector3 &v, const ubii::RecordInfo &info) {
            std::printf("subscriber: %s = (%.3f, %.3f, %.3f)\n", std::string(info.topic).c_str(),
                        v.x(), v.y(), v.z());
            ++received;
        });
    auto pump = [&](std::chrono::milliseconds duration) {
        const auto until = std::chrono::steady_clock::now() + duration;
        while (std::chrono::steady_clock::now() < until) {
            publisher.poll(5ms);
            subscriber.poll(5ms);
        }
    };
    pump(300ms); // let the subscriptions reach the master

    int sent = 0;
    const auto start = std::chrono::steady_clock::now();
    for (;;) {
        const double elapsed =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (elapsed >= seconds)
            break;
        const double phase = elapsed * 2.0;
        publisher.publish(base + "/counter", sent);
        publisher.publish(base + "/vector", ubii::vector3(std::cos(phase), std::sin(phase), phase));
        sent += 2;
        pump(250ms);
    }
    pump(300ms);
    std::printf("sent %d records, received %d\n", sent, received);
    if (sent == 0 || received != sent) {
        std::fprintf(stderr, "pubsub_cpp: not every record sent arrived\n");
        return 1;
    }
    return 0;
} catch (const std::exception &error) {
    std::fprintf(stderr, "pubsub_cpp: %s\n", error.what());
    return 1;
}

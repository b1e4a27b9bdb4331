// cpp_layer_cost: what the C++ layer adds per message, without a master or a socket in the way.
// A replay port hands the node the same TopicData (one double record) as often as it asks and
// swallows what the node sends, so the time measured is the core's and the layer's alone:
//   receive: records dispatched to a subscription that reads the double
//            (C: ubii_record_double in a C callback; C++: a lent ubii::Record, as<double>())
//   publish: ubii_publish_double against ubii::Node::try_publish
// C and C++ alternate, ROUNDS times; prints each figure's median in ns per message and the
// ratios C++/C. Asserts nothing.
//
//   cpp_layer_cost [RECORDS_PER_ROUND [ROUNDS]]    defaults 1000000 7
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "ubii/ubii.h"
#include "ubii/ubii.hpp"

using Clock = std::chrono::steady_clock;

namespace
{

// ServiceReply encodings the connection sequence needs, and one TopicData{record{topic, double}}.
std::vector<std::uint8_t> bytes(std::initializer_list<int> values)
{
    std::vector<std::uint8_t> out;
    for (int v : values)
        out.push_back(static_cast<std::uint8_t>(v));
    return out;
}

class ReplayPort
{
  public:
    ReplayPort()
    {
        vtable_.open = [](void *p, ubii_channel c, const char *, const char *) {
            self(p).open_[c] = true;
            return UBII_OK;
        };
        vtable_.close = [](void *p, ubii_channel c) { self(p).open_[c] = false; };
        vtable_.state = [](void *p, ubii_channel c) {
            return self(p).open_[c] ? UBII_CHANNEL_OPEN : UBII_CHANNEL_CLOSED;
        };
        vtable_.send_begin = [](void *p, ubii_channel c, std::size_t size, std::uint8_t **out) {
            auto &port = self(p);
            port.sent_.resize(size);
            *out = port.sent_.data();
            port.sending_ = c;
            return UBII_OK;
        };
        vtable_.send_commit = [](void *p, ubii_channel c, unsigned) {
            if (c == UBII_CHANNEL_SERVICE)
                self(p).answer();
            return UBII_OK;
        };
        vtable_.receive = [](void *p, ubii_channel c, const std::uint8_t **data, std::size_t *size,
                             unsigned *flags) {
            auto &port = self(p);
            *flags = 0;
            if (c == UBII_CHANNEL_SERVICE) {
                if (port.reply_.empty())
                    return UBII_ERR_WOULD_BLOCK;
                port.lent_ = std::move(port.reply_);
                port.reply_.clear();
                *data = port.lent_.data();
                *size = port.lent_.size();
                return UBII_OK;
            }
            if (port.records_left_ == 0)
                return UBII_ERR_WOULD_BLOCK;
            --port.records_left_;
            *data = port.record_.data();
            *size = port.record_.size();
            return UBII_OK;
        };
        vtable_.wait = [](void *, int) { return UBII_OK; };
        vtable_.pollfds = [](void *, ubii_pollfd *, int) { return 0; };
        vtable_.monotonic_ms = [](void *) {
            return static_cast<std::uint64_t>(std::chrono::duration_cast<std::chrono::milliseconds>(
                                                  Clock::now().time_since_epoch())
                                                  .count());
        };
        vtable_.epoch_ms = [](void *) { return std::int64_t{1700000000000}; };
        // TopicData{record{topic "/bench", double 1.5}}
        record_ = bytes({0x12, 0x11, 0x0a, 0x06, '/', 'b', 'e', 'n', 'c', 'h', 0x19, 0, 0, 0, 0, 0,
                         0, 0xf8, 0x3f});
    }
    ubii_port get()
    {
        return ubii_port{&vtable_, this};
    }
    void queue_records(std::size_t count)
    {
        records_left_ = count;
    }

  private:
    static ReplayPort &self(void *p)
    {
        return *static_cast<ReplayPort *>(p);
    }
    // Answers by the request's topic: server configuration, registration, anything else success.
    void answer()
    {
        const std::string request(sent_.begin(), sent_.end());
        if (request.find("/services/server_configuration") != std::string::npos)
            // ServiceReply{server{port_topic_data_zmq "8103"}}
            reply_ = bytes({0x2a, 0x06, 0x3a, 0x04, '8', '1', '0', '3'});
        else if (request.find("/services/client/registration") != std::string::npos)
            // ServiceReply{client{id "c"}}
            reply_ = bytes({0x1a, 0x03, 0x0a, 0x01, 'c'});
        else
            // ServiceReply{success{}}
            reply_ = bytes({0x0a, 0x00});
    }

    ubii_port_vtable vtable_{};
    bool open_[UBII_CHANNEL_COUNT] = {false, false};
    std::vector<std::uint8_t> sent_, reply_, lent_, record_;
    ubii_channel sending_ = UBII_CHANNEL_SERVICE;
    std::size_t records_left_ = 0;
};

double received_sum = 0;

void on_c_record(ubii_node *, const ubii_record *record, void *)
{
    double value = 0;
    ubii_record_double(record, &value);
    received_sum += value;
}

// Time per message of `work(count)`, in ns.
template <class Work> double ns_per_message(std::size_t count, Work work)
{
    const auto start = Clock::now();
    work(count);
    return std::chrono::duration<double, std::nano>(Clock::now() - start).count() /
           static_cast<double>(count);
}

double median(std::vector<double> values)
{
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

} // namespace

int main(int argc, char **argv)
{
    const std::size_t records = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 1000000;
    const int rounds = argc > 2 ? std::atoi(argv[2]) : 7;

    ReplayPort c_port;
    ubii_config config;
    ubii_config_init(&config);
    config.service_url = "tcp://replay:8101";
    config.stamp_records = false;
    static ubii_node c_node;
    ubii_node_init(&c_node, sizeof c_node, &config, c_port.get());
    ubii_subscribe(&c_node, "/bench", on_c_record, nullptr, nullptr);
    ubii_node_start(&c_node);
    for (int i = 0; i < 20 && ubii_node_state(&c_node) != UBII_STATE_READY; ++i)
        ubii_node_poll(&c_node, 0);

    ReplayPort cpp_port;
    ubii::NodeOptions options;
    options.service_url = "tcp://replay:8101";
    options.stamp_records = false;
    ubii::Node node(options, cpp_port.get());
    auto subscription = node.subscribe(
        "/bench", [](const ubii::Record &record) { received_sum += record.as<double>(); });
    node.start();
    for (int i = 0; i < 20 && !node.ready(); ++i)
        node.poll();
    if (ubii_node_state(&c_node) != UBII_STATE_READY || !node.ready()) {
        std::fprintf(stderr, "cpp_layer_cost: the nodes did not get ready on the replay port\n");
        return 1;
    }

    auto receive_c = [&](std::size_t count) {
        c_port.queue_records(count);
        while (ubii_node_poll(&c_node, 0) == UBII_OK &&
               ubii_node_state(&c_node) == UBII_STATE_READY) {
            ubii_stats stats;
            ubii_node_stats(&c_node, &stats);
            if (stats.records_received % count == 0 && stats.records_received > 0)
                break;
        }
    };
    auto receive_cpp = [&](std::size_t count) {
        cpp_port.queue_records(count);
        while (node.ready()) {
            node.poll();
            if (node.stats().records_received % count == 0 && node.stats().records_received > 0)
                break;
        }
    };
    auto publish_c = [&](std::size_t count) {
        for (std::size_t i = 0; i < count; ++i)
            ubii_publish_double(&c_node, "/bench/out", static_cast<double>(i));
    };
    auto publish_cpp = [&](std::size_t count) {
        for (std::size_t i = 0; i < count; ++i)
            node.try_publish("/bench/out", static_cast<double>(i));
    };

    std::vector<double> c_in, cpp_in, c_out, cpp_out;
    for (int round = 0; round < rounds; ++round) {
        c_in.push_back(ns_per_message(records, receive_c));
        cpp_in.push_back(ns_per_message(records, receive_cpp));
        c_out.push_back(ns_per_message(records, publish_c));
        cpp_out.push_back(ns_per_message(records, publish_cpp));
    }
    ubii_stats c_stats;
    ubii_node_stats(&c_node, &c_stats);
    const ubii::Stats cpp_stats = node.stats();
    std::printf("records per round %zu, rounds %d (received C %llu, C++ %llu; checksum %.0f)\n",
                records, rounds, static_cast<unsigned long long>(c_stats.records_received),
                static_cast<unsigned long long>(cpp_stats.records_received), received_sum);
    std::printf("receive: C %.1f ns, C++ %.1f ns per record, ratio %.3f\n", median(c_in),
                median(cpp_in), median(cpp_in) / median(c_in));
    std::printf("publish: C %.1f ns, C++ %.1f ns per record, ratio %.3f\n", median(c_out),
                median(cpp_out), median(cpp_out) / median(c_out));
    return 0;
}

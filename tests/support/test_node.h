#ifndef UBII_TEST_NODE_H
#define UBII_TEST_NODE_H

// A node on the Linux port, owned RAII-style, with helpers to poll until something happens.
// Endpoints come from UBII_TEST_PORT_BASE (the master fixture's ports).

#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "test_port.h"
#include "ubii/ubii.h"

namespace ubii_test
{

int port_base();
std::string service_url();                         // tcp://127.0.0.1:<base>
std::string topic_zmq_url();                       // tcp://127.0.0.1:<base + 2>
std::string topic_ws_url();                        // ws://127.0.0.1:<base + 3>
std::string unique_topic(const std::string &stem); // distinct per call and per process

struct Received {
    std::string topic;
    ubii_record_type type;
    std::vector<uint8_t> value;
    uint64_t scalar;
    bool has_timestamp;
    int64_t millis;
};

class TestNode
{
  public:
    explicit TestNode(const std::string &name, const std::string &topic_url = topic_zmq_url(),
                      const std::string &service = service_url(), Tls tls = Tls::off);
    ~TestNode();
    TestNode(const TestNode &) = delete;
    TestNode &operator=(const TestNode &) = delete;

    ubii_node *get()
    {
        return node_.get();
    }
    const char *transport_error() const
    {
        return port_.last_error();
    }
    ubii_config &config()
    {
        return config_;
    }
    ubii_status start()
    {
        return ubii_node_start(node_.get());
    }
    // Polls until `done` holds or `timeout` passes; returns whether it held.
    bool poll_until(const std::function<bool()> &done,
                    std::chrono::milliseconds timeout = std::chrono::seconds(10));
    bool wait_ready(std::chrono::milliseconds timeout = std::chrono::seconds(10));
    // Starts a node that cannot succeed and polls until it gives up (FAILED) after
    // `attempts` reconnection attempts 50 ms apart; false if it does not within `timeout`.
    bool start_and_wait_failed(uint32_t attempts,
                               std::chrono::milliseconds timeout = std::chrono::seconds(10));
    // Subscribes, collecting every record into received(); regex when `regex`.
    ubii_subscription collect(const std::string &pattern, bool regex = false);
    std::vector<Received> &received()
    {
        return received_;
    }
    std::vector<std::pair<ubii_status, std::string>> &errors()
    {
        return errors_;
    }
    std::vector<ubii_state> &states()
    {
        return states_;
    }
    // The client id the master gave each registration (read when the node reached OPENING).
    std::vector<std::string> &registered_ids()
    {
        return registered_ids_;
    }

  private:
    static void on_record(ubii_node *, const ubii_record *record, void *user);
    static void on_error(ubii_node *, ubii_status status, const char *detail, void *user);
    static void on_state(ubii_node *, ubii_state, ubii_state current, ubii_status, void *user);

    std::string name_, topic_url_, service_url_;
    ubii_config config_;
    TestPort port_;
    std::unique_ptr<ubii_node> node_;
    bool initialised_ = false;
    std::vector<Received> received_;
    std::vector<std::pair<ubii_status, std::string>> errors_;
    std::vector<ubii_state> states_;
    std::vector<std::string> registered_ids_;
};

} // namespace ubii_test

#endif

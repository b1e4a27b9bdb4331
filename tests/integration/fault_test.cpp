// Faults between a node and the real master, made by a TCP proxy on the node's topic data
// connection (ZMQ and WebSocket) or its service connection: a cut, a frame cut off in the middle,
// corrupted bytes, delay, a stall. The node must say so (a state change or an error report),
// reconnect, subscribe again and carry records again; no call may wait past its timeout.
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "fault_proxy.h"
#include "test_node.h"

using namespace std::chrono_literals;
using ubii_test::FaultProxy;
using ubii_test::TestNode;
using ubii_test::unique_topic;

namespace
{

enum class Transport { zmq, websocket };

std::string name_of(Transport transport)
{
    return transport == Transport::zmq ? "zmq" : "websocket";
}

// Each test listens on a port of its own: ctest runs them in parallel.
uint16_t proxy_port(int test, Transport transport)
{
    return static_cast<uint16_t>(ubii_test::port_base() + 40 + 2 * test +
                                 (transport == Transport::websocket ? 1 : 0));
}

uint16_t topic_port(Transport transport)
{
    return static_cast<uint16_t>(ubii_test::port_base() + (transport == Transport::zmq ? 2 : 3));
}

std::string url(Transport transport, uint16_t port)
{
    return (transport == Transport::zmq ? "tcp://127.0.0.1:" : "ws://127.0.0.1:") +
           std::to_string(port);
}

bool saw(TestNode &node, ubii_state state)
{
    return std::count(node.states().begin(), node.states().end(), state) > 0;
}

class TopicFaults : public ::testing::TestWithParam<Transport>
{
  protected:
    // A node whose topic data runs through `proxy`, subscribed to a topic of its own and
    // receiving its own int32 records; true once a record went round.
    bool start(TestNode &node)
    {
        node.config().reconnect_min_ms = 50;
        node.config().reconnect_max_ms = 200;
        topic_ = unique_topic("/fault-" + name_of(GetParam()));
        if (!node.wait_ready())
            return false;
        node.collect(topic_);
        return round_trip(node);
    }

    // Publishes `value` until it comes back (publishing again while the node reconnects).
    bool round_trip(TestNode &node, int32_t value = 1, std::chrono::milliseconds timeout = 10s)
    {
        return node.poll_until(
            [&] {
                if (ubii_node_state(node.get()) == UBII_STATE_READY)
                    ubii_publish_int32(node.get(), topic_.c_str(), value);
                return std::any_of(node.received().begin(), node.received().end(),
                                   [&](const ubii_test::Received &r) {
                                       return static_cast<int32_t>(r.scalar) == value;
                                   });
            },
            timeout);
    }

    // After a fault: the node left READY, came back, and carries records again.
    void expect_recovered(TestNode &node)
    {
        ASSERT_TRUE(node.poll_until([&] { return saw(node, UBII_STATE_RECONNECTING); }, 10s))
            << "the fault went unnoticed";
        EXPECT_TRUE(round_trip(node, 2)) << "no record after reconnecting";
        EXPECT_EQ(ubii_node_state(node.get()), UBII_STATE_READY);
    }

    std::string topic_;
};

TEST_P(TopicFaults, ACutConnectionIsReportedAndTheNodeComesBack)
{
    FaultProxy proxy(proxy_port(0, GetParam()), topic_port(GetParam()));
    TestNode node("fault-cut", url(GetParam(), proxy.port()));
    ASSERT_TRUE(start(node)) << node.transport_error();
    proxy.cut();
    expect_recovered(node);
    EXPECT_GE(proxy.accepted(), 2); // a new connection, subscribed again (round_trip)
}

TEST_P(TopicFaults, AFrameCutOffInTheMiddleEndsTheConnectionCleanly)
{
    FaultProxy proxy(proxy_port(1, GetParam()), topic_port(GetParam()));
    TestNode node("fault-truncate", url(GetParam(), proxy.port()));
    ASSERT_TRUE(start(node)) << node.transport_error();
    proxy.truncate_next_from_master();
    ubii_publish_int32(node.get(), topic_.c_str(), 7); // its echo is the chunk cut in half
    expect_recovered(node);
}

TEST_P(TopicFaults, CorruptedBytesFromTheMasterAreRefusedNotCrashedOn)
{
    FaultProxy proxy(proxy_port(2, GetParam()), topic_port(GetParam()));
    TestNode node("fault-corrupt", url(GetParam(), proxy.port()));
    ASSERT_TRUE(start(node)) << node.transport_error();
    proxy.corrupt_next_from_master();
    ubii_publish_int32(node.get(), topic_.c_str(), 7);
    // Inverted framing breaks the stream: the connection ends and comes back. (Bytes that still
    // framed a message would reach the decoder, which reports them; either way the node goes on.)
    ASSERT_TRUE(node.poll_until(
        [&] { return saw(node, UBII_STATE_RECONNECTING) || !node.errors().empty(); }, 10s));
    EXPECT_TRUE(round_trip(node, 2)) << "no record after the corruption";
}

TEST_P(TopicFaults, DelayedTrafficArrivesCompleteAndInOrder)
{
    FaultProxy proxy(proxy_port(3, GetParam()), topic_port(GetParam()));
    TestNode node("fault-delay", url(GetParam(), proxy.port()));
    ASSERT_TRUE(start(node)) << node.transport_error();
    proxy.delay(300ms);
    for (int32_t value = 100; value < 120; ++value)
        ASSERT_EQ(ubii_publish_int32(node.get(), topic_.c_str(), value), UBII_OK);
    std::vector<int32_t> numbered; // start()'s records may still come in: only 100 to 119 count
    ASSERT_TRUE(node.poll_until(
        [&] {
            numbered.clear();
            for (const auto &record : node.received())
                if (static_cast<int32_t>(record.scalar) >= 100)
                    numbered.push_back(static_cast<int32_t>(record.scalar));
            return numbered.size() >= 20;
        },
        10s))
        << numbered.size() << " of 20 arrived";
    for (size_t i = 0; i < numbered.size(); ++i)
        EXPECT_EQ(numbered[i], 100 + static_cast<int32_t>(i));
    EXPECT_FALSE(saw(node, UBII_STATE_RECONNECTING));
}

// A half-open connection: the proxy plays a master that PINGs, then stops forwarding while
// keeping both sockets open. Neither socket can tell; the node's PING watchdog must, within
// ping_timeout_ms, and then reconnect.
TEST_P(TopicFaults, AHalfOpenConnectionIsDetectedWithinThePingWindow)
{
    FaultProxy proxy(proxy_port(4, GetParam()), topic_port(GetParam()));
    TestNode node("fault-half-open", url(GetParam(), proxy.port()));
    node.config().ping_timeout_ms = 1000;
    ASSERT_TRUE(start(node)) << node.transport_error();
    proxy.send_pings(GetParam() == Transport::zmq ? FaultProxy::Framing::zmtp
                                                  : FaultProxy::Framing::websocket,
                     200ms);
    ubii_stats stats{};
    ASSERT_TRUE(node.poll_until(
        [&] {
            ubii_node_stats(node.get(), &stats);
            return stats.pings >= 2;
        },
        5s))
        << "the node answered no PING";
    proxy.stall();
    const auto stalled = std::chrono::steady_clock::now();
    ASSERT_TRUE(node.poll_until([&] { return saw(node, UBII_STATE_RECONNECTING); }, 10s))
        << "the half-open connection went unnoticed";
    const auto noticed = std::chrono::steady_clock::now() - stalled;
    EXPECT_LT(noticed, 2500ms) << "later than the PING window (1000 ms) allows";
    proxy.pass();
    EXPECT_TRUE(round_trip(node, 2)) << "no record after reconnecting";
}

INSTANTIATE_TEST_SUITE_P(Transports, TopicFaults,
                         ::testing::Values(Transport::zmq, Transport::websocket),
                         [](const auto &test) { return name_of(test.param); });

struct CallResult {
    bool done = false;
    ubii_status status = UBII_OK;
};

void on_reply(ubii_node *, const ubii_reply *reply, void *user)
{
    auto *result = static_cast<CallResult *>(user);
    result->done = true;
    result->status = reply->status;
}

// The service connection stalls (the proxy keeps both sockets open and forwards nothing): a call
// ends with UBII_ERR_TIMEOUT at its own timeout, not later, and once the stall ends calls are
// answered again.
TEST(ServiceFaults, AStalledServiceConnectionTimesTheCallOut)
{
    FaultProxy proxy(static_cast<uint16_t>(ubii_test::port_base() + 60),
                     static_cast<uint16_t>(ubii_test::port_base()));
    TestNode node("fault-service-stall", ubii_test::topic_zmq_url(),
                  "tcp://127.0.0.1:" + std::to_string(proxy.port()));
    ASSERT_TRUE(node.wait_ready()) << node.transport_error();
    proxy.stall();
    CallResult stalled;
    const auto started = std::chrono::steady_clock::now();
    ASSERT_EQ(ubii_call_topic(node.get(), UBII_SERVICE_TOPIC_LIST, 300, on_reply, &stalled),
              UBII_OK);
    ASSERT_TRUE(node.poll_until([&] { return stalled.done; }, 5s));
    const auto took = std::chrono::steady_clock::now() - started;
    EXPECT_EQ(stalled.status, UBII_ERR_TIMEOUT);
    EXPECT_GE(took, 290ms); // the node's clock counts whole milliseconds
    EXPECT_LT(took, 2s) << "the call outlived its timeout";

    proxy.pass();
    CallResult answered;
    ASSERT_TRUE(node.poll_until(
        [&] {
            if (!answered.done || answered.status != UBII_OK) {
                answered = CallResult{};
                ubii_call_topic(node.get(), UBII_SERVICE_TOPIC_LIST, 500, on_reply, &answered);
                node.poll_until([&] { return answered.done; }, 2s);
            }
            return answered.done && answered.status == UBII_OK;
        },
        10s));
}

} // namespace

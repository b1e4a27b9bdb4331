// A node against the real master: the connection sequence, publish and subscribe.
#include <algorithm>
#include <cstddef>
#include <cstring>
#include <functional>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <poll.h>

#include "test_node.h"

using ubii_test::Received;
using ubii_test::TestNode;
using ubii_test::TestPort;
using ubii_test::unique_topic;

namespace
{

TEST(NodeConnection, ReachesReadyWithAClientIdFromTheMaster)
{
    TestNode node("connection-test");
    ASSERT_TRUE(node.wait_ready()) << ubii_state_name(ubii_node_state(node.get()));
    EXPECT_EQ(std::strlen(ubii_node_client_id(node.get())), 36u);
    std::vector<ubii_state> expected = {UBII_STATE_CONNECTING, UBII_STATE_REGISTERING,
                                        UBII_STATE_OPENING, UBII_STATE_READY};
    EXPECT_EQ(node.states(), expected);
}

TEST(NodeConnection, StopDeregistersAndReachesStopped)
{
    TestNode node("stop-test");
    ASSERT_TRUE(node.wait_ready());
    EXPECT_EQ(ubii_node_stop_wait(node.get(), 3000), UBII_OK);
    EXPECT_EQ(ubii_node_state(node.get()), UBII_STATE_STOPPED);
    EXPECT_STREQ(ubii_node_client_id(node.get()), "");
    EXPECT_TRUE(node.errors().empty()) << node.errors().front().second;
}

TEST(NodePubSub, DoubleRoundTripsThroughTheMaster)
{
    TestNode node("pubsub-test");
    ASSERT_TRUE(node.wait_ready());
    const std::string topic = unique_topic("/double");
    node.collect(topic);
    // The subscription reaches the master asynchronously; publish until the first copy arrives.
    ASSERT_TRUE(node.poll_until([&] {
        ubii_publish_double(node.get(), topic.c_str(), 2.5);
        return !node.received().empty();
    }));
    const auto &record = node.received().front();
    EXPECT_EQ(record.topic, topic);
    ASSERT_EQ(record.type, UBII_RECORD_DOUBLE);
    double value;
    std::memcpy(&value, &record.scalar, sizeof value);
    EXPECT_EQ(value, 2.5);
    // No timestamp check: the npm 0.4.0 master forwards only topic and value (it rebuilds each
    // record), while the current master forwards the publisher's record whole.
}

} // namespace

namespace
{

TEST(NodeWebSocket, DoubleRoundTripsOverWebSocketTopicData)
{
    TestNode node("websocket-test", ubii_test::topic_ws_url());
    ASSERT_TRUE(node.wait_ready()) << ubii_state_name(ubii_node_state(node.get()));
    const std::string topic = unique_topic("/ws-double");
    node.collect(topic);
    ASSERT_TRUE(node.poll_until([&] {
        ubii_publish_double(node.get(), topic.c_str(), -7.25);
        return !node.received().empty();
    }));
    double value;
    std::memcpy(&value, &node.received().front().scalar, sizeof value);
    EXPECT_EQ(value, -7.25);
}

} // namespace

namespace
{

// A game engine polls once per frame, without waiting. Everything published during a frame must go
// out and come back within a few frames, not one message per poll.
class NodeFrameTick : public ::testing::TestWithParam<std::string>
{
  protected:
    // Subscribes `node` to `topic` and waits until the master serves the subscription; returns
    // with nothing received.
    static bool subscribe_and_warm_up(TestNode &node, const std::string &topic)
    {
        node.collect(topic);
        bool served = node.poll_until([&] {
            ubii_publish_double(node.get(), topic.c_str(), -1.0);
            return !node.received().empty();
        });
        node.poll_until([] { return false; }, std::chrono::milliseconds(100)); // late copies
        node.received().clear();
        return served;
    }
};

TEST_P(NodeFrameTick, HundredsOfMessagesPerFrameGoOutAndComeBack)
{
    TestNode node("frame-tick-test", GetParam());
    ASSERT_TRUE(node.wait_ready());
    const std::string topic = unique_topic("/frame-tick");
    ASSERT_TRUE(subscribe_and_warm_up(node, topic));

    constexpr int messages = 300;
    for (int i = 0; i < messages; ++i) {
        ASSERT_EQ(ubii_publish_double(node.get(), topic.c_str(), i), UBII_OK);
    }
    constexpr int frames = 30; // at 60 Hz: half a second
    int frame = 0;
    for (; frame < frames && node.received().size() < messages; ++frame) {
        ASSERT_EQ(ubii_node_poll(node.get(), 0), UBII_OK);
        std::this_thread::sleep_for(std::chrono::microseconds(16667));
    }
    EXPECT_EQ(node.received().size(), static_cast<size_t>(messages))
        << "after " << frame << " frames";
}

// A camera stream read by a game engine: an image of about a megabyte published every frame, each
// back within a few frames. (The Linux port's libwebsockets connections used to read 4 KB per poll
// and send 64 KB: over WebSocket and the in-thread ZMQ engine no image came back within a second.)
TEST_P(NodeFrameTick, MegabyteImagesKeepUpWithTheFrameRate)
{
    TestNode node("frame-image-test", GetParam());
    ASSERT_TRUE(node.wait_ready());
    const std::string topic = unique_topic("/frame-image");
    ASSERT_TRUE(subscribe_and_warm_up(node, topic));

    constexpr size_t width = 640;
    constexpr size_t room_for_framing = 512;
    // 640x480 RGB8; on the embedded port as many rows as its buffers take.
    const size_t height =
        std::min<size_t>(480, (TestPort::max_message_size() - room_for_framing) / (3 * width));
    auto pixels_of = [&](int image) {
        std::vector<uint8_t> pixels(3 * width * height);
        for (size_t i = 0; i < pixels.size(); ++i) {
            pixels[i] = static_cast<uint8_t>(i * 7 + static_cast<size_t>(image));
        }
        return pixels;
    };
    constexpr int images = 10;
    constexpr int frames = 60; // one second at 60 Hz
    int frame = 0;
    for (; frame < frames && node.received().size() < images; ++frame) {
        if (frame < images) {
            const std::vector<uint8_t> pixels = pixels_of(frame);
            ASSERT_EQ(ubii_publish_image(node.get(), topic.c_str(), static_cast<int32_t>(width),
                                         static_cast<int32_t>(height),
                                         ubii_dataStructure_Image2D_DataFormat_RGB8, pixels.data(),
                                         pixels.size()),
                      UBII_OK);
        }
        ASSERT_EQ(ubii_node_poll(node.get(), 0), UBII_OK);
        std::this_thread::sleep_for(std::chrono::microseconds(16667));
    }
    ASSERT_EQ(node.received().size(), static_cast<size_t>(images))
        << "after " << frame << " frames of " << 3 * width * height << "-byte images";
    for (int image = 0; image < images; ++image) {
        const Received &record = node.received()[static_cast<size_t>(image)];
        ASSERT_EQ(record.type, UBII_RECORD_IMAGE2D);
        const std::vector<uint8_t> pixels = pixels_of(image);
        // The pixels are Image2D's last field, so they end the record's value.
        ASSERT_GE(record.value.size(), pixels.size());
        EXPECT_TRUE(std::equal(pixels.begin(), pixels.end(),
                               record.value.end() - static_cast<std::ptrdiff_t>(pixels.size())))
            << "image " << image;
    }
}

// A loop that publishes once per ubii_node_poll(node, 50) is paced by the poll: writing what was
// published is not the event the wait is for. (The Linux port's WebSocket and in-thread ZMQ used
// to return at once after the write, so such a loop spun and flooded the master.)
TEST_P(NodeFrameTick, PollWithATimeoutWaitsAlthoughEachRoundPublishes)
{
    TestNode node("poll-pacing-test", GetParam());
    ASSERT_TRUE(node.wait_ready());
    const std::string topic = unique_topic("/nobody-listens"); // no copies come back
    constexpr auto span = std::chrono::milliseconds(500);
    const auto end = std::chrono::steady_clock::now() + span;
    int rounds = 0;
    while (std::chrono::steady_clock::now() < end) {
        ASSERT_EQ(ubii_publish_double(node.get(), topic.c_str(), rounds), UBII_OK);
        ASSERT_EQ(ubii_node_poll(node.get(), 50), UBII_OK);
        ++rounds;
    }
    // About 10 rounds of 50 ms; a poll that returns after the write makes thousands.
    EXPECT_LE(rounds, 50) << "published " << rounds << " times in " << span.count() << " ms";
}

// An event loop (libuv's, an engine's) that sleeps until one of the node's fds is ready or its
// deadline comes, and only then calls ubii_node_poll(node, 0): the fds must say when the node
// has work, writing included (a connection being set up, output the socket did not take yet).
// The application's own timer, if any, wakes the loop every `tick`. Returns false when the loop
// slept past `limit` without `done` holding.
bool run_event_loop(TestNode &node, const std::function<bool()> &done,
                    std::chrono::milliseconds limit,
                    std::chrono::milliseconds tick = std::chrono::milliseconds::max())
{
    const auto end = std::chrono::steady_clock::now() + limit;
    while (!done()) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
            end - std::chrono::steady_clock::now());
        if (left.count() <= 0) {
            return false;
        }
        ubii_pollfd node_fds[8];
        pollfd fds[8];
        const int count = std::min(ubii_node_pollfds(node.get(), node_fds, 8), 8);
        for (int i = 0; i < count; ++i) {
            fds[i] = pollfd{node_fds[i].fd, node_fds[i].events, 0};
        }
        const int deadline = ubii_node_next_timeout_ms(node.get());
        int timeout = static_cast<int>(std::min(left, tick).count());
        if (deadline >= 0 && deadline < timeout) {
            timeout = deadline;
        }
        poll(fds, static_cast<nfds_t>(count), timeout);
        if (ubii_node_poll(node.get(), 0) != UBII_OK) {
            return false;
        }
    }
    return true;
}

TEST_P(NodeFrameTick, AnEventLoopWaitingOnTheNodesFdsConnectsAndMovesMegabytes)
{
    TestNode node("event-loop-test", GetParam());
    node.config().service_timeout_ms = 2000;
    ASSERT_TRUE(node.poll_until([] { return true; })); // initialised, not started
    ASSERT_EQ(node.start(), UBII_OK);
    ASSERT_TRUE(run_event_loop(
        node, [&] { return ubii_node_state(node.get()) == UBII_STATE_READY; },
        std::chrono::seconds(10)))
        << ubii_state_name(ubii_node_state(node.get())) << "; " << node.transport_error();
    const std::string topic = unique_topic("/event-loop");
    node.collect(topic);
    // Until the subscription is served: one record per 50 ms, on the application's timer (a flood
    // would fill the master's queue to this node, which then drops what comes next).
    auto last_published = std::chrono::steady_clock::now() - std::chrono::seconds(1);
    ASSERT_TRUE(run_event_loop(
        node,
        [&] {
            const auto now = std::chrono::steady_clock::now();
            if (now - last_published >= std::chrono::milliseconds(50)) {
                ubii_publish_double(node.get(), topic.c_str(), 1.0);
                last_published = now;
            }
            return !node.received().empty();
        },
        std::chrono::seconds(10), std::chrono::milliseconds(50)));
    node.received().clear();
    const size_t size = std::min<size_t>(4u << 20, TestPort::max_message_size() - 512);
    const std::vector<uint8_t> pixels(size, 0x5a);
    ASSERT_EQ(ubii_publish_image(node.get(), topic.c_str(), static_cast<int32_t>(size), 1,
                                 ubii_dataStructure_Image2D_DataFormat_GRAY8, pixels.data(),
                                 pixels.size()),
              UBII_OK);
    EXPECT_TRUE(run_event_loop(
        node,
        [&] {
            for (const Received &record : node.received()) {
                if (record.type == UBII_RECORD_IMAGE2D && record.value.size() >= size) {
                    return true;
                }
            }
            return false;
        },
        std::chrono::seconds(10)))
        << node.received().size() << " records back";
}

INSTANTIATE_TEST_SUITE_P(Transports, NodeFrameTick,
                         ::testing::Values(ubii_test::topic_zmq_url(), ubii_test::topic_ws_url()),
                         [](const ::testing::TestParamInfo<std::string> &transport) {
                             return transport.param.rfind("ws", 0) == 0 ? "WebSocket" : "Zmq";
                         });

} // namespace

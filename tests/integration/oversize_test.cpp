// The embedded port's fixed buffers: a record larger than UBII_EMBEDDED_MAX_MESSAGE, sent by the
// official Node.js node through the real master, is dropped as it streams in and reported; the
// node stays connected and the next record arrives.
#include <algorithm>

#include <gtest/gtest.h>
#include <unistd.h>

#include "child_process.h"
#include "test_node.h"

using ubii_test::ChildProcess;
using ubii_test::TestNode;

namespace {

TEST(OversizeMessages, AreDroppedAndReportedWhileTheNodeCarriesOn)
{
    TestNode node("oversize-test");
    ASSERT_TRUE(node.wait_ready());
    const std::string topic = ubii_test::unique_topic("/oversize");
    node.collect(topic);
    node.collect(topic + "/after");
    node.poll_until([] { return false; }, std::chrono::milliseconds(300)); // subscriptions in place
    ChildProcess publisher({"node", UBII_NODEJS_PUBLISH, UBII_NODEJS_CLIENT, ubii_test::service_url(),
                            ubii_test::topic_zmq_url(), topic,
                            std::to_string(UBII_EMBEDDED_MAX_MESSAGE + 1000)});
    ASSERT_TRUE(publisher.started());
    auto got_after = [&] {
        return std::any_of(node.received().begin(), node.received().end(),
                           [&](const ubii_test::Received &r) { return r.topic == topic + "/after"; });
    };
    auto reported = [&] {
        return std::any_of(node.errors().begin(), node.errors().end(),
                           [](const auto &e) { return e.first == UBII_ERR_TOO_LARGE; });
    };
    ASSERT_TRUE(node.poll_until([&] { return got_after() && reported(); }, std::chrono::seconds(20)))
        << "after: " << got_after() << ", reported: " << reported();
    EXPECT_EQ(ubii_node_state(node.get()), UBII_STATE_READY);
    for (const auto &r : node.received()) {
        EXPECT_NE(r.topic, topic) << "an over-size record was passed on";
    }
}

} // namespace

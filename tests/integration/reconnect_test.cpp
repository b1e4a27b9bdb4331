// Kill the master mid-stream and start it again: the node notices, re-registers (new id),
// re-subscribes and carries on. Uses a master of its own, so the shared one is not disturbed.
#include <chrono>
#include <cstdlib>
#include <cstring>

#include <gtest/gtest.h>

#include "test_node.h"

using ubii_test::TestNode;
using ubii_test::unique_topic;

namespace
{

const int own_port_base = 8201;

// Runs scripts/master.sh; `background` returns at once (the node keeps being polled meanwhile).
bool master(const std::string &action, bool background = false)
{
    std::string command = std::string("UBII_CACHE_DIR='") + UBII_TEST_CACHE_DIR + "' " +
                          UBII_MASTER_SCRIPT + " " + action + " " + UBII_RECONNECT_MASTER_STATE +
                          (action == "start" ? " " + std::to_string(own_port_base) : "") +
                          " >/dev/null" + (background ? " &" : "");
    return std::system(command.c_str()) == 0;
}

bool master_stopped()
{
    return std::system(
               (std::string("test ! -e ") + UBII_RECONNECT_MASTER_STATE + "/master.pid").c_str()) ==
           0;
}

double seconds_since(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

TEST(Reconnection, NodeRecoversWhenTheMasterIsRestarted)
{
    ASSERT_TRUE(master("start")) << "could not start the test's own master";
    {
        const std::string base = "tcp://127.0.0.1:";
        TestNode node("reconnect-test", base + std::to_string(own_port_base + 2),
                      base + std::to_string(own_port_base));
        node.config().service_timeout_ms = 1000;
        node.config().reconnect_min_ms = 100;
        node.config().reconnect_max_ms = 1000;
        ASSERT_TRUE(node.wait_ready());
        const std::string first_id = ubii_node_client_id(node.get());
        const std::string topic = unique_topic("/reconnect");
        node.collect(topic);
        ASSERT_TRUE(node.poll_until([&] {
            ubii_publish_int32(node.get(), topic.c_str(), 1);
            return !node.received().empty();
        }));

        auto stopping = std::chrono::steady_clock::now();
        ASSERT_TRUE(master("stop", true));
        ASSERT_TRUE(node.poll_until([&] { return ubii_node_state(node.get()) != UBII_STATE_READY; },
                                    std::chrono::seconds(5)));
        double noticed = seconds_since(stopping);
        EXPECT_EQ(ubii_publish_int32(node.get(), topic.c_str(), 2), UBII_ERR_NOT_CONNECTED);
        ASSERT_TRUE(node.poll_until(master_stopped, std::chrono::seconds(10)));
        node.poll_until([] { return false; }, std::chrono::milliseconds(500)); // it keeps retrying

        // The master reports ready about a second after it is started; the node is polled
        // throughout, as an application would.
        auto restarted = std::chrono::steady_clock::now();
        ASSERT_TRUE(master("start", true));
        ASSERT_TRUE(node.wait_ready(std::chrono::seconds(15)));
        double ready = seconds_since(restarted);
        node.received().clear();
        ASSERT_TRUE(node.poll_until(
            [&] {
                ubii_publish_int32(node.get(), topic.c_str(), 3);
                return !node.received().empty();
            },
            std::chrono::seconds(5)));
        double flowing = seconds_since(restarted);
        EXPECT_NE(ubii_node_client_id(node.get()), first_id);
        ubii_stats stats;
        ubii_node_stats(node.get(), &stats);
        EXPECT_GE(stats.reconnects, 1u);
        std::printf("reconnection: loss noticed %.3f s after the stop was sent; ready %.3f s and "
                    "records flowing %.3f s after the master was started again\n",
                    noticed, ready, flowing);
        RecordProperty("noticed_s", std::to_string(noticed));
        RecordProperty("flowing_s", std::to_string(flowing));
    }
    master("stop");
}

} // namespace

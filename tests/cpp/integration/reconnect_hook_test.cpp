// A hook on the connection protocol runs on every (re)connection and holds the node back from
// ready until its asynchronous work is done: here a device registered before the node counts as
// ready, again after the master was killed and restarted. Uses a master of its own (ports 8201...).
#include <cstdlib>

#include <gtest/gtest.h>

#include "cpp_test_support.hpp"

using namespace std::chrono_literals;

namespace
{

const int own_port_base = 8201;

bool master(const std::string &action, bool background = false)
{
    const std::string command = std::string("UBII_CACHE_DIR='") + UBII_TEST_CACHE_DIR + "' " +
                                UBII_MASTER_SCRIPT + " " + action + " " + UBII_HOOK_MASTER_STATE +
                                (action == "start" ? " " + std::to_string(own_port_base) : "") +
                                " >/dev/null" + (background ? " &" : "");
    return std::system(command.c_str()) == 0;
}

TEST(ConnectionHooks, APreparingHookRegistersADeviceBeforeReadyOnEveryConnection)
{
    ASSERT_TRUE(master("start")) << "could not start the test's own master";
    {
        ubii::NodeOptions options;
        options.name = "cpp-hook-test";
        options.service_url = "tcp://127.0.0.1:" + std::to_string(own_port_base);
        options.topic_url = "tcp://127.0.0.1:" + std::to_string(own_port_base + 2);
        options.service_timeout = 1000ms;
        options.reconnect.first_delay = 100ms;
        options.reconnect.max_delay = 1000ms;
        ubii::Node node(options);

        int hook_runs = 0;
        int devices_registered = 0;
        bool ready_before_device = false;
        std::optional<ubii::Hold> hold;
        node.connection().on_enter(ubii::ConnectionState::preparing,
                                   [&](ubii::ConnectionTransition &transition) {
                                       ++hook_runs;
                                       ubii::Device device;
                                       device.set_name("cpp-hook-device");
                                       hold.emplace(transition.hold());
                                       node.master().register_device(device).then(
                                           [&](const ubii::Result<ubii::Device> &registered) {
                                               if (registered.ok())
                                                   ++devices_registered;
                                               hold.reset(); // ready may come now
                                           });
                                   });
        node.connection().on_enter(ubii::ConnectionState::ready, [&](ubii::ConnectionTransition &) {
            ready_before_device |= devices_registered < hook_runs;
        });

        node.connect(10s);
        EXPECT_EQ(hook_runs, 1);
        EXPECT_EQ(devices_registered, 1);
        const std::string first_id = node.client_id();

        ASSERT_TRUE(master("stop"));
        ASSERT_TRUE(node.run_until([&] { return !node.ready(); }, 10s)) << "the loss went unseen";
        ASSERT_TRUE(master("start", true));
        ASSERT_TRUE(node.run_until([&] { return node.ready(); }, 30s))
            << "not ready again after the restart (" << ubii::to_string(node.state()) << ")";
        EXPECT_EQ(hook_runs, 2);
        EXPECT_EQ(devices_registered, 2);
        EXPECT_FALSE(ready_before_device) << "the node counted as ready before its device";
        EXPECT_NE(node.client_id(), first_id);
    }
    EXPECT_TRUE(master("stop"));
}

} // namespace

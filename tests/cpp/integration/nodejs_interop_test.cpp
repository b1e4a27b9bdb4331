// Cross-language: every record member the npm master carries goes from a ubii::Node to the
// official Node.js node, which decodes it with its own schema (protobufjs) and publishes it back;
// the C++ node compares what returns with what it sent. Both directions of encoding, over ZMQ and
// WebSocket on the C++ side (nodejs_echo.js is the other side).
#include <map>

#include <gtest/gtest.h>
#include <unistd.h>

#include "child_process.h"
#include "cpp_test_support.hpp"
#include "test_node.h"

using namespace std::chrono_literals;
using ubii_cpp_test::Transport;

namespace
{

class CppNodeJsInterop : public ::testing::TestWithParam<Transport>
{
};

TEST_P(CppNodeJsInterop, EveryMemberComesBackFromTheNodeJsNodeUnchanged)
{
    ubii::Node node(ubii_cpp_test::options_for("cpp-interop", GetParam()));
    node.connect(10s);
    const std::string run = std::to_string(getpid()) + ubii_cpp_test::name(GetParam());
    ubii_test::ChildProcess peer({"node", UBII_CPP_ECHO_PEER, UBII_NODEJS_CLIENT,
                                  ubii_test::service_url(), ubii_test::topic_zmq_url(), run});
    ASSERT_TRUE(peer.started());
    ASSERT_TRUE(node.run_until(
        [&] {
            for (const auto &line : peer.lines()) {
                if (line.rfind("PEER ready", 0) == 0)
                    return true;
                if (line.rfind("PEER error", 0) == 0)
                    ADD_FAILURE() << line;
            }
            return false;
        },
        20s))
        << "the Node.js node did not start";

    // Members 3-31: what the npm 0.4.0 master carries (see records_test.cpp), TouchEvent with
    // only type and position.
    std::map<std::string, ubii::Value> sent;
    int seed = 100;
    for (ubii::RecordType type : ubii::detail::record_types) {
        if (type != ubii::RecordType::NONE && static_cast<int>(type) <= 31)
            sent.emplace(std::string(ubii::record_type_name(type)),
                         ubii_cpp_test::value_for(type, ++seed));
    }
    ubii::TouchEvent touch;
    touch.set_type(ubii::TouchEvent::TOUCH_MOVE);
    *touch.mutable_position() = ubii::vector2(0.5, 0.75);
    sent["touch_event"] = touch;

    const std::string out = "/cpp-echo/" + run + "/out/";
    const std::string back = "/cpp-echo/" + run + "/back/";
    std::map<std::string, ubii::Record> returned;
    auto subscription = node.subscribe_regex("^" + back, [&](const ubii::Record &record) {
        returned.emplace(std::string(record.topic().substr(back.size())), record);
    });
    const bool all_returned = node.run_until(
        [&] {
            for (const auto &[member, value] : sent) {
                if (returned.count(member) == 0)
                    node.publish(out + member, value);
            }
            node.poll(100ms);
            return returned.size() >= sent.size();
        },
        30s);
    EXPECT_TRUE(all_returned) << returned.size() << " of " << sent.size() << " came back";
    for (const auto &[member, value] : sent) {
        auto found = returned.find(member);
        if (found == returned.end()) {
            ADD_FAILURE() << member << " never came back";
            continue;
        }
        std::string difference;
        EXPECT_TRUE(ubii_cpp_test::same_value(value, found->second.value(), &difference))
            << member << ": " << difference;
    }
    EXPECT_EQ(peer.stop(SIGTERM, 5s), 0);
}

INSTANTIATE_TEST_SUITE_P(Transports, CppNodeJsInterop,
                         ::testing::Values(Transport::zmq, Transport::websocket),
                         [](const auto &param) { return ubii_cpp_test::name(param.param); });

} // namespace

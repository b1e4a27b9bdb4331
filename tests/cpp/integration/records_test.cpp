// Every TopicDataRecord member goes from a ubii::Node through the real npm master to a ubii::Node,
// over ZMQ and WebSocket: a value for each member is built from the schema by reflection (every
// field set), published as a ubii::Value and compared with what the subscription received.
#include <map>
#include <set>

#include <gtest/gtest.h>

#include "cpp_test_support.hpp"
#include "test_node.h"

using namespace std::chrono_literals;
using ubii_cpp_test::Transport;

namespace
{

class RecordsThroughTheMaster : public ::testing::TestWithParam<Transport>
{
};

// What the npm 0.4.0 master can carry (it decodes and re-encodes every record with its own,
// older schema): members 3-31. Session (32) has other field numbers there; 33-44 (and client_id)
// do not exist there.
bool carried_by_the_npm_master(ubii::RecordType type)
{
    const int number = static_cast<int>(type);
    return number <= 31;
}

// Publishes a probe on base/probe until the subscription delivers it: the master has it then.
void wait_until_subscribed(ubii::Node &node, const ubii::Subscription &, const std::string &base)
{
    bool seen = false;
    auto probe = node.subscribe(base + "/probe", [&](const ubii::Record &) { seen = true; });
    ASSERT_TRUE(node.run_until(
        [&] {
            node.publish(base + "/probe", true);
            node.poll(50ms);
            return seen;
        },
        10s));
}

TEST_P(RecordsThroughTheMaster, EveryMemberArrivesAsPublished)
{
    ubii::Node node(ubii_cpp_test::options_for("cpp-records", GetParam()));
    node.connect(10s);
    const std::string base = ubii_test::unique_topic("/cpp-records");
    std::map<ubii::RecordType, ubii::Record> received;
    auto subscription = node.subscribe_regex("^" + base + "/", [&](const ubii::Record &record) {
        if (record.topic() != base + "/probe")
            received.emplace(record.type(), record); // an owning copy of the lent record
    });

    std::map<ubii::RecordType, ubii::Value> sent;
    int seed = 0;
    for (ubii::RecordType type : ubii::detail::record_types) {
        if (type != ubii::RecordType::NONE)
            sent.emplace(type, ubii_cpp_test::value_for(type, ++seed));
    }
    // The npm master's TouchEvent has only type and position; it refuses to re-encode more (a
    // TopicData error: "TopicData message publishing failed").
    ubii::TouchEvent touch;
    touch.set_type(ubii::TouchEvent::TOUCH_MOVE);
    *touch.mutable_position() = ubii::vector2(0.25, -0.5);
    sent[ubii::RecordType::TOUCH_EVENT] = touch;
    auto topic_of = [&](ubii::RecordType type) {
        return base + "/" + std::string(ubii::record_type_name(type));
    };
    wait_until_subscribed(node, subscription, base);
    for (const auto &[type, value] : sent) {
        if (!carried_by_the_npm_master(type))
            node.publish(topic_of(type), value);
    }
    // Until every member the master carries has arrived once.
    const bool all_arrived = node.run_until(
        [&] {
            for (const auto &[type, value] : sent) {
                if (carried_by_the_npm_master(type) && received.count(type) == 0)
                    node.publish(topic_of(type), value);
            }
            node.poll(50ms);
            for (const auto &entry : sent) {
                if (carried_by_the_npm_master(entry.first) && received.count(entry.first) == 0)
                    return false;
            }
            return true;
        },
        15s);
    node.run_for(300ms); // stragglers of the members the master does not carry

    std::set<ubii::RecordType> missing;
    int compared = 0;
    for (const auto &[type, value] : sent) {
        const std::string member(ubii::record_type_name(type));
        auto arrived = received.find(type);
        if (!carried_by_the_npm_master(type)) {
            // Those the npm master does not know it forwards, if at all, as something else.
            if (arrived != received.end()) {
                EXPECT_FALSE(ubii_cpp_test::same_value(value, arrived->second.value()))
                    << member << " went through the npm master unchanged";
            }
            continue;
        }
        if (arrived == received.end()) {
            missing.insert(type);
            continue;
        }
        EXPECT_EQ(arrived->second.topic(), base + "/" + member);
        std::string difference;
        ++compared;
        EXPECT_TRUE(ubii_cpp_test::same_value(value, arrived->second.value(), &difference))
            << member << ": " << difference;
    }
    EXPECT_EQ(compared, 29); // members 3-31
    EXPECT_TRUE(all_arrived && missing.empty())
        << missing.size() << " members never arrived, e.g. "
        << (missing.empty() ? "" : std::string(ubii::record_type_name(*missing.begin())));
}

INSTANTIATE_TEST_SUITE_P(Transports, RecordsThroughTheMaster,
                         ::testing::Values(Transport::zmq, Transport::websocket),
                         [](const auto &param) { return ubii_cpp_test::name(param.param); });

// Images arrive as a view of the received message while lent, and as an owning copy on demand.
TEST(ImagesThroughTheMaster, AViewWhileLentAndACopyThatOutlivesTheCallback)
{
    ubii::Node node(ubii_cpp_test::options_for("cpp-images"));
    node.connect(10s);
    const std::string topic = ubii_test::unique_topic("/cpp-image");
    ubii::Image2D image;
    image.set_width(640);
    image.set_height(480);
    image.set_data_format(ubii::Image2D::RGB8);
    std::string pixels(640 * 480 * 3, '\0');
    for (std::size_t i = 0; i < pixels.size(); ++i)
        pixels[i] = static_cast<char>(i * 7);
    image.set_data(pixels);

    std::optional<ubii::Image2D> kept;
    bool view_was_lent = false;
    auto subscription = node.subscribe<ubii::ImageView>(
        topic, [&](const ubii::ImageView &view, const ubii::RecordInfo &info) {
            EXPECT_EQ(info.topic, topic);
            view_was_lent = view.data != nullptr && view.size == pixels.size();
            kept = view.to_image();
        });
    ASSERT_TRUE(node.run_until(
        [&] {
            node.publish(topic, image);
            node.poll(50ms);
            return kept.has_value();
        },
        10s));
    EXPECT_TRUE(view_was_lent);
    EXPECT_EQ(kept->width(), 640);
    EXPECT_EQ(kept->height(), 480);
    EXPECT_EQ(kept->data_format(), ubii::Image2D::RGB8);
    EXPECT_EQ(kept->data(), pixels);
}

} // namespace

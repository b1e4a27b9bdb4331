// Cross-language: the C node and the official Node.js client node exchange the same table of
// typed values through the real master, in both directions (nodejs_peer.js holds the JS side).
#include <cmath>
#include <cstring>
#include <functional>
#include <map>
#include <set>

#include <gtest/gtest.h>
#include <unistd.h>

#include "child_process.h"
#include "test_node.h"
#include "ubii/dataStructure/pose3d.pb.h"
#include "ubii/dataStructure/quaternion.pb.h"
#include "ubii/dataStructure/vector3.pb.h"

using ubii_test::ChildProcess;
using ubii_test::TestNode;

namespace
{

struct Entry {
    std::function<ubii_status(ubii_node *, const char *)> publish;
    std::function<void(const ubii_record &)> check;
};

ubii_dataStructure_Vector3 vector3(double x, double y, double z)
{
    ubii_dataStructure_Vector3 v = ubii_dataStructure_Vector3_init_zero;
    v.x = x;
    v.y = y;
    v.z = z;
    return v;
}

// The same values as the table in nodejs_peer.js.
std::map<std::string, Entry> table()
{
    static const double doubles[] = {1.5, -2.25, 1e-300};
    static const int32_t ints[] = {1, -2, 2147483647};
    static const char *const strings[] = {"eins", "zwei", ""};
    static const uint8_t pixels[] = {255, 0, 0, 0, 255, 0};
    static const std::string text = "Grüße aus C und JS 🐋";
    static const ubii_dataStructure_Vector3 v3 = vector3(1.5, -2.5, 3.25);
    static const ubii_dataStructure_Quaternion q = {0, 0, 0.7071067811865476, 0.7071067811865476};
    static ubii_dataStructure_Pose3D pose = [] {
        ubii_dataStructure_Pose3D p = ubii_dataStructure_Pose3D_init_zero;
        p.has_position = true;
        p.position = vector3(1, 2, 3);
        p.which_orientation = ubii_dataStructure_Pose3D_euler_tag;
        p.orientation.euler = vector3(0.5, 0, -0.5);
        return p;
    }();
    std::map<std::string, Entry> t;
    t["double"] = {[](ubii_node *n, const char *topic) {
                       return ubii_publish_double(n, topic, 3.141592653589793);
                   },
                   [](const ubii_record &r) {
                       double v;
                       ASSERT_EQ(ubii_record_double(&r, &v), UBII_OK);
                       EXPECT_EQ(v, 3.141592653589793);
                   }};
    t["float"] = {
        [](ubii_node *n, const char *topic) { return ubii_publish_float(n, topic, 0.15625f); },
        [](const ubii_record &r) {
            float v;
            ASSERT_EQ(ubii_record_float(&r, &v), UBII_OK);
            EXPECT_EQ(v, 0.15625f);
        }};
    t["int32"] = {
        [](ubii_node *n, const char *topic) { return ubii_publish_int32(n, topic, -123456); },
        [](const ubii_record &r) {
            int32_t v;
            ASSERT_EQ(ubii_record_int32(&r, &v), UBII_OK);
            EXPECT_EQ(v, -123456);
        }};
    t["bool"] = {[](ubii_node *n, const char *topic) { return ubii_publish_bool(n, topic, true); },
                 [](const ubii_record &r) {
                     bool v = false;
                     ASSERT_EQ(ubii_record_bool(&r, &v), UBII_OK);
                     EXPECT_TRUE(v);
                 }};
    t["string"] = {[](ubii_node *n, const char *topic) {
                       return ubii_publish_string(n, topic, text.data(), text.size());
                   },
                   [](const ubii_record &r) {
                       const char *v;
                       size_t length;
                       ASSERT_EQ(ubii_record_string(&r, &v, &length), UBII_OK);
                       EXPECT_EQ(std::string(v, length), text);
                   }};
    auto message_entry = [](ubii_record_type type, const pb_msgdesc_t *fields, const void *value,
                            size_t size) {
        return Entry{[=](ubii_node *n, const char *topic) {
                         return ubii_publish_message(n, topic, type, fields, value);
                     },
                     [=](const ubii_record &r) {
                         std::vector<uint8_t> decoded(size, 0);
                         ASSERT_EQ(ubii_record_decode(&r, type, fields, decoded.data()), UBII_OK);
                         EXPECT_EQ(std::memcmp(decoded.data(), value, size), 0);
                     }};
    };
    t["vector3"] =
        message_entry(UBII_RECORD_VECTOR3, ubii_dataStructure_Vector3_fields, &v3, sizeof v3);
    t["quaternion"] =
        message_entry(UBII_RECORD_QUATERNION, ubii_dataStructure_Quaternion_fields, &q, sizeof q);
    t["pose3D"] =
        message_entry(UBII_RECORD_POSE3D, ubii_dataStructure_Pose3D_fields, &pose, sizeof pose);
    t["doubleList"] = {
        [](ubii_node *n, const char *topic) { return ubii_publish_doubles(n, topic, doubles, 3); },
        [](const ubii_record &r) {
            ubii_list_iter it;
            ASSERT_EQ(ubii_record_list(&r, UBII_RECORD_DOUBLE_LIST, &it), UBII_OK);
            std::vector<double> got;
            double v;
            while (ubii_list_next_double(&it, &v)) {
                got.push_back(v);
            }
            EXPECT_EQ(got, std::vector<double>(doubles, doubles + 3));
        }};
    t["int32List"] = {
        [](ubii_node *n, const char *topic) { return ubii_publish_int32s(n, topic, ints, 3); },
        [](const ubii_record &r) {
            ubii_list_iter it;
            ASSERT_EQ(ubii_record_list(&r, UBII_RECORD_INT32_LIST, &it), UBII_OK);
            std::vector<int32_t> got;
            int32_t v;
            while (ubii_list_next_int32(&it, &v)) {
                got.push_back(v);
            }
            EXPECT_EQ(got, std::vector<int32_t>(ints, ints + 3));
        }};
    t["stringList"] = {
        [](ubii_node *n, const char *topic) { return ubii_publish_strings(n, topic, strings, 3); },
        [](const ubii_record &r) {
            ubii_list_iter it;
            ASSERT_EQ(ubii_record_list(&r, UBII_RECORD_STRING_LIST, &it), UBII_OK);
            std::vector<std::string> got;
            const uint8_t *bytes;
            size_t size;
            while (ubii_list_next_bytes(&it, &bytes, &size)) {
                got.emplace_back(reinterpret_cast<const char *>(bytes), size);
            }
            EXPECT_EQ(got, (std::vector<std::string>{"eins", "zwei", ""}));
        }};
    t["image2D"] = {[](ubii_node *n, const char *topic) {
                        return ubii_publish_image(n, topic, 2, 1,
                                                  ubii_dataStructure_Image2D_DataFormat_RGB8,
                                                  pixels, sizeof pixels);
                    },
                    [](const ubii_record &r) {
                        ubii_image_view image;
                        ASSERT_EQ(ubii_record_image(&r, &image), UBII_OK);
                        EXPECT_EQ(image.width, 2);
                        EXPECT_EQ(image.height, 1);
                        EXPECT_EQ(image.format, ubii_dataStructure_Image2D_DataFormat_RGB8);
                        ASSERT_EQ(image.size, sizeof pixels);
                        EXPECT_EQ(std::memcmp(image.data, pixels, sizeof pixels), 0);
                    }};
    return t;
}

struct Collected {
    std::map<std::string, Entry> *table;
    std::set<std::string> checked;
    static void on_record(ubii_node *, const ubii_record *record, void *user)
    {
        auto *self = static_cast<Collected *>(user);
        std::string topic = record->topic;
        std::string type = topic.substr(topic.rfind('/') + 1);
        auto entry = self->table->find(type);
        ASSERT_NE(entry, self->table->end()) << topic;
        if (self->checked.insert(type).second) {
            entry->second.check(*record);
        }
    }
};

class NodeJsInterop : public ::testing::TestWithParam<std::string>
{
};

TEST_P(NodeJsInterop, ValuesCrossBetweenCAndTheNodeJsNodeBothWays)
{
    const std::string topic_url =
        GetParam() == "websocket" ? ubii_test::topic_ws_url() : ubii_test::topic_zmq_url();
    TestNode node("c-interop-" + GetParam(), topic_url);
    ASSERT_TRUE(node.wait_ready());
    const std::string run = std::to_string(getpid()) + GetParam();
    ChildProcess peer({"node", UBII_INTEROP_PEER, UBII_NODEJS_CLIENT, ubii_test::service_url(),
                       ubii_test::topic_zmq_url(), run});
    ASSERT_TRUE(peer.started());
    auto has_line = [&](const std::string &prefix) {
        for (const auto &line : peer.lines()) {
            if (line.rfind(prefix, 0) == 0) {
                return true;
            }
        }
        return false;
    };
    ASSERT_TRUE(node.poll_until([&] { return has_line("PEER ready"); }, std::chrono::seconds(20)))
        << "the Node.js node did not start";

    // Node.js -> C
    auto entries = table();
    Collected collected{&entries, {}};
    ASSERT_EQ(ubii_subscribe_regex(node.get(), ("^/interop/" + run + "/js/").c_str(),
                                   Collected::on_record, &collected, nullptr),
              UBII_OK);
    ASSERT_TRUE(node.poll_until([&] { return collected.checked.size() == entries.size(); },
                                std::chrono::seconds(15)))
        << "received " << collected.checked.size() << " of " << entries.size() << " types";

    // C -> Node.js: publish the table until the peer has judged every type.
    std::set<std::string> judged;
    ASSERT_TRUE(node.poll_until(
        [&] {
            for (auto &[type, entry] : entries) {
                entry.publish(node.get(), ("/interop/" + run + "/c/" + type).c_str());
            }
            for (const auto &line : peer.lines()) {
                if (line.rfind("PEER ok ", 0) == 0) {
                    judged.insert(line.substr(8));
                } else if (line.rfind("PEER mismatch ", 0) == 0 ||
                           line.rfind("PEER unknown", 0) == 0) {
                    ADD_FAILURE() << line;
                    judged.insert(line);
                }
            }
            usleep(50000);
            return judged.size() >= entries.size();
        },
        std::chrono::seconds(20)))
        << "the Node.js node confirmed " << judged.size() << " of " << entries.size() << " types";
}

INSTANTIATE_TEST_SUITE_P(CTopicTransport, NodeJsInterop, ::testing::Values("zmq", "websocket"));

} // namespace

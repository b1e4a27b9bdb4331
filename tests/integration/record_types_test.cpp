// Every record member the npm 0.4.0 master knows (field numbers 3-31) goes through the master and
// arrives bit-exactly: the value bytes received equal the bytes a reference encoding produces, and
// the accessors return the values published. (Session, 32, changed its own field numbers since
// that master's schema; members 33-44 do not exist there.)
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <tuple>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "pb_test_callbacks.h"
#include "test_node.h"
#include "ubii/dataStructure/color.pb.h"
#include "ubii/dataStructure/keyEvent.pb.h"
#include "ubii/dataStructure/matrix3x2.pb.h"
#include "ubii/dataStructure/matrix4x4.pb.h"
#include "ubii/dataStructure/mouseEvent.pb.h"
#include "ubii/dataStructure/myoEvent.pb.h"
#include "ubii/dataStructure/object2d.pb.h"
#include "ubii/dataStructure/object3d.pb.h"
#include "ubii/dataStructure/pose2d.pb.h"
#include "ubii/dataStructure/pose3d.pb.h"
#include "ubii/dataStructure/touchEvent.pb.h"
#include "ubii/dataStructure/vector4.pb.h"

using ubii_test::Received;
using ubii_test::TestNode;
using ubii_test::unique_topic;

namespace
{

// Reference encodings, written out by hand from the protobuf wire format.
std::vector<uint8_t> tag(uint32_t number, uint8_t wire_type)
{
    return {static_cast<uint8_t>(number << 3 | wire_type)};
}

void append_varint(std::vector<uint8_t> &out, uint64_t value)
{
    while (value >= 0x80) {
        out.push_back(static_cast<uint8_t>(value | 0x80));
        value >>= 7;
    }
    out.push_back(static_cast<uint8_t>(value));
}

template <typename T> void append_raw(std::vector<uint8_t> &out, T value)
{
    uint8_t bytes[sizeof value];
    std::memcpy(bytes, &value, sizeof value);
    out.insert(out.end(), bytes, bytes + sizeof value);
}

std::vector<uint8_t> packed(const std::vector<uint8_t> &payload)
{
    std::vector<uint8_t> out = tag(1, 2);
    append_varint(out, payload.size());
    out.insert(out.end(), payload.begin(), payload.end());
    return out;
}

template <typename Message>
std::vector<uint8_t> encode(const pb_msgdesc_t *fields, const Message &message)
{
    std::vector<uint8_t> out(4096);
    pb_ostream_t stream = pb_ostream_from_buffer(out.data(), out.size());
    EXPECT_TRUE(pb_encode(&stream, fields, &message)) << PB_GET_ERROR(&stream);
    out.resize(stream.bytes_written);
    return out;
}

// One member type: how to publish it, and what must arrive.
struct Case {
    std::string name;
    ubii_record_type type;
    std::function<ubii_status(ubii_node *, const char *)> publish;
    std::vector<uint8_t> expected_value; // for length-delimited members
    uint64_t expected_scalar;            // for double, float, int32, bool
    std::function<void(const ubii_record &)> check;
};

ubii_dataStructure_Vector2 vector2(double x, double y)
{
    ubii_dataStructure_Vector2 v = ubii_dataStructure_Vector2_init_zero;
    v.x = x;
    v.y = y;
    return v;
}

ubii_dataStructure_Vector3 vector3(double x, double y, double z)
{
    ubii_dataStructure_Vector3 v = ubii_dataStructure_Vector3_init_zero;
    v.x = x;
    v.y = y;
    v.z = z;
    return v;
}

ubii_dataStructure_Quaternion quaternion()
{
    ubii_dataStructure_Quaternion q = ubii_dataStructure_Quaternion_init_zero;
    q.x = 0.1;
    q.y = -0.2;
    q.z = 0.3;
    q.w = 0.9273618495495704;
    return q;
}

template <typename Message>
Case message_case(const std::string &name, ubii_record_type type, const pb_msgdesc_t *fields,
                  const Message &message)
{
    auto bytes = encode(fields, message);
    return Case{name,
                type,
                [=](ubii_node *node, const char *topic) {
                    return ubii_publish_message(node, topic, type, fields, &message);
                },
                bytes,
                0,
                [=](const ubii_record &record) {
                    Message decoded;
                    std::memset(&decoded, 0, sizeof decoded);
                    ASSERT_EQ(ubii_record_decode(&record, type, fields, &decoded), UBII_OK);
                    EXPECT_EQ(encode(fields, decoded), bytes);
                }};
}

// Messages whose strings are callbacks are encoded with them bound.
ubii_test::StringValues object_id{{"text: ÄÖÜ"}};
ubii_test::StringValues object_json{{"{\"confidence\":97.5}"}};

std::vector<Case> all_cases()
{
    std::vector<Case> cases;
    const double d = -1234.5678e-9;
    uint64_t d_bits;
    std::memcpy(&d_bits, &d, sizeof d);
    cases.push_back({"double",
                     UBII_RECORD_DOUBLE,
                     [=](ubii_node *n, const char *t) { return ubii_publish_double(n, t, d); },
                     {},
                     d_bits,
                     [=](const ubii_record &r) {
                         double v;
                         ASSERT_EQ(ubii_record_double(&r, &v), UBII_OK);
                         EXPECT_EQ(v, d);
                     }});
    const double denormal = std::numeric_limits<double>::denorm_min();
    uint64_t denormal_bits;
    std::memcpy(&denormal_bits, &denormal, sizeof denormal);
    cases.push_back(
        {"double_denormal",
         UBII_RECORD_DOUBLE,
         [=](ubii_node *n, const char *t) { return ubii_publish_double(n, t, denormal); },
         {},
         denormal_bits,
         nullptr});
    const float f = -3.4028235e38f;
    uint32_t f_bits;
    std::memcpy(&f_bits, &f, sizeof f);
    cases.push_back({"float",
                     UBII_RECORD_FLOAT,
                     [=](ubii_node *n, const char *t) { return ubii_publish_float(n, t, f); },
                     {},
                     f_bits,
                     [=](const ubii_record &r) {
                         float v;
                         ASSERT_EQ(ubii_record_float(&r, &v), UBII_OK);
                         EXPECT_EQ(v, f);
                     }});
    cases.push_back(
        {"int32_negative",
         UBII_RECORD_INT32,
         [](ubii_node *n, const char *t) { return ubii_publish_int32(n, t, INT32_MIN); },
         {},
         static_cast<uint64_t>(static_cast<int64_t>(INT32_MIN)),
         [](const ubii_record &r) {
             int32_t v;
             ASSERT_EQ(ubii_record_int32(&r, &v), UBII_OK);
             EXPECT_EQ(v, INT32_MIN);
         }});
    cases.push_back({"bool",
                     UBII_RECORD_BOOL,
                     [](ubii_node *n, const char *t) { return ubii_publish_bool(n, t, true); },
                     {},
                     1,
                     [](const ubii_record &r) {
                         bool v = false;
                         ASSERT_EQ(ubii_record_bool(&r, &v), UBII_OK);
                         EXPECT_TRUE(v);
                     }});
    const std::string text = "Grüße, 🐋 \"quoted\" \\ / ";
    cases.push_back({"string", UBII_RECORD_STRING,
                     [=](ubii_node *n, const char *t) {
                         return ubii_publish_string(n, t, text.data(), text.size());
                     },
                     std::vector<uint8_t>(text.begin(), text.end()), 0,
                     [=](const ubii_record &r) {
                         const char *v;
                         size_t length;
                         ASSERT_EQ(ubii_record_string(&r, &v, &length), UBII_OK);
                         EXPECT_EQ(std::string(v, length), text);
                     }});

    cases.push_back(message_case("vector2", UBII_RECORD_VECTOR2, ubii_dataStructure_Vector2_fields,
                                 vector2(1.5, -2.25)));
    cases.push_back(message_case("vector3", UBII_RECORD_VECTOR3, ubii_dataStructure_Vector3_fields,
                                 vector3(1e300, -1e-300, 3.0)));
    ubii_dataStructure_Vector4 v4 = {1, 2, 3, 4};
    cases.push_back(
        message_case("vector4", UBII_RECORD_VECTOR4, ubii_dataStructure_Vector4_fields, v4));
    cases.push_back(message_case("quaternion", UBII_RECORD_QUATERNION,
                                 ubii_dataStructure_Quaternion_fields, quaternion()));
    ubii_dataStructure_Matrix3x2 m32 = {1, 2, 3, 4, 5, 6};
    cases.push_back(
        message_case("matrix3x2", UBII_RECORD_MATRIX3X2, ubii_dataStructure_Matrix3x2_fields, m32));
    ubii_dataStructure_Matrix4x4 m44;
    double *cells = &m44.m00;
    for (int i = 0; i < 16; ++i) {
        cells[i] = (i + 1) * 0.5 - 4;
    }
    m44.m11 = 1.0; // the value 0 would be left out, as it is in every encoder
    cases.push_back(
        message_case("matrix4x4", UBII_RECORD_MATRIX4X4, ubii_dataStructure_Matrix4x4_fields, m44));
    ubii_dataStructure_Color color = {0.25, 0.5, 0.75, 1.0};
    cases.push_back(
        message_case("color", UBII_RECORD_COLOR, ubii_dataStructure_Color_fields, color));
    // The npm 0.4.0 master's TouchEvent has only type (0 or 1) and position; it cannot re-encode
    // more, and drops such a record. Those two fields are what both dialects carry.
    ubii_dataStructure_TouchEvent touch = ubii_dataStructure_TouchEvent_init_zero;
    touch.type = ubii_dataStructure_TouchEvent_TouchEventType_TOUCH_MOVE;
    touch.has_position = true;
    touch.position = vector2(0.5, 0.25);
    cases.push_back(message_case("touch_event", UBII_RECORD_TOUCH_EVENT,
                                 ubii_dataStructure_TouchEvent_fields, touch));
    ubii_dataStructure_KeyEvent key = ubii_dataStructure_KeyEvent_init_zero;
    key.type = ubii_dataStructure_ButtonEventType_DOWN;
    std::strcpy(key.key, "Escape");
    cases.push_back(
        message_case("key_event", UBII_RECORD_KEY_EVENT, ubii_dataStructure_KeyEvent_fields, key));
    ubii_dataStructure_MouseEvent mouse = {ubii_dataStructure_ButtonEventType_DOWN, 3};
    cases.push_back(message_case("mouse_event", UBII_RECORD_MOUSE_EVENT,
                                 ubii_dataStructure_MouseEvent_fields, mouse));
    ubii_dataStructure_MyoEvent myo = ubii_dataStructure_MyoEvent_init_zero;
    myo.has_emg = true;
    double *emg = &myo.emg.v0;
    for (int i = 0; i < 8; ++i) {
        emg[i] = i - 3.5;
    }
    myo.has_orientation = true;
    myo.orientation = quaternion();
    myo.has_gyroscope = true;
    myo.gyroscope = vector3(1, 2, 3);
    myo.has_accelerometer = true;
    myo.accelerometer = vector3(-1, -2, -3);
    myo.gesture = ubii_dataStructure_HandGestureType_DOUBLE_TAP;
    cases.push_back(
        message_case("myo_event", UBII_RECORD_MYO_EVENT, ubii_dataStructure_MyoEvent_fields, myo));
    ubii_dataStructure_Pose2D pose2 = ubii_dataStructure_Pose2D_init_zero;
    pose2.has_position = true;
    pose2.position = vector2(4, 5);
    pose2.which_orientation = ubii_dataStructure_Pose2D_angle_tag;
    pose2.orientation.angle = 1.25f;
    cases.push_back(
        message_case("pose2D", UBII_RECORD_POSE2D, ubii_dataStructure_Pose2D_fields, pose2));
    ubii_dataStructure_Pose3D pose3 = ubii_dataStructure_Pose3D_init_zero;
    pose3.has_position = true;
    pose3.position = vector3(1, 2, 3);
    pose3.which_orientation = ubii_dataStructure_Pose3D_quaternion_tag;
    pose3.orientation.quaternion = quaternion();
    cases.push_back(
        message_case("pose3D", UBII_RECORD_POSE3D, ubii_dataStructure_Pose3D_fields, pose3));

    ubii_dataStructure_Object2D object2 = ubii_dataStructure_Object2D_init_zero;
    ubii_test::encode_from(object2.id, object_id);
    object2.has_pose = true;
    object2.pose = pose2;
    object2.has_size = true;
    object2.size = vector2(10, 20);
    ubii_test::encode_from(object2.user_data_json, object_json);
    auto object2_bytes = encode(ubii_dataStructure_Object2D_fields, object2);
    cases.push_back({"object2D", UBII_RECORD_OBJECT2D,
                     [=](ubii_node *n, const char *t) {
                         return ubii_publish_message(n, t, UBII_RECORD_OBJECT2D,
                                                     ubii_dataStructure_Object2D_fields, &object2);
                     },
                     object2_bytes, 0, nullptr});
    ubii_dataStructure_Object3D object3 = ubii_dataStructure_Object3D_init_zero;
    ubii_test::encode_from(object3.id, object_id);
    object3.has_pose = true;
    object3.pose = pose3;
    object3.has_size = true;
    object3.size = vector3(1, 1, 1);
    auto object3_bytes = encode(ubii_dataStructure_Object3D_fields, object3);
    cases.push_back({"object3D", UBII_RECORD_OBJECT3D,
                     [=](ubii_node *n, const char *t) {
                         return ubii_publish_message(n, t, UBII_RECORD_OBJECT3D,
                                                     ubii_dataStructure_Object3D_fields, &object3);
                     },
                     object3_bytes, 0, nullptr});
    // Lists of messages: the elements are the messages' bytes, each under field 1.
    auto list_of = [](const std::vector<std::vector<uint8_t>> &elements) {
        std::vector<uint8_t> out;
        for (const auto &element : elements) {
            auto t = tag(1, 2);
            out.insert(out.end(), t.begin(), t.end());
            append_varint(out, element.size());
            out.insert(out.end(), element.begin(), element.end());
        }
        return out;
    };
    auto object2_list = list_of({object2_bytes, object2_bytes});
    auto object3_list = list_of({object3_bytes});
    ubii_test::StringValues object2_elements{
        {std::string(object2_bytes.begin(), object2_bytes.end()),
         std::string(object2_bytes.begin(), object2_bytes.end())}};
    ubii_test::StringValues object3_elements{
        {std::string(object3_bytes.begin(), object3_bytes.end())}};
    cases.push_back({"object2D_list", UBII_RECORD_OBJECT2D_LIST,
                     [=](ubii_node *n, const char *t) {
                         ubii_dataStructure_Object2DList list =
                             ubii_dataStructure_Object2DList_init_zero;
                         ubii_test::encode_from(list.elements, object2_elements);
                         return ubii_publish_message(n, t, UBII_RECORD_OBJECT2D_LIST,
                                                     ubii_dataStructure_Object2DList_fields, &list);
                     },
                     object2_list, 0, nullptr});
    cases.push_back({"object3D_list", UBII_RECORD_OBJECT3D_LIST,
                     [=](ubii_node *n, const char *t) {
                         ubii_dataStructure_Object3DList list =
                             ubii_dataStructure_Object3DList_init_zero;
                         ubii_test::encode_from(list.elements, object3_elements);
                         return ubii_publish_message(n, t, UBII_RECORD_OBJECT3D_LIST,
                                                     ubii_dataStructure_Object3DList_fields, &list);
                     },
                     object3_list, 0, nullptr});

    // Numeric lists: packed.
    const std::vector<int32_t> ints = {0, -1, 2147483647, INT32_MIN, 300};
    std::vector<uint8_t> int_payload;
    for (int32_t v : ints) {
        append_varint(int_payload, static_cast<uint64_t>(static_cast<int64_t>(v)));
    }
    cases.push_back({"int32_list", UBII_RECORD_INT32_LIST,
                     [=](ubii_node *n, const char *t) {
                         return ubii_publish_int32s(n, t, ints.data(), ints.size());
                     },
                     packed(int_payload), 0,
                     [=](const ubii_record &r) {
                         ubii_list_iter it;
                         ASSERT_EQ(ubii_record_list(&r, UBII_RECORD_INT32_LIST, &it), UBII_OK);
                         std::vector<int32_t> got;
                         int32_t v;
                         while (ubii_list_next_int32(&it, &v)) {
                             got.push_back(v);
                         }
                         EXPECT_FALSE(it.malformed);
                         EXPECT_EQ(got, ints);
                     }});
    const std::vector<float> floats = {0.0f, -0.0f, 1.5f, std::numeric_limits<float>::infinity()};
    std::vector<uint8_t> float_payload;
    for (float v : floats) {
        append_raw(float_payload, v);
    }
    cases.push_back({"float_list", UBII_RECORD_FLOAT_LIST,
                     [=](ubii_node *n, const char *t) {
                         return ubii_publish_floats(n, t, floats.data(), floats.size());
                     },
                     packed(float_payload), 0, nullptr});
    const std::vector<double> doubles = {3.141592653589793, -2.718281828459045, 1e-310, 0.0};
    std::vector<uint8_t> double_payload;
    for (double v : doubles) {
        append_raw(double_payload, v);
    }
    cases.push_back({"double_list", UBII_RECORD_DOUBLE_LIST,
                     [=](ubii_node *n, const char *t) {
                         return ubii_publish_doubles(n, t, doubles.data(), doubles.size());
                     },
                     packed(double_payload), 0,
                     [=](const ubii_record &r) {
                         ubii_list_iter it;
                         ASSERT_EQ(ubii_record_list(&r, UBII_RECORD_DOUBLE_LIST, &it), UBII_OK);
                         std::vector<double> got;
                         double v;
                         while (ubii_list_next_double(&it, &v)) {
                             got.push_back(v);
                         }
                         EXPECT_EQ(got, doubles);
                     }});
    const char *strings[] = {"one", "", "drei 3", "🐋"};
    std::vector<uint8_t> string_list;
    for (const char *s : strings) {
        auto t = tag(1, 2);
        string_list.insert(string_list.end(), t.begin(), t.end());
        append_varint(string_list, std::strlen(s));
        string_list.insert(string_list.end(), s, s + std::strlen(s));
    }
    cases.push_back(
        {"string_list", UBII_RECORD_STRING_LIST,
         [=](ubii_node *n, const char *t) { return ubii_publish_strings(n, t, strings, 4); },
         string_list, 0, nullptr});
    const bool bools[] = {true, false, true};
    cases.push_back(
        {"bool_list", UBII_RECORD_BOOL_LIST,
         [=](ubii_node *n, const char *t) { return ubii_publish_bools(n, t, bools, 3); },
         packed({1, 0, 1}), 0, nullptr});

    // Image: width, height, format, pixels.
    std::vector<uint8_t> pixels(64 * 48 * 3);
    for (size_t i = 0; i < pixels.size(); ++i) {
        pixels[i] = static_cast<uint8_t>(i * 7);
    }
    std::vector<uint8_t> image;
    append_varint(image, 1 << 3);
    append_varint(image, 64);
    append_varint(image, 2 << 3);
    append_varint(image, 48);
    append_varint(image, 3 << 3);
    append_varint(image, ubii_dataStructure_Image2D_DataFormat_RGB8);
    append_varint(image, 4 << 3 | 2);
    append_varint(image, pixels.size());
    image.insert(image.end(), pixels.begin(), pixels.end());
    cases.push_back({"image2D", UBII_RECORD_IMAGE2D,
                     [=](ubii_node *n, const char *t) {
                         return ubii_publish_image(n, t, 64, 48,
                                                   ubii_dataStructure_Image2D_DataFormat_RGB8,
                                                   pixels.data(), pixels.size());
                     },
                     image, 0,
                     [=](const ubii_record &r) {
                         ubii_image_view view;
                         ASSERT_EQ(ubii_record_image(&r, &view), UBII_OK);
                         EXPECT_EQ(view.width, 64);
                         EXPECT_EQ(view.height, 48);
                         EXPECT_EQ(view.format, ubii_dataStructure_Image2D_DataFormat_RGB8);
                         ASSERT_EQ(view.size, pixels.size());
                         EXPECT_EQ(std::memcmp(view.data, pixels.data(), view.size), 0);
                     }});
    ubii_test::StringValues image_elements{{std::string(image.begin(), image.end())}};
    cases.push_back({"image2D_list", UBII_RECORD_IMAGE2D_LIST,
                     [=](ubii_node *n, const char *t) {
                         ubii_dataStructure_Image2DList list =
                             ubii_dataStructure_Image2DList_init_zero;
                         ubii_test::encode_from(list.elements, image_elements);
                         return ubii_publish_message(n, t, UBII_RECORD_IMAGE2D_LIST,
                                                     ubii_dataStructure_Image2DList_fields, &list);
                     },
                     list_of({image}), 0, nullptr});
    return cases;
}

void PrintTo(const Case &c, std::ostream *out)
{
    *out << c.name;
}

// Topic data over ZMQ (tcp://) or WebSocket (ws://); one node per transport for all cases.
class RecordTypes : public ::testing::TestWithParam<std::tuple<std::string, Case>>
{
};

TEST_P(RecordTypes, ArriveBitExactThroughTheMaster)
{
    static std::map<std::string, std::unique_ptr<TestNode>> nodes;
    const std::string &transport = std::get<0>(GetParam());
    auto &owner = nodes[transport];
    if (!owner) {
        owner = std::make_unique<TestNode>("record-types-" + transport,
                                           transport == "websocket" ? ubii_test::topic_ws_url()
                                                                    : ubii_test::topic_zmq_url());
    }
    TestNode *node = owner.get();
    ASSERT_TRUE(node->wait_ready());
    const Case &c = std::get<1>(GetParam());
    const std::string topic = unique_topic("/" + c.name);
    node->received().clear();
    // The node serves every case of its transport: give the subscription back afterwards.
    struct Unsubscribe {
        ubii_node *node;
        ubii_subscription handle;
        ~Unsubscribe()
        {
            ubii_unsubscribe(node, handle);
        }
    } unsubscribe{node->get(), node->collect(topic)};
    // Publish until this case's record is back; copies of earlier cases' records may still
    // arrive in between and are passed over.
    auto own_record = [&]() -> const Received * {
        for (const Received &r : node->received()) {
            if (r.topic == topic) {
                return &r;
            }
        }
        return nullptr;
    };
    ubii_status last = UBII_OK;
    ASSERT_TRUE(node->poll_until([&] {
        last = c.publish(node->get(), topic.c_str());
        return own_record() != nullptr || last != UBII_OK;
    }));
    ASSERT_EQ(last, UBII_OK) << ubii_strerror(last);
    ASSERT_TRUE(node->poll_until([&] { return own_record() != nullptr; }));
    const Received &got = *own_record();
    ASSERT_EQ(got.type, c.type);
    if (c.expected_value.empty()) {
        EXPECT_EQ(got.scalar, c.expected_scalar);
    } else {
        EXPECT_EQ(ubii_test::to_hex(got.value.data(), got.value.size()),
                  ubii_test::to_hex(c.expected_value.data(), c.expected_value.size()));
    }
    if (c.check) {
        ubii_record record{};
        record.topic = got.topic.c_str();
        record.client_id = "";
        record.type = got.type;
        record.value = got.value.data();
        record.value_size = got.value.size();
        record.scalar = got.scalar;
        c.check(record);
    }
}

INSTANTIATE_TEST_SUITE_P(AllMembers, RecordTypes,
                         ::testing::Combine(::testing::Values("zmq", "websocket"),
                                            ::testing::ValuesIn(all_cases())),
                         [](const auto &test) {
                             return std::get<0>(test.param) + "_" + std::get<1>(test.param).name;
                         });

} // namespace

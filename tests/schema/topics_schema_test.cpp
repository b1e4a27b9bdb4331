// The reduced "topics" schema (UBII_SCHEMA=topics) against a scripted master (FakePort): a record
// of a type the schema leaves out is skipped, counted and reported, and the records beside it in
// the same TopicData are delivered. Built only in a topics-schema tree
// (tests/schema/topics_schema.sh).
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "fake_port.h"
#include "ubii/ubii.h"

using namespace ubii_test;

namespace
{

// Protobuf by hand, because the schema this test is built with has no types for the left-out
// members: these are the bytes a full-schema sender (the Node.js client, libubii's full build)
// writes. Field numbers: docs/PROTOCOL.md §3.3.
using Bytes = std::vector<uint8_t>;

Bytes varint(uint64_t value)
{
    Bytes out;
    while (value >= 0x80) {
        out.push_back(static_cast<uint8_t>(value | 0x80));
        value >>= 7;
    }
    out.push_back(static_cast<uint8_t>(value));
    return out;
}

Bytes cat(std::initializer_list<Bytes> parts)
{
    Bytes out;
    for (const auto &part : parts) {
        out.insert(out.end(), part.begin(), part.end());
    }
    return out;
}

Bytes delimited(uint32_t field, const Bytes &body)
{
    return cat({varint(field << 3 | 2), varint(body.size()), body});
}

Bytes text(uint32_t field, const std::string &value)
{
    return delimited(field, Bytes(value.begin(), value.end()));
}

Bytes varint_field(uint32_t field, uint64_t value)
{
    return cat({varint(field << 3), varint(value)});
}

Bytes double_field(uint32_t field, double value)
{
    Bytes out = varint(field << 3 | 1);
    uint8_t raw[8];
    std::memcpy(raw, &value, sizeof raw);
    out.insert(out.end(), raw, raw + 8);
    return out;
}

enum : uint32_t {
    RECORD_TOPIC = 1,
    DOUBLE = 3,
    VECTOR3 = 7,
    MATRIX4X4 = 11,
    OBJECT2D_LIST = 21,
    INT32 = 23,
    IMAGE2D = 30,
    TOPIC_DATA_RECORD = 2,
    TOPIC_DATA_RECORD_LIST = 3,
    LIST_ELEMENTS = 1
};

Bytes record(const std::string &topic, const Bytes &value)
{
    return cat({text(RECORD_TOPIC, topic), value});
}

const std::string client_id = "11111111-2222-4333-8444-555555555555";

struct Received {
    ubii_record_type type;
    double number;
};

class TopicsSchemaNode : public ::testing::Test
{
  protected:
    void SetUp() override
    {
        fake.answer =
            [](const ubii_services_ServiceRequest &request) -> std::optional<std::vector<uint8_t>> {
            std::string topic = request.topic;
            if (topic == UBII_SERVICE_SERVER_CONFIGURATION) {
                return server_reply();
            }
            if (topic == UBII_SERVICE_CLIENT_REGISTRATION) {
                return client_reply(client_id);
            }
            return success_reply();
        };
        ubii_config_init(&config);
        config.service_url = "tcp://fake:8101";
        config.client_name = "topics-schema-test";
        config.on_error = [](ubii_node *, ubii_status status, const char *detail, void *user) {
            static_cast<TopicsSchemaNode *>(user)->errors.emplace_back(status, detail);
        };
        config.on_error_user = this;
        ASSERT_EQ(ubii_node_init(&node, sizeof node, &config, fake.port()), UBII_OK);
        ASSERT_EQ(ubii_node_start(&node), UBII_OK);
        poll(5);
        ASSERT_EQ(ubii_node_state(&node), UBII_STATE_READY);
        ASSERT_EQ(ubii_subscribe(&node, "/gadget", on_record, this, nullptr), UBII_OK);
        poll(3);
    }

    void poll(int times)
    {
        for (int i = 0; i < times; ++i) {
            ubii_node_poll(&node, 0);
        }
    }

    static void on_record(ubii_node *, const ubii_record *record, void *user)
    {
        Received received{record->type, 0};
        int32_t integer = 0;
        if (ubii_record_int32(record, &integer) == UBII_OK) {
            received.number = integer;
        } else {
            ubii_record_double(record, &received.number);
        }
        static_cast<TopicsSchemaNode *>(user)->received.push_back(received);
    }

    ubii_stats stats()
    {
        ubii_stats out;
        ubii_node_stats(&node, &out);
        return out;
    }

    FakePort fake;
    ubii_config config;
    ubii_node node;
    std::vector<Received> received;
    std::vector<std::pair<ubii_status, std::string>> errors;
};

TEST(TopicsSchema, HasExactlyTheDocumentedRecordTypes)
{
    std::vector<unsigned> numbers;
#define COLLECT(name, number) numbers.push_back(number);
    UBII_RECORD_TYPE_LIST(COLLECT)
#undef COLLECT
    EXPECT_EQ(numbers, (std::vector<unsigned>{3, 4, 5, 6, 7, 8, 9, 12, 17, 18, 23, 24, 39}));
    EXPECT_STREQ(UBII_SCHEMA_NAME, "topics");
    // Kept members keep their field numbers.
    EXPECT_EQ(UBII_RECORD_POSE3D, 18);
    EXPECT_EQ(ubii_topicData_TopicDataRecord_pose3D_tag, 18);
    EXPECT_EQ(ubii_services_ServiceReply_server_tag, 5);
    EXPECT_EQ(ubii_services_ServiceRequest_topic_subscription_tag, 4);
}

TEST_F(TopicsSchemaNode, ARecordOfALeftOutTypeIsSkippedAndTheOthersInTheMessageAreDelivered)
{
    Bytes image = cat({varint_field(1, 2), varint_field(2, 1), text(4, "ab")});
    Bytes object2d_list = delimited(LIST_ELEMENTS, text(1, "box"));
    Bytes list = cat({
        delimited(LIST_ELEMENTS, record("/gadget", double_field(DOUBLE, 1.5))),
        delimited(LIST_ELEMENTS, record("/gadget", delimited(IMAGE2D, image))),
        delimited(LIST_ELEMENTS, record("/gadget", delimited(OBJECT2D_LIST, object2d_list))),
        delimited(LIST_ELEMENTS, record("/gadget", varint_field(INT32, uint64_t(int64_t(-7))))),
    });
    fake.push_topic(delimited(TOPIC_DATA_RECORD_LIST, list));
    poll(1);

    ASSERT_EQ(received.size(), 2u);
    EXPECT_EQ(received[0].type, UBII_RECORD_DOUBLE);
    EXPECT_EQ(received[0].number, 1.5);
    EXPECT_EQ(received[1].type, UBII_RECORD_INT32);
    EXPECT_EQ(received[1].number, -7);
    ubii_stats counted = stats();
    EXPECT_EQ(counted.records_skipped, 2u);
    EXPECT_EQ(counted.records_received, 2u);
    EXPECT_EQ(counted.decode_errors, 0u);
    ASSERT_EQ(errors.size(), 2u);
    for (const auto &error : errors) {
        EXPECT_EQ(error.first, UBII_ERR_UNSUPPORTED);
        EXPECT_EQ(error.second, "record of a type this build's schema leaves out was skipped");
    }
    EXPECT_EQ(ubii_node_state(&node), UBII_STATE_READY);
}

TEST_F(TopicsSchemaNode, ASingleLeftOutRecordIsSkippedAndTheNextMessageArrives)
{
    Bytes matrix;
    for (uint32_t field = 1; field <= 16; ++field) {
        matrix = cat({matrix, double_field(field, field)});
    }
    fake.push_topic(delimited(TOPIC_DATA_RECORD, record("/gadget", delimited(MATRIX4X4, matrix))));
    fake.push_topic(delimited(TOPIC_DATA_RECORD, record("/gadget", double_field(DOUBLE, 2.5))));
    poll(1);
    ASSERT_EQ(received.size(), 1u);
    EXPECT_EQ(received[0].number, 2.5);
    EXPECT_EQ(stats().records_skipped, 1u);
    EXPECT_EQ(stats().decode_errors, 0u);
}

TEST_F(TopicsSchemaNode, AKeptMessageTypeIsDeliveredAndDecoded)
{
    Bytes vector = cat({double_field(1, 1.0), double_field(2, 2.0), double_field(3, 3.0)});
    fake.push_topic(delimited(TOPIC_DATA_RECORD, record("/gadget", delimited(VECTOR3, vector))));
    poll(1);
    ASSERT_EQ(received.size(), 1u);
    EXPECT_EQ(received[0].type, UBII_RECORD_VECTOR3);
    EXPECT_EQ(stats().records_skipped, 0u);
}

TEST_F(TopicsSchemaNode, LeftOutMemberNumbersAreRefusedByTheGenericCalls)
{
    // A caller cannot name a left-out type (no enumerator); a number cast in is refused, not sent.
    ubii_dataStructure_Vector3 vector = ubii_dataStructure_Vector3_init_zero;
    EXPECT_EQ(ubii_publish_message(&node, "/gadget", static_cast<ubii_record_type>(IMAGE2D),
                                   ubii_dataStructure_Vector3_fields, &vector),
              UBII_ERR_INVALID_ARGUMENT);
    EXPECT_EQ(ubii_publish_message(&node, "/gadget", UBII_RECORD_VECTOR3,
                                   ubii_dataStructure_Vector3_fields, &vector),
              UBII_OK);
    ubii_record record{};
    record.type = UBII_RECORD_VECTOR3;
    EXPECT_EQ(ubii_record_decode(&record, static_cast<ubii_record_type>(MATRIX4X4),
                                 ubii_dataStructure_Vector3_fields, &vector),
              UBII_ERR_INVALID_ARGUMENT);
}

} // namespace

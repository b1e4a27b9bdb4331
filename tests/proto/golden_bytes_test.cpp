// The golden byte sequences of docs/PROTOCOL.md §3.4 (written by the broker's own encoder) decode
// with our generated code to the values they stand for, and encode back to exactly the same bytes.
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "pb_test_callbacks.h"
#include "ubii/dataStructure/lists.pb.h"
#include "ubii/services/serviceReply.pb.h"
#include "ubii/services/serviceRequest.pb.h"
#include "ubii/topicData/topicData.pb.h"

using ubii_test::from_hex;
using ubii_test::to_hex;

namespace
{

// Decodes in place, so that callbacks bound in `message` beforehand stay where nanopb expects them.
template <typename Message>
void decode(const std::vector<uint8_t> &bytes, const pb_msgdesc_t *fields, Message &message)
{
    pb_istream_t stream = pb_istream_from_buffer(bytes.data(), bytes.size());
    EXPECT_TRUE(pb_decode(&stream, fields, &message)) << PB_GET_ERROR(&stream);
}

template <typename Message>
std::string encode_hex(const pb_msgdesc_t *fields, const Message &message)
{
    uint8_t buffer[512];
    pb_ostream_t stream = pb_ostream_from_buffer(buffer, sizeof buffer);
    EXPECT_TRUE(pb_encode(&stream, fields, &message)) << PB_GET_ERROR(&stream);
    return to_hex(buffer, stream.bytes_written);
}

TEST(GoldenBytes, ServerConfigurationRequest)
{
    const std::string golden = "0a1e2f73657276696365732f7365727665725f636f6e66696775726174696f6e";
    ubii_services_ServiceRequest request = ubii_services_ServiceRequest_init_zero;
    decode(from_hex(golden), ubii_services_ServiceRequest_fields, request);
    EXPECT_STREQ(request.topic, "/services/server_configuration");
    EXPECT_EQ(request.which_type, 0);
    EXPECT_EQ(encode_hex(ubii_services_ServiceRequest_fields, request), golden);
}

TEST(GoldenBytes, ClientRegistrationRequest)
{
    const std::string golden = "0a1d2f73657276696365732f636c69656e742f726567697374726174696f6e120a"
                               "1206632d6e6f64653801";
    ubii_services_ServiceRequest request = ubii_services_ServiceRequest_init_zero;
    decode(from_hex(golden), ubii_services_ServiceRequest_fields, request);
    EXPECT_STREQ(request.topic, "/services/client/registration");
    ASSERT_EQ(request.which_type, ubii_services_ServiceRequest_client_tag);
    EXPECT_STREQ(request.type.client.name, "c-node");
    EXPECT_TRUE(request.type.client.is_dedicated_processing_node);
    EXPECT_EQ(encode_hex(ubii_services_ServiceRequest_fields, request), golden);
}

// Repeated strings are callbacks; the oneof's submsg_callback is where they get bound.
struct SubscriptionLists {
    ubii_test::StringValues subscribe_topics, subscribe_regexps;
};

bool bind_subscription_lists(pb_istream_t *, const pb_field_t *field, void **arg)
{
    if (field->tag == ubii_services_ServiceRequest_topic_subscription_tag) {
        auto *lists = static_cast<SubscriptionLists *>(*arg);
        auto *subscription = static_cast<ubii_services_request_TopicSubscription *>(field->pData);
        ubii_test::decode_into(subscription->subscribe_topics, lists->subscribe_topics);
        ubii_test::decode_into(subscription->subscribe_topic_regexp, lists->subscribe_regexps);
    }
    return true;
}

TEST(GoldenBytes, TopicSubscriptionRequest)
{
    const std::string golden = "0a1c2f73657276696365732f746f7069635f737562736372697074696f6e220f"
                               "0a02494412022f6122052f622f2e2a";
    SubscriptionLists lists;
    ubii_services_ServiceRequest request = ubii_services_ServiceRequest_init_zero;
    request.cb_type.funcs.decode = bind_subscription_lists;
    request.cb_type.arg = &lists;
    decode(from_hex(golden), ubii_services_ServiceRequest_fields, request);

    EXPECT_STREQ(request.topic, "/services/topic_subscription");
    ASSERT_EQ(request.which_type, ubii_services_ServiceRequest_topic_subscription_tag);
    EXPECT_STREQ(request.type.topic_subscription.client_id, "ID");
    EXPECT_EQ(lists.subscribe_topics.values, std::vector<std::string>{"/a"});
    EXPECT_EQ(lists.subscribe_regexps.values, std::vector<std::string>{"/b/.*"});

    // nanopb calls the oneof hook while encoding too; it must not re-bind the decoders now.
    request.cb_type.funcs.encode = nullptr;
    ubii_test::encode_from(request.type.topic_subscription.subscribe_topics,
                           lists.subscribe_topics);
    ubii_test::encode_from(request.type.topic_subscription.subscribe_topic_regexp,
                           lists.subscribe_regexps);
    EXPECT_EQ(encode_hex(ubii_services_ServiceRequest_fields, request), golden);
}

TEST(GoldenBytes, TopicDataWithOneDoubleRecord)
{
    const std::string golden = "12120a022f61120318e80719000000000000f03f";
    ubii_topicData_TopicData data = ubii_topicData_TopicData_init_zero;
    decode(from_hex(golden), ubii_topicData_TopicData_fields, data);
    ASSERT_EQ(data.which_type, ubii_topicData_TopicData_topic_data_record_tag);
    const auto &record = data.type.topic_data_record;
    EXPECT_STREQ(record.topic, "/a");
    ASSERT_TRUE(record.has_timestamp);
    EXPECT_EQ(record.timestamp.millis, 1000);
    ASSERT_EQ(record.which_type, ubii_topicData_TopicDataRecord_double__tag);
    EXPECT_EQ(record.type.double_, 1.0);
    EXPECT_EQ(encode_hex(ubii_topicData_TopicData_fields, data), golden);
}

// The list's elements are a callback; each element is decoded into a record of its own.
struct DecodedRecords {
    std::vector<ubii_topicData_TopicDataRecord> records;
};

bool decode_record_element(pb_istream_t *stream, const pb_field_t *, void **arg)
{
    auto *decoded = static_cast<DecodedRecords *>(*arg);
    ubii_topicData_TopicDataRecord record = ubii_topicData_TopicDataRecord_init_zero;
    if (!pb_decode(stream, ubii_topicData_TopicDataRecord_fields, &record)) {
        return false;
    }
    decoded->records.push_back(record);
    return true;
}

bool encode_record_elements(pb_ostream_t *stream, const pb_field_t *field, void *const *arg)
{
    auto *decoded = static_cast<DecodedRecords *>(*arg);
    for (const ubii_topicData_TopicDataRecord &record : decoded->records) {
        if (!pb_encode_tag_for_field(stream, field) ||
            !pb_encode_submessage(stream, ubii_topicData_TopicDataRecord_fields, &record)) {
            return false;
        }
    }
    return true;
}

TEST(GoldenBytes, TopicDataWithRecordList)
{
    const std::string golden = "1a120a070a022f61b801050a070a022f622a0178";
    DecodedRecords decoded;
    auto bind_list = [](pb_istream_t *, const pb_field_t *field, void **arg) {
        if (field->tag == ubii_topicData_TopicData_topic_data_record_list_tag) {
            auto *list = static_cast<ubii_topicData_TopicDataRecordList *>(field->pData);
            list->elements.funcs.decode = decode_record_element;
            list->elements.arg = *arg;
        }
        return true;
    };
    ubii_topicData_TopicData data = ubii_topicData_TopicData_init_zero;
    data.cb_type.funcs.decode = bind_list;
    data.cb_type.arg = &decoded;
    decode(from_hex(golden), ubii_topicData_TopicData_fields, data);

    ASSERT_EQ(data.which_type, ubii_topicData_TopicData_topic_data_record_list_tag);
    ASSERT_EQ(decoded.records.size(), 2u);
    EXPECT_STREQ(decoded.records[0].topic, "/a");
    ASSERT_EQ(decoded.records[0].which_type, ubii_topicData_TopicDataRecord_int32_tag);
    EXPECT_EQ(decoded.records[0].type.int32, 5);
    EXPECT_STREQ(decoded.records[1].topic, "/b");
    ASSERT_EQ(decoded.records[1].which_type, ubii_topicData_TopicDataRecord_string_tag);
    EXPECT_STREQ(decoded.records[1].type.string, "x");

    data.cb_type.funcs.encode = nullptr;
    data.type.topic_data_record_list.elements.funcs.encode = encode_record_elements;
    data.type.topic_data_record_list.elements.arg = &decoded;
    EXPECT_EQ(encode_hex(ubii_topicData_TopicData_fields, data), golden);
}

TEST(GoldenBytes, SuccessReply)
{
    const std::string golden = "0a0d0a075375636365737312026f6b";
    ubii_services_ServiceReply reply = ubii_services_ServiceReply_init_zero;
    decode(from_hex(golden), ubii_services_ServiceReply_fields, reply);
    ASSERT_EQ(reply.which_type, ubii_services_ServiceReply_success_tag);
    EXPECT_STREQ(reply.type.success.title, "Success");
    EXPECT_STREQ(reply.type.success.message, "ok");
    EXPECT_EQ(encode_hex(ubii_services_ServiceReply_fields, reply), golden);
}

TEST(GoldenBytes, ClientReplyKeepsExplicitDefaults)
{
    const std::string golden = "1a0d0a015812016350005d00000000";
    ubii_services_ServiceReply reply = ubii_services_ServiceReply_init_zero;
    decode(from_hex(golden), ubii_services_ServiceReply_fields, reply);
    ASSERT_EQ(reply.which_type, ubii_services_ServiceReply_client_tag);
    const auto &client = reply.type.client;
    EXPECT_STREQ(client.id, "X");
    EXPECT_STREQ(client.name, "c");
    EXPECT_TRUE(client.has_state);
    EXPECT_EQ(client.state, ubii_clients_Client_State_ACTIVE);
    EXPECT_TRUE(client.has_latency);
    EXPECT_EQ(client.latency, 0.0f);
    EXPECT_EQ(encode_hex(ubii_services_ServiceReply_fields, reply), golden);
}

TEST(GoldenBytes, PackedFloatList)
{
    const std::string golden = "0a080000803f00000040";
    ubii_test::Fixed32Values elements;
    ubii_dataStructure_FloatList list = ubii_dataStructure_FloatList_init_zero;
    ubii_test::decode_into(list.elements, elements);
    decode(from_hex(golden), ubii_dataStructure_FloatList_fields, list);
    ASSERT_EQ(elements.values.size(), 2u);
    float first, second;
    std::memcpy(&first, &elements.values[0], sizeof first);
    std::memcpy(&second, &elements.values[1], sizeof second);
    EXPECT_EQ(first, 1.0f);
    EXPECT_EQ(second, 2.0f);
    ubii_test::encode_packed_from(list.elements, elements);
    EXPECT_EQ(encode_hex(ubii_dataStructure_FloatList_fields, list), golden);
}

} // namespace

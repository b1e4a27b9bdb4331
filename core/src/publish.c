/* Publishing: one TopicData{topic_data_record} per call (the npm 0.4.0 master understands no
 * record lists), encoded straight into the transport's buffer after a sizing pass. */
#include <string.h>

#include <pb_encode.h>

#include "publish.h"
#include "record.h"
#include "ubii/topicData/timestamp.pb.h"

enum { TOPIC_DATA_RECORD = 2, RECORD_TOPIC = 1, RECORD_TIMESTAMP = 2, LIST_ELEMENTS = 1 };

typedef struct record_spec {
    const char *topic;
    bool stamped;
    int64_t millis;
    uint32_t member;
    ubii__value_writer write_value;
    const void *value;
} record_spec;

static bool write_record(pb_ostream_t *stream, const record_spec *spec)
{
    if (!pb_encode_tag(stream, PB_WT_STRING, RECORD_TOPIC) ||
        !pb_encode_string(stream, (const pb_byte_t *)spec->topic, strlen(spec->topic))) {
        return false;
    }
    if (spec->stamped) {
        ubii_topicData_Timestamp timestamp = ubii_topicData_Timestamp_init_zero;
        timestamp.millis = spec->millis;
        if (!pb_encode_tag(stream, PB_WT_STRING, RECORD_TIMESTAMP) ||
            !pb_encode_submessage(stream, ubii_topicData_Timestamp_fields, &timestamp)) {
            return false;
        }
    }
    return spec->write_value(stream, spec->member, spec->value);
}

static size_t varint_size(uint64_t value)
{
    size_t size = 1;
    while (value >= 0x80) {
        value >>= 7;
        size++;
    }
    return size;
}

ubii_status ubii__publish(ubii_node *node, const char *topic, uint32_t member,
                          ubii__value_writer write, const void *value)
{
    if (node == NULL || topic == NULL || topic[0] == '\0' || strlen(topic) >= UBII_MAX_TOPIC_SIZE) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    if (node->state != UBII_STATE_READY) {
        return UBII_ERR_NOT_CONNECTED;
    }
    record_spec spec = {topic, node->config.stamp_records, 0, member, write, value};
    if (spec.stamped) {
        spec.millis = node->port.vtable->epoch_ms(node->port.context);
    }
    pb_ostream_t sizing = PB_OSTREAM_SIZING;
    if (!write_record(&sizing, &spec)) {
        return UBII_ERR_ENCODE;
    }
    size_t record_size = sizing.bytes_written;
    size_t total = 1 + varint_size(record_size) + record_size;
    if (total > UBII_MAX_MESSAGE_SIZE) {
        return UBII_ERR_TOO_LARGE; /* a port with a larger limit would send what no peer takes */
    }

    uint8_t *buffer = NULL;
    ubii_status status =
        node->port.vtable->send_begin(node->port.context, UBII_CHANNEL_TOPIC, total, &buffer);
    if (status != UBII_OK) {
        return status;
    }
    pb_ostream_t stream = pb_ostream_from_buffer(buffer, total);
    if (!pb_encode_tag(&stream, PB_WT_STRING, TOPIC_DATA_RECORD) ||
        !pb_encode_varint(&stream, record_size) || !write_record(&stream, &spec) ||
        stream.bytes_written != total) {
        return UBII_ERR_ENCODE;
    }
    status = node->port.vtable->send_commit(node->port.context, UBII_CHANNEL_TOPIC, 0);
    if (status == UBII_OK) {
        node->stats.records_published++;
    }
    return status;
}

/* ---- scalars -----------------------------------------------------------------------------------
 */

static bool write_fixed64(pb_ostream_t *stream, uint32_t member, const void *value)
{
    return pb_encode_tag(stream, PB_WT_64BIT, member) && pb_encode_fixed64(stream, value);
}

static bool write_fixed32(pb_ostream_t *stream, uint32_t member, const void *value)
{
    return pb_encode_tag(stream, PB_WT_32BIT, member) && pb_encode_fixed32(stream, value);
}

static bool write_varint(pb_ostream_t *stream, uint32_t member, const void *value)
{
    return pb_encode_tag(stream, PB_WT_VARINT, member) &&
           pb_encode_varint(stream, *(const uint64_t *)value);
}

ubii_status ubii_publish_double(ubii_node *node, const char *topic, double value)
{
    return ubii__publish(node, topic, UBII_RECORD_DOUBLE, write_fixed64, &value);
}

ubii_status ubii_publish_float(ubii_node *node, const char *topic, float value)
{
    return ubii__publish(node, topic, UBII_RECORD_FLOAT, write_fixed32, &value);
}

ubii_status ubii_publish_int32(ubii_node *node, const char *topic, int32_t value)
{
    uint64_t widened = (uint64_t)(int64_t)value; /* protobuf's int32: negative as 10-byte varint */
    return ubii__publish(node, topic, UBII_RECORD_INT32, write_varint, &widened);
}

ubii_status ubii_publish_bool(ubii_node *node, const char *topic, bool value)
{
    uint64_t raw = value ? 1 : 0;
    return ubii__publish(node, topic, UBII_RECORD_BOOL, write_varint, &raw);
}

/* ---- length-delimited members ------------------------------------------------------------------
 */

typedef struct bytes_value {
    const uint8_t *data;
    size_t size;
} bytes_value;

static bool write_bytes(pb_ostream_t *stream, uint32_t member, const void *value)
{
    const bytes_value *bytes = value;
    return pb_encode_tag(stream, PB_WT_STRING, member) &&
           pb_encode_string(stream, bytes->data, bytes->size);
}

ubii_status ubii_publish_string(ubii_node *node, const char *topic, const char *text, size_t length)
{
    if (text == NULL && length > 0) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    bytes_value value = {(const uint8_t *)text, length};
    return ubii__publish(node, topic, UBII_RECORD_STRING, write_bytes, &value);
}

typedef struct message_value {
    const pb_msgdesc_t *fields;
    const void *message;
} message_value;

static bool write_message(pb_ostream_t *stream, uint32_t member, const void *value)
{
    const message_value *message = value;
    return pb_encode_tag(stream, PB_WT_STRING, member) &&
           pb_encode_submessage(stream, message->fields, message->message);
}

ubii_status ubii_publish_message(ubii_node *node, const char *topic, ubii_record_type type,
                                 const pb_msgdesc_t *fields, const void *message)
{
    if (fields == NULL || message == NULL || !ubii__record_type_known((uint32_t)type) ||
        ubii__record_wire_type((uint32_t)type) != PB_WT_STRING || type == UBII_RECORD_STRING) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    message_value value = {fields, message};
    return ubii__publish(node, topic, (uint32_t)type, write_message, &value);
}

ubii_status ubii_publish_encoded(ubii_node *node, const char *topic, ubii_record_type type,
                                 const uint8_t *bytes, size_t size)
{
    if ((bytes == NULL && size > 0) || !ubii__record_type_known((uint32_t)type) ||
        ubii__record_wire_type((uint32_t)type) != PB_WT_STRING) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    bytes_value value = {bytes, size};
    return ubii__publish(node, topic, (uint32_t)type, write_bytes, &value);
}

ubii_status ubii_publish_vector2(ubii_node *node, const char *topic,
                                 const ubii_dataStructure_Vector2 *value)
{
    return ubii_publish_message(node, topic, UBII_RECORD_VECTOR2, ubii_dataStructure_Vector2_fields,
                                value);
}

ubii_status ubii_publish_vector3(ubii_node *node, const char *topic,
                                 const ubii_dataStructure_Vector3 *value)
{
    return ubii_publish_message(node, topic, UBII_RECORD_VECTOR3, ubii_dataStructure_Vector3_fields,
                                value);
}

ubii_status ubii_publish_vector4(ubii_node *node, const char *topic,
                                 const ubii_dataStructure_Vector4 *value)
{
    return ubii_publish_message(node, topic, UBII_RECORD_VECTOR4, ubii_dataStructure_Vector4_fields,
                                value);
}

ubii_status ubii_publish_quaternion(ubii_node *node, const char *topic,
                                    const ubii_dataStructure_Quaternion *value)
{
    return ubii_publish_message(node, topic, UBII_RECORD_QUATERNION,
                                ubii_dataStructure_Quaternion_fields, value);
}

ubii_status ubii_publish_color(ubii_node *node, const char *topic,
                               const ubii_dataStructure_Color *value)
{
    return ubii_publish_message(node, topic, UBII_RECORD_COLOR, ubii_dataStructure_Color_fields,
                                value);
}

ubii_status ubii_publish_pose2d(ubii_node *node, const char *topic,
                                const ubii_dataStructure_Pose2D *value)
{
    return ubii_publish_message(node, topic, UBII_RECORD_POSE2D, ubii_dataStructure_Pose2D_fields,
                                value);
}

ubii_status ubii_publish_pose3d(ubii_node *node, const char *topic,
                                const ubii_dataStructure_Pose3D *value)
{
    return ubii_publish_message(node, topic, UBII_RECORD_POSE3D, ubii_dataStructure_Pose3D_fields,
                                value);
}

/* ---- message-typed members written field by field ----------------------------------------------
 */

typedef struct body_value {
    ubii__body_writer write_body;
    const void *body;
} body_value;

/* Tag, length (from a sizing pass over the body), body. */
static bool write_body_member(pb_ostream_t *stream, uint32_t member, const void *value)
{
    const body_value *body = value;
    pb_ostream_t sizing = PB_OSTREAM_SIZING;
    if (!body->write_body(&sizing, body->body)) {
        return false;
    }
    return pb_encode_tag(stream, PB_WT_STRING, member) &&
           pb_encode_varint(stream, sizing.bytes_written) && body->write_body(stream, body->body);
}

ubii_status ubii__publish_body(ubii_node *node, const char *topic, uint32_t member,
                               ubii__body_writer write_body, const void *body)
{
    body_value value = {write_body, body};
    return ubii__publish(node, topic, member, write_body_member, &value);
}

/* Publishing: one TopicData{topic_data_record} per call (the npm 0.4.0 master understands no
 * record lists), encoded straight into the transport's buffer after a sizing pass. */
#include <string.h>

#include <pb_encode.h>

#include "node_internal.h"
#include "ubii/topicData/timestamp.pb.h"

enum { TOPIC_DATA_RECORD = 2, RECORD_TOPIC = 1, RECORD_TIMESTAMP = 2, LIST_ELEMENTS = 1 };

/* Writes a record's value member (tag included). */
typedef bool (*value_writer)(pb_ostream_t *stream, uint32_t member, const void *value);

typedef struct record_spec {
    const char *topic;
    bool stamped;
    int64_t millis;
    uint32_t member;
    value_writer write_value;
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

static ubii_status publish(ubii_node *node, const char *topic, uint32_t member, value_writer write,
                           const void *value)
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
    return publish(node, topic, UBII_RECORD_DOUBLE, write_fixed64, &value);
}

ubii_status ubii_publish_float(ubii_node *node, const char *topic, float value)
{
    return publish(node, topic, UBII_RECORD_FLOAT, write_fixed32, &value);
}

ubii_status ubii_publish_int32(ubii_node *node, const char *topic, int32_t value)
{
    uint64_t widened = (uint64_t)(int64_t)value; /* protobuf's int32: negative as 10-byte varint */
    return publish(node, topic, UBII_RECORD_INT32, write_varint, &widened);
}

ubii_status ubii_publish_bool(ubii_node *node, const char *topic, bool value)
{
    uint64_t raw = value ? 1 : 0;
    return publish(node, topic, UBII_RECORD_BOOL, write_varint, &raw);
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
    return publish(node, topic, UBII_RECORD_STRING, write_bytes, &value);
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
    if (fields == NULL || message == NULL || type == UBII_RECORD_NONE ||
        type == UBII_RECORD_DOUBLE || type == UBII_RECORD_FLOAT || type == UBII_RECORD_BOOL ||
        type == UBII_RECORD_INT32 || type == UBII_RECORD_STRING || (uint32_t)type > 44) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    message_value value = {fields, message};
    return publish(node, topic, (uint32_t)type, write_message, &value);
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

/* A list message's body, written by `write_body` into a sizing stream first to learn its length. */
typedef bool (*body_writer)(pb_ostream_t *stream, const void *value);

typedef struct list_value {
    body_writer write_body;
    const void *items;
    size_t count;
} list_value;

static bool write_list(pb_ostream_t *stream, uint32_t member, const void *value)
{
    const list_value *list = value;
    pb_ostream_t sizing = PB_OSTREAM_SIZING;
    if (!list->write_body(&sizing, list)) {
        return false;
    }
    return pb_encode_tag(stream, PB_WT_STRING, member) &&
           pb_encode_varint(stream, sizing.bytes_written) && list->write_body(stream, list);
}

/* Packed numeric elements: tag, byte length, values. */
static bool write_packed(pb_ostream_t *stream, const list_value *list, size_t width,
                         bool (*write_one)(pb_ostream_t *, const void *))
{
    if (list->count == 0) {
        return true;
    }
    const uint8_t *item = list->items;
    pb_ostream_t sizing = PB_OSTREAM_SIZING;
    for (size_t i = 0; i < list->count; ++i) {
        if (!write_one(&sizing, item + i * width)) {
            return false;
        }
    }
    if (!pb_encode_tag(stream, PB_WT_STRING, LIST_ELEMENTS) ||
        !pb_encode_varint(stream, sizing.bytes_written)) {
        return false;
    }
    for (size_t i = 0; i < list->count; ++i) {
        if (!write_one(stream, item + i * width)) {
            return false;
        }
    }
    return true;
}

static bool write_double_element(pb_ostream_t *stream, const void *item)
{
    return pb_encode_fixed64(stream, item);
}

static bool write_float_element(pb_ostream_t *stream, const void *item)
{
    return pb_encode_fixed32(stream, item);
}

static bool write_int32_element(pb_ostream_t *stream, const void *item)
{
    return pb_encode_varint(stream, (uint64_t)(int64_t) * (const int32_t *)item);
}

static bool write_bool_element(pb_ostream_t *stream, const void *item)
{
    return pb_encode_varint(stream, *(const bool *)item ? 1 : 0);
}

static bool write_doubles(pb_ostream_t *stream, const void *value)
{
    return write_packed(stream, value, sizeof(double), write_double_element);
}

static bool write_floats(pb_ostream_t *stream, const void *value)
{
    return write_packed(stream, value, sizeof(float), write_float_element);
}

static bool write_int32s(pb_ostream_t *stream, const void *value)
{
    return write_packed(stream, value, sizeof(int32_t), write_int32_element);
}

static bool write_bools(pb_ostream_t *stream, const void *value)
{
    return write_packed(stream, value, sizeof(bool), write_bool_element);
}

static bool write_strings(pb_ostream_t *stream, const void *value)
{
    const list_value *list = value;
    const char *const *texts = list->items;
    for (size_t i = 0; i < list->count; ++i) {
        if (texts[i] == NULL || !pb_encode_tag(stream, PB_WT_STRING, LIST_ELEMENTS) ||
            !pb_encode_string(stream, (const pb_byte_t *)texts[i], strlen(texts[i]))) {
            return false;
        }
    }
    return true;
}

static ubii_status publish_list(ubii_node *node, const char *topic, ubii_record_type type,
                                body_writer write_body, const void *items, size_t count)
{
    if (items == NULL && count > 0) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    list_value list = {write_body, items, count};
    return publish(node, topic, (uint32_t)type, write_list, &list);
}

ubii_status ubii_publish_doubles(ubii_node *node, const char *topic, const double *values,
                                 size_t count)
{
    return publish_list(node, topic, UBII_RECORD_DOUBLE_LIST, write_doubles, values, count);
}

ubii_status ubii_publish_floats(ubii_node *node, const char *topic, const float *values,
                                size_t count)
{
    return publish_list(node, topic, UBII_RECORD_FLOAT_LIST, write_floats, values, count);
}

ubii_status ubii_publish_int32s(ubii_node *node, const char *topic, const int32_t *values,
                                size_t count)
{
    return publish_list(node, topic, UBII_RECORD_INT32_LIST, write_int32s, values, count);
}

ubii_status ubii_publish_bools(ubii_node *node, const char *topic, const bool *values, size_t count)
{
    return publish_list(node, topic, UBII_RECORD_BOOL_LIST, write_bools, values, count);
}

ubii_status ubii_publish_strings(ubii_node *node, const char *topic, const char *const *texts,
                                 size_t count)
{
    return publish_list(node, topic, UBII_RECORD_STRING_LIST, write_strings, texts, count);
}

/* ---- images ------------------------------------------------------------------------------------
 */

typedef struct image_value {
    int32_t width;
    int32_t height;
    ubii_dataStructure_Image2D_DataFormat format;
    const uint8_t *data;
    size_t size;
} image_value;

static bool write_image_body(pb_ostream_t *stream, const void *value)
{
    const image_value *image = ((const list_value *)value)->items;
    /* proto3: fields at their default value are left out, as every other encoder does. */
    return (image->width == 0 || (pb_encode_tag(stream, PB_WT_VARINT, 1) &&
                                  pb_encode_varint(stream, (uint64_t)(int64_t)image->width))) &&
           (image->height == 0 || (pb_encode_tag(stream, PB_WT_VARINT, 2) &&
                                   pb_encode_varint(stream, (uint64_t)(int64_t)image->height))) &&
           (image->format == 0 || (pb_encode_tag(stream, PB_WT_VARINT, 3) &&
                                   pb_encode_varint(stream, (uint64_t)image->format))) &&
           (image->size == 0 || (pb_encode_tag(stream, PB_WT_STRING, 4) &&
                                 pb_encode_string(stream, image->data, image->size)));
}

ubii_status ubii_publish_image(ubii_node *node, const char *topic, int32_t width, int32_t height,
                               ubii_dataStructure_Image2D_DataFormat format, const uint8_t *data,
                               size_t size)
{
    if ((data == NULL && size > 0) || width < 0 || height < 0) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    image_value image = {width, height, format, data, size};
    return publish_list(node, topic, UBII_RECORD_IMAGE2D, write_image_body, &image, 1);
}

/* Received TopicData: the records are read in place and lent to subscription callbacks; a value is
 * decoded only when an accessor asks for it. */
#include <string.h>

#include <pb_decode.h>

#include "node_internal.h"
#include "ubii/general/error.pb.h"
#include "ubii/topicData/timestamp.pb.h"
#include "ubii/wire.h"
#include "wire_scan.h"

enum {
    RECORD_TOPIC = 1,
    RECORD_TIMESTAMP = 2,
    RECORD_CLIENT_ID = 33,
    RECORD_LAST_MEMBER = 44,
    TOPIC_DATA_RECORD = 2,
    TOPIC_DATA_RECORD_LIST = 3,
    TOPIC_DATA_ERROR = 4,
    LIST_ELEMENTS = 1,
    IMAGE_WIDTH = 1,
    IMAGE_HEIGHT = 2,
    IMAGE_FORMAT = 3,
    IMAGE_DATA = 4
};

/* The wire type each value member must arrive with. */
static int member_wire_type(uint32_t number)
{
    switch (number) {
    case UBII_RECORD_DOUBLE:
        return PB_WT_64BIT;
    case UBII_RECORD_FLOAT:
        return PB_WT_32BIT;
    case UBII_RECORD_BOOL:
    case UBII_RECORD_INT32:
        return PB_WT_VARINT;
    default:
        return PB_WT_STRING;
    }
}

static bool copy_text(char *destination, size_t capacity, const uint8_t *bytes, size_t size)
{
    if (size >= capacity || memchr(bytes, '\0', size) != NULL) {
        return false;
    }
    memcpy(destination, bytes, size);
    destination[size] = '\0';
    return true;
}

static ubii_status parse_record(ubii_node *node, const uint8_t *bytes, size_t size,
                                ubii_record *record)
{
    memset(record, 0, sizeof *record);
    node->record_topic[0] = '\0';
    node->record_client_id[0] = '\0';
    record->topic = node->record_topic;
    record->client_id = node->record_client_id;

    ubii_wire_scan scan;
    ubii_wire_field field;
    bool malformed = false;
    ubii_wire_scan_init(&scan, bytes, size);
    while (ubii_wire_scan_next(&scan, &field, &malformed)) {
        if (field.number == RECORD_TOPIC && field.wire_type == PB_WT_STRING) {
            if (!copy_text(node->record_topic, sizeof node->record_topic, field.bytes,
                           field.size)) {
                return UBII_ERR_TOO_LARGE;
            }
        } else if (field.number == RECORD_CLIENT_ID && field.wire_type == PB_WT_STRING) {
            if (!copy_text(node->record_client_id, sizeof node->record_client_id, field.bytes,
                           field.size)) {
                return UBII_ERR_TOO_LARGE;
            }
        } else if (field.number == RECORD_TIMESTAMP && field.wire_type == PB_WT_STRING) {
            ubii_topicData_Timestamp timestamp = ubii_topicData_Timestamp_init_zero;
            pb_istream_t stream = pb_istream_from_buffer(field.bytes, field.size);
            if (!pb_decode(&stream, ubii_topicData_Timestamp_fields, &timestamp)) {
                return UBII_ERR_DECODE;
            }
            record->has_timestamp = true;
            record->timestamp_millis = timestamp.millis;
            record->timestamp_seconds = timestamp.seconds;
            record->timestamp_nanos = timestamp.nanos;
        } else if (field.number >= UBII_RECORD_DOUBLE && field.number <= RECORD_LAST_MEMBER &&
                   field.number != RECORD_CLIENT_ID) {
            if (field.wire_type != member_wire_type(field.number)) {
                return UBII_ERR_DECODE;
            }
            record->type = (ubii_record_type)field.number; /* the last member wins */
            record->value = field.bytes;
            record->value_size = field.size;
            record->scalar = field.scalar;
        }
    }
    if (malformed) {
        return UBII_ERR_DECODE;
    }
    return record->topic[0] != '\0' ? UBII_OK : UBII_ERR_DECODE;
}

static void handle_record(ubii_node *node, const uint8_t *bytes, size_t size,
                          const uint8_t *message, size_t message_size)
{
    ubii_record record;
    ubii_status status = parse_record(node, bytes, size, &record);
    if (status != UBII_OK) {
        node->stats.decode_errors++;
        ubii__report(node, status,
                     status == UBII_ERR_TOO_LARGE
                         ? "record with a topic or client id over the size limit"
                         : "record could not be decoded");
        return;
    }
    ubii__dispatch_record(node, &record, message, message_size);
}

static void handle_master_error(ubii_node *node, const uint8_t *bytes, size_t size)
{
    ubii_general_Error error = ubii_general_Error_init_zero;
    pb_istream_t stream = pb_istream_from_buffer(bytes, size);
    node->stats.master_errors++;
    if (!pb_decode(&stream, ubii_general_Error_fields, &error)) {
        ubii__report(node, UBII_ERR_DECODE, "undecodable TopicData.error from the master");
        return;
    }
    ubii__report(node, UBII_ERR_BROKER, error.title[0] ? error.title : error.message);
}

void ubii__handle_topic_data(ubii_node *node, const uint8_t *bytes, size_t size)
{
    ubii_wire_scan scan;
    ubii_wire_field field;
    bool malformed = false;
    ubii_wire_scan_init(&scan, bytes, size);
    while (node->state == UBII_STATE_READY && ubii_wire_scan_next(&scan, &field, &malformed)) {
        if (field.wire_type != PB_WT_STRING) {
            continue;
        }
        if (field.number == TOPIC_DATA_RECORD) {
            handle_record(node, field.bytes, field.size, bytes, size);
        } else if (field.number == TOPIC_DATA_RECORD_LIST) {
            ubii_field_iter elements;
            const uint8_t *element;
            size_t element_size;
            ubii_field_iter_init(&elements, field.bytes, field.size, LIST_ELEMENTS);
            while (node->state == UBII_STATE_READY &&
                   ubii_field_iter_next(&elements, &element, &element_size)) {
                handle_record(node, element, element_size, element, element_size);
            }
            malformed = malformed || elements.malformed;
        } else if (field.number == TOPIC_DATA_ERROR) {
            handle_master_error(node, field.bytes, field.size);
        }
    }
    if (malformed) {
        node->stats.decode_errors++;
        ubii__report(node, UBII_ERR_DECODE, "topic data could not be decoded");
    }
}

/* ---- accessors ---------------------------------------------------------------------------------
 */

ubii_status ubii_record_double(const ubii_record *record, double *value)
{
    if (record == NULL || value == NULL) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    if (record->type != UBII_RECORD_DOUBLE) {
        return UBII_ERR_WRONG_TYPE;
    }
    memcpy(value, &record->scalar, sizeof *value);
    return UBII_OK;
}

ubii_status ubii_record_float(const ubii_record *record, float *value)
{
    if (record == NULL || value == NULL) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    if (record->type != UBII_RECORD_FLOAT) {
        return UBII_ERR_WRONG_TYPE;
    }
    uint32_t bits = (uint32_t)record->scalar;
    memcpy(value, &bits, sizeof *value);
    return UBII_OK;
}

ubii_status ubii_record_int32(const ubii_record *record, int32_t *value)
{
    if (record == NULL || value == NULL) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    if (record->type != UBII_RECORD_INT32) {
        return UBII_ERR_WRONG_TYPE;
    }
    *value = (int32_t)(uint32_t)record->scalar; /* int32 travels sign-extended to 64 bits */
    return UBII_OK;
}

ubii_status ubii_record_bool(const ubii_record *record, bool *value)
{
    if (record == NULL || value == NULL) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    if (record->type != UBII_RECORD_BOOL) {
        return UBII_ERR_WRONG_TYPE;
    }
    *value = record->scalar != 0;
    return UBII_OK;
}

ubii_status ubii_record_string(const ubii_record *record, const char **text, size_t *length)
{
    if (record == NULL || text == NULL || length == NULL) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    if (record->type != UBII_RECORD_STRING) {
        return UBII_ERR_WRONG_TYPE;
    }
    *text = (const char *)record->value;
    *length = record->value_size;
    return UBII_OK;
}

ubii_status ubii_record_decode(const ubii_record *record, ubii_record_type type,
                               const pb_msgdesc_t *fields, void *message)
{
    if (record == NULL || fields == NULL || message == NULL ||
        member_wire_type((uint32_t)type) != PB_WT_STRING || type == UBII_RECORD_STRING) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    if (record->type != type) {
        return UBII_ERR_WRONG_TYPE;
    }
    pb_istream_t stream = pb_istream_from_buffer(record->value, record->value_size);
    return pb_decode(&stream, fields, message) ? UBII_OK : UBII_ERR_DECODE;
}

ubii_status ubii_record_image(const ubii_record *record, ubii_image_view *image)
{
    if (record == NULL || image == NULL) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    if (record->type != UBII_RECORD_IMAGE2D) {
        return UBII_ERR_WRONG_TYPE;
    }
    memset(image, 0, sizeof *image);
    ubii_wire_scan scan;
    ubii_wire_field field;
    bool malformed = false;
    ubii_wire_scan_init(&scan, record->value, record->value_size);
    while (ubii_wire_scan_next(&scan, &field, &malformed)) {
        bool varint = field.wire_type == PB_WT_VARINT;
        if (field.number == IMAGE_WIDTH && varint) {
            image->width = (int32_t)(uint32_t)field.scalar;
        } else if (field.number == IMAGE_HEIGHT && varint) {
            image->height = (int32_t)(uint32_t)field.scalar;
        } else if (field.number == IMAGE_FORMAT && varint) {
            image->format = (ubii_dataStructure_Image2D_DataFormat)field.scalar;
        } else if (field.number == IMAGE_DATA && field.wire_type == PB_WT_STRING) {
            image->data = field.bytes;
            image->size = field.size;
        }
    }
    return malformed ? UBII_ERR_DECODE : UBII_OK;
}

ubii_status ubii_record_list(const ubii_record *record, ubii_record_type type, ubii_list_iter *iter)
{
    if (record == NULL || iter == NULL || member_wire_type((uint32_t)type) != PB_WT_STRING) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    if (record->type != type) {
        return UBII_ERR_WRONG_TYPE;
    }
    memset(iter, 0, sizeof *iter);
    iter->bytes = record->value;
    iter->size = record->value_size;
    return UBII_OK;
}

/* The next element of field 1 whose wire type is `element_wire_type`, from a packed run or alone.
 */
static bool next_scalar(ubii_list_iter *iter, int element_wire_type, uint64_t *value)
{
    for (;;) {
        if (iter->packed_left > 0) {
            pb_istream_t stream = pb_istream_from_buffer(iter->packed, iter->packed_left);
            bool ok;
            if (element_wire_type == PB_WT_64BIT) {
                ok = pb_decode_fixed64(&stream, value);
            } else if (element_wire_type == PB_WT_32BIT) {
                uint32_t bits = 0;
                ok = pb_decode_fixed32(&stream, &bits);
                *value = bits;
            } else {
                ok = pb_decode_varint(&stream, value);
            }
            if (!ok) {
                iter->malformed = true;
                iter->packed_left = 0;
                return false;
            }
            iter->packed += iter->packed_left - stream.bytes_left;
            iter->packed_left = stream.bytes_left;
            return true;
        }
        ubii_wire_scan scan = {iter->bytes, iter->size, iter->offset};
        ubii_wire_field field;
        bool found = false;
        while (!found && ubii_wire_scan_next(&scan, &field, &iter->malformed)) {
            found = field.number == LIST_ELEMENTS;
        }
        iter->offset = scan.offset;
        if (!found) {
            return false;
        }
        if (field.wire_type == PB_WT_STRING) {
            iter->packed = field.bytes;
            iter->packed_left = field.size;
        } else if (field.wire_type == element_wire_type) {
            *value = field.scalar;
            return true;
        } else {
            iter->malformed = true;
            return false;
        }
    }
}

bool ubii_list_next_double(ubii_list_iter *iter, double *value)
{
    uint64_t bits;
    if (iter == NULL || value == NULL || !next_scalar(iter, PB_WT_64BIT, &bits)) {
        return false;
    }
    memcpy(value, &bits, sizeof *value);
    return true;
}

bool ubii_list_next_float(ubii_list_iter *iter, float *value)
{
    uint64_t bits;
    if (iter == NULL || value == NULL || !next_scalar(iter, PB_WT_32BIT, &bits)) {
        return false;
    }
    uint32_t narrow = (uint32_t)bits;
    memcpy(value, &narrow, sizeof *value);
    return true;
}

bool ubii_list_next_int32(ubii_list_iter *iter, int32_t *value)
{
    uint64_t raw;
    if (iter == NULL || value == NULL || !next_scalar(iter, PB_WT_VARINT, &raw)) {
        return false;
    }
    *value = (int32_t)(uint32_t)raw;
    return true;
}

bool ubii_list_next_bool(ubii_list_iter *iter, bool *value)
{
    uint64_t raw;
    if (iter == NULL || value == NULL || !next_scalar(iter, PB_WT_VARINT, &raw)) {
        return false;
    }
    *value = raw != 0;
    return true;
}

bool ubii_list_next_bytes(ubii_list_iter *iter, const uint8_t **bytes, size_t *size)
{
    if (iter == NULL || bytes == NULL || size == NULL) {
        return false;
    }
    ubii_field_iter fields = {iter->bytes, iter->size, iter->offset, LIST_ELEMENTS, false};
    bool found = ubii_field_iter_next(&fields, bytes, size);
    iter->offset = fields.offset;
    iter->malformed = iter->malformed || fields.malformed;
    return found;
}

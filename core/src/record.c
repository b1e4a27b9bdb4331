/* Received TopicData: the records are read in place and lent to subscription callbacks; a value is
 * decoded only when an accessor asks for it. */
#include <string.h>

#include <pb_decode.h>

#include "node_events.h"
#include "record.h"
#include "subscriptions.h"
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
    LIST_ELEMENTS = 1
};

/* A fact of the wire schema, the same for every schema built: the full schema's value members are
 * fields 3 to 44 except 33 (client_id). A reduced schema recognises a left-out member by number and
 * wire type, and skips the record instead of failing on it. */
static bool is_value_member(uint32_t number)
{
    return number >= UBII_RECORD_DOUBLE && number <= RECORD_LAST_MEMBER &&
           number != RECORD_CLIENT_ID;
}

bool ubii__record_type_known(uint32_t number)
{
    switch (number) {
#define UBII_RECORD_CASE(name, field_number) case UBII_RECORD_##name:
        UBII_RECORD_TYPE_LIST(UBII_RECORD_CASE)
#undef UBII_RECORD_CASE
        return true;
    default:
        return false;
    }
}

typedef struct member_info {
    ubii_record_type type;
    const char *name;
    const char *format;
} member_info;

#define UBII_MEMBER_INFO(upper, number, name, format, cpp_type) {UBII_RECORD_##upper, name, format},
static const member_info members[] = {UBII_RECORD_MEMBER_LIST(UBII_MEMBER_INFO)};
#undef UBII_MEMBER_INFO
enum { MEMBER_COUNT = sizeof members / sizeof members[0] };

static const member_info *find_member(ubii_record_type type)
{
    for (size_t i = 0; i < MEMBER_COUNT; ++i) {
        if (members[i].type == type) {
            return &members[i];
        }
    }
    return NULL;
}

const char *ubii_record_type_name(ubii_record_type type)
{
    const member_info *member = find_member(type);
    return member != NULL ? member->name : NULL;
}

const char *ubii_record_type_format(ubii_record_type type)
{
    const member_info *member = find_member(type);
    return member != NULL ? member->format : NULL;
}

ubii_record_type ubii_record_type_for_format(const char *format)
{
    if (format == NULL) {
        return UBII_RECORD_NONE;
    }
    for (size_t i = 0; i < MEMBER_COUNT; ++i) {
        if (strcmp(members[i].format, format) == 0) {
            return members[i].type;
        }
    }
    return UBII_RECORD_NONE;
}

int ubii__record_wire_type(uint32_t number)
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

    uint32_t member = 0;
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
        } else if (is_value_member(field.number)) {
            if (field.wire_type != ubii__record_wire_type(field.number)) {
                return UBII_ERR_DECODE;
            }
            member = field.number; /* the last member wins */
            record->value = field.bytes;
            record->value_size = field.size;
            record->scalar = field.scalar;
        }
    }
    if (malformed || record->topic[0] == '\0') {
        return UBII_ERR_DECODE;
    }
    if (member != 0 && !ubii__record_type_known(member)) {
        return UBII_ERR_UNSUPPORTED; /* a member this build's schema leaves out */
    }
    record->type = (ubii_record_type)member;
    return UBII_OK;
}

static void handle_record(ubii_node *node, const uint8_t *bytes, size_t size,
                          const uint8_t *message, size_t message_size)
{
    ubii_record record;
    ubii_status status = parse_record(node, bytes, size, &record);
    if (status == UBII_ERR_UNSUPPORTED) {
        /* Not an error of the sender's: the record is valid, this build cannot represent it. */
        node->stats.records_skipped++;
        ubii__report(node, status, "record of a type this build's schema leaves out was skipped");
        return;
    }
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
    ubii_general_Error error;
    memset(&error, 0, sizeof error);
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
        !ubii__record_type_known((uint32_t)type) ||
        ubii__record_wire_type((uint32_t)type) != PB_WT_STRING || type == UBII_RECORD_STRING) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    if (record->type != type) {
        return UBII_ERR_WRONG_TYPE;
    }
    pb_istream_t stream = pb_istream_from_buffer(record->value, record->value_size);
    return pb_decode(&stream, fields, message) ? UBII_OK : UBII_ERR_DECODE;
}

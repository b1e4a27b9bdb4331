#include "ubii/service_codec.h"

#include <string.h>

#include <pb_decode.h>
#include <pb_encode.h>

#include "ubii/general/error.pb.h"
#include "ubii/services/serviceReply.pb.h"
#include "ubii/services/serviceRequest.pb.h"
#include "wire_scan.h"

ubii_status ubii_encode_topic_request(const char *topic, uint8_t *buffer, size_t capacity,
                                      size_t *length)
{
    if (topic == NULL || topic[0] == '\0' || buffer == NULL || length == NULL) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    ubii_services_ServiceRequest request = ubii_services_ServiceRequest_init_zero;
    size_t topic_length = strlen(topic);
    if (topic_length >= sizeof request.topic) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    memcpy(request.topic, topic, topic_length + 1);

    pb_ostream_t stream = pb_ostream_from_buffer(buffer, capacity);
    if (!pb_encode(&stream, ubii_services_ServiceRequest_fields, &request)) {
        return stream.bytes_written >= capacity ? UBII_ERR_BUFFER_TOO_SMALL : UBII_ERR_ENCODE;
    }
    *length = stream.bytes_written;
    return UBII_OK;
}

static void copy_truncated(char *destination, size_t capacity, const char *source)
{
    size_t length = strlen(source);
    if (length >= capacity) {
        length = capacity - 1;
    }
    memcpy(destination, source, length);
    destination[length] = '\0';
}

/* Finds the member of ServiceReply's oneof. Protobuf gives the last occurrence precedence. */
static ubii_status find_reply_member(const uint8_t *bytes, size_t length, ubii_wire_field *member)
{
    ubii_wire_scan scan;
    ubii_wire_field field;
    bool malformed = false;
    bool found = false;
    ubii_wire_scan_init(&scan, bytes, length);
    while (ubii_wire_scan_next(&scan, &field, &malformed)) {
        if (field.wire_type == PB_WT_STRING) {
            *member = field;
            found = true;
        }
    }
    if (malformed) {
        return UBII_ERR_DECODE;
    }
    return found ? UBII_OK : UBII_ERR_UNEXPECTED_REPLY;
}

static ubii_status decode_broker_error(const ubii_wire_field *member, ubii_broker_error *error)
{
    ubii_general_Error decoded = ubii_general_Error_init_zero;
    /* The stack is a callback left unset: nanopb skips it, as nobody should parse JS stacks. */
    pb_istream_t stream = pb_istream_from_buffer(member->bytes, member->size);
    if (!pb_decode(&stream, ubii_general_Error_fields, &decoded)) {
        return UBII_ERR_DECODE;
    }
    if (error != NULL) {
        copy_truncated(error->title, sizeof error->title, decoded.title);
        copy_truncated(error->message, sizeof error->message, decoded.message);
    }
    return UBII_ERR_BROKER;
}

ubii_status ubii_decode_server_reply(const uint8_t *bytes, size_t length,
                                     ubii_servers_Server *server, ubii_broker_error *error)
{
    if ((bytes == NULL && length > 0) || server == NULL) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    ubii_wire_field member;
    ubii_status status = find_reply_member(bytes, length, &member);
    if (status != UBII_OK) {
        return status;
    }
    if (member.number == ubii_services_ServiceReply_error_tag) {
        return decode_broker_error(&member, error);
    }
    if (member.number != ubii_services_ServiceReply_server_tag) {
        return UBII_ERR_UNEXPECTED_REPLY;
    }
    ubii_servers_Server decoded = ubii_servers_Server_init_zero;
    pb_istream_t stream = pb_istream_from_buffer(member.bytes, member.size);
    if (!pb_decode(&stream, ubii_servers_Server_fields, &decoded)) {
        return UBII_ERR_DECODE;
    }
    *server = decoded;
    return UBII_OK;
}

/* ServiceRequest and ServiceReply bytes: the node's own reply parsing, and the codec helpers of
 * ubii/service_codec.h for programs that carry the bytes themselves. */
#include "ubii/service_codec.h"

#include <string.h>

#include <pb_decode.h>
#include <pb_encode.h>

#include "reply_parse.h"
#include "ubii/wire.h"
#include "ubii/services/serviceRequest.pb.h"
#include "wire_scan.h"

static const char empty_text[] = "";

void ubii__reply_with_status(ubii_reply *reply, ubii_status status)
{
    memset(reply, 0, sizeof *reply);
    reply->status = status;
    reply->error_title = empty_text;
    reply->error_message = empty_text;
}

void ubii__parse_reply(const uint8_t *bytes, size_t size, ubii_reply *reply,
                       ubii_general_Error *error_storage)
{
    ubii__reply_with_status(reply, UBII_OK);

    ubii_wire_scan scan;
    ubii_wire_field field;
    bool malformed = false;
    bool found = false;
    ubii_wire_scan_init(&scan, bytes, size);
    while (ubii_wire_scan_next(&scan, &field, &malformed)) {
        /* Every ServiceReply member is a message; protobuf lets the last one win. */
        if (field.wire_type == PB_WT_STRING) {
            reply->member = field.number;
            reply->bytes = field.bytes;
            reply->size = field.size;
            found = true;
        }
    }
    if (malformed) {
        reply->status = UBII_ERR_DECODE;
        return;
    }
    if (!found) {
        reply->status = UBII_ERR_UNEXPECTED_REPLY;
        return;
    }
    if (reply->member == ubii_services_ServiceReply_error_tag) {
        ubii_general_Error error;
        memset(&error, 0, sizeof error);
        pb_istream_t stream = pb_istream_from_buffer(reply->bytes, reply->size);
        if (!pb_decode(&stream, ubii_general_Error_fields, &error)) {
            reply->status = UBII_ERR_DECODE;
            return;
        }
        *error_storage = error;
        reply->error_title = error_storage->title;
        reply->error_message = error_storage->message;
        reply->status = UBII_ERR_BROKER;
    }
}

/* The reply's own failure, UBII_ERR_WRONG_TYPE for another member, else UBII_OK. */
static ubii_status member_of(const ubii_reply *reply, uint32_t expected_member)
{
    if (reply->status != UBII_OK) {
        return reply->status;
    }
    return reply->member == expected_member ? UBII_OK : UBII_ERR_WRONG_TYPE;
}

ubii_status ubii_reply_decode(const ubii_reply *reply, uint32_t expected_member,
                              const pb_msgdesc_t *fields, void *message)
{
    if (reply == NULL || fields == NULL || message == NULL) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    ubii_status status = member_of(reply, expected_member);
    if (status != UBII_OK) {
        return status;
    }
    pb_istream_t stream = pb_istream_from_buffer(reply->bytes, reply->size);
    return pb_decode(&stream, fields, message) ? UBII_OK : UBII_ERR_DECODE;
}

enum { LIST_ELEMENTS = 1 }; /* every list message of the schema repeats its field 1 */

ubii_status ubii_reply_for_each(const ubii_reply *reply, uint32_t expected_member,
                                uint32_t repeated_field, const pb_msgdesc_t *fields, void *element,
                                ubii_element_fn fn, void *user)
{
    if (reply == NULL || repeated_field == 0 || fields == NULL || element == NULL || fn == NULL) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    ubii_status status = member_of(reply, expected_member);
    if (status != UBII_OK) {
        return status;
    }
    ubii_field_iter it;
    ubii_field_iter_init(&it, reply->bytes, reply->size, repeated_field);
    const uint8_t *bytes;
    size_t size;
    while (ubii_field_iter_next(&it, &bytes, &size)) {
        pb_istream_t stream = pb_istream_from_buffer(bytes, size);
        if (!pb_decode(&stream, fields, element)) {
            return UBII_ERR_DECODE;
        }
        if (!fn(element, user)) {
            return UBII_OK;
        }
    }
    return it.malformed ? UBII_ERR_DECODE : UBII_OK;
}

ubii_status ubii_reply_for_each_string(const ubii_reply *reply, uint32_t expected_member,
                                       ubii_text_fn fn, void *user)
{
    if (reply == NULL || fn == NULL) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    ubii_status status = member_of(reply, expected_member);
    if (status != UBII_OK) {
        return status;
    }
    ubii_field_iter it;
    ubii_field_iter_init(&it, reply->bytes, reply->size, LIST_ELEMENTS);
    const uint8_t *text;
    size_t length;
    while (ubii_field_iter_next(&it, &text, &length)) {
        if (!fn((const char *)text, length, user)) {
            return UBII_OK;
        }
    }
    return it.malformed ? UBII_ERR_DECODE : UBII_OK;
}

ubii_status ubii_encode_topic_request(const char *topic, uint8_t *buffer, size_t capacity,
                                      size_t *length)
{
    if (topic == NULL || topic[0] == '\0' || buffer == NULL || length == NULL) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    ubii_services_ServiceRequest request;
    memset(&request, 0, sizeof request);
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

ubii_status ubii_decode_server_reply(const uint8_t *bytes, size_t length,
                                     ubii_servers_Server *server, ubii_broker_error *error)
{
    if ((bytes == NULL && length > 0) || server == NULL) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    ubii_reply reply;
    ubii_general_Error error_storage;
    ubii__parse_reply(bytes, length, &reply, &error_storage);
    if (reply.status == UBII_ERR_BROKER && error != NULL) {
        copy_truncated(error->title, sizeof error->title, reply.error_title);
        copy_truncated(error->message, sizeof error->message, reply.error_message);
    }
    ubii_servers_Server decoded;
    memset(&decoded, 0, sizeof decoded);
    ubii_status status = ubii_reply_decode(&reply, ubii_services_ServiceReply_server_tag,
                                           ubii_servers_Server_fields, &decoded);
    if (status == UBII_ERR_WRONG_TYPE) {
        status = UBII_ERR_UNEXPECTED_REPLY;
    }
    if (status == UBII_OK) {
        *server = decoded;
    }
    return status;
}

#include "ubii/service_codec.h"

#include <string.h>

#include <pb_decode.h>
#include <pb_encode.h>

#include "node_internal.h"
#include "ubii/services/serviceRequest.pb.h"

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

/* Service calls: encoded into the node's queue when made, sent one at a time (the master's REQ/REP
 * channel allows one outstanding request), each with its own timeout. */
#include <string.h>

#include <pb_encode.h>

#include "copy_string.h"
#include "node_events.h"
#include "reply_parse.h"
#include "service_queue.h"
#include "wire_scan.h"

/* Reserves the queue room for a request of `size` bytes and its call entry; *bytes receives where
 * the encoded request goes. */
static ubii_status reserve_call(ubii_node *node, size_t size, uint32_t timeout_ms,
                                enum ubii__call_owner owner, ubii_reply_fn fn, void *user,
                                uint8_t **bytes)
{
    if (node->call_count == UBII_SERVICE_QUEUE_DEPTH) {
        return UBII_ERR_FULL;
    }
    if (size > UBII_SERVICE_QUEUE_BYTES) {
        return UBII_ERR_TOO_LARGE;
    }
    if (size > UBII_SERVICE_QUEUE_BYTES - node->queue_used) {
        return UBII_ERR_FULL;
    }
    *bytes = node->queue_bytes + node->queue_used;
    ubii__call *call = &node->calls[node->call_count];
    call->offset = node->queue_used;
    call->size = (uint32_t)size;
    call->timeout_ms = timeout_ms != 0 ? timeout_ms : node->config.service_timeout_ms;
    call->fn = (ubii__callback)fn;
    call->user = user;
    call->node_step = owner == UBII__NODE_STEP;
    return UBII_OK;
}

/* Makes the call reserved last part of the queue. */
static void commit_call(ubii_node *node)
{
    node->queue_used += node->calls[node->call_count].size;
    node->call_count++;
}

ubii_status ubii__enqueue(ubii_node *node, const ubii_services_ServiceRequest *request,
                          uint32_t timeout_ms, enum ubii__call_owner owner, ubii_reply_fn fn,
                          void *user)
{
    size_t size = 0;
    if (!pb_get_encoded_size(&size, ubii_services_ServiceRequest_fields, request)) {
        return UBII_ERR_ENCODE;
    }
    uint8_t *bytes = NULL;
    ubii_status status = reserve_call(node, size, timeout_ms, owner, fn, user, &bytes);
    if (status != UBII_OK) {
        return status;
    }
    pb_ostream_t stream = pb_ostream_from_buffer(bytes, size);
    if (!pb_encode(&stream, ubii_services_ServiceRequest_fields, request)) {
        return UBII_ERR_ENCODE;
    }
    commit_call(node);
    return UBII_OK;
}

static ubii__call pop_head(ubii_node *node)
{
    ubii__call head = node->calls[0];
    memmove(node->queue_bytes, node->queue_bytes + head.size, node->queue_used - head.size);
    node->queue_used -= head.size;
    for (uint32_t i = 1; i < node->call_count; ++i) {
        node->calls[i - 1] = node->calls[i];
        node->calls[i - 1].offset -= head.size;
    }
    node->call_count--;
    node->call_sent = false;
    return head;
}

static void deliver(ubii_node *node, const ubii__call *call, const ubii_reply *reply)
{
    if (call->fn != NULL) {
        ((ubii_reply_fn)call->fn)(node, reply, call->user);
    }
}

/* A REQ socket whose request went unanswered cannot send again: start the channel afresh. */
static void reset_service_channel(ubii_node *node)
{
    node->port.vtable->close(node->port.context, UBII_CHANNEL_SERVICE);
    node->port.vtable->open(node->port.context, UBII_CHANNEL_SERVICE, node->service_url, NULL);
}

void ubii__cancel_calls(ubii_node *node, ubii_status status, enum ubii__service_channel_next next)
{
    if (node->call_count == 0) {
        return;
    }
    if (node->call_sent && next == UBII__SERVICE_CHANNEL_REUSED) {
        reset_service_channel(node);
    }
    ubii__call cancelled[UBII_SERVICE_QUEUE_DEPTH];
    uint32_t count = node->call_count;
    memcpy(cancelled, node->calls, count * sizeof cancelled[0]);
    node->call_count = 0;
    node->queue_used = 0;
    node->call_sent = false;
    node->subscription_call_pending = false;

    ubii_reply reply;
    ubii__reply_with_status(&reply, status);
    for (uint32_t i = 0; i < count; ++i) {
        if (!cancelled[i].node_step) {
            deliver(node, &cancelled[i], &reply);
        }
    }
}

static bool send_head(ubii_node *node)
{
    const ubii__call *head = &node->calls[0];
    uint8_t *buffer = NULL;
    ubii_status status = node->port.vtable->send_begin(node->port.context, UBII_CHANNEL_SERVICE,
                                                       head->size, &buffer);
    if (status == UBII_OK) {
        memcpy(buffer, node->queue_bytes + head->offset, head->size);
        status = node->port.vtable->send_commit(node->port.context, UBII_CHANNEL_SERVICE, 0);
    }
    if (status == UBII_ERR_WOULD_BLOCK) {
        return false;
    }
    node->call_sent = true;
    node->call_deadline_ms = ubii__now(node) + head->timeout_ms;
    if (status != UBII_OK) {
        node->call_deadline_ms = ubii__now(node); /* fails as a timeout at once */
    }
    return true;
}

void ubii__service_step(ubii_node *node)
{
    void *port = node->port.context;
    while (node->call_count > 0) {
        ubii_channel_state channel = node->port.vtable->state(port, UBII_CHANNEL_SERVICE);
        if (channel == UBII_CHANNEL_CLOSED || channel == UBII_CHANNEL_LOST) {
            return;
        }
        if (!node->call_sent && !send_head(node)) {
            return;
        }
        const uint8_t *data;
        size_t size;
        unsigned flags;
        ubii_reply reply;
        ubii_general_Error error_storage;
        ubii_status received =
            node->port.vtable->receive(port, UBII_CHANNEL_SERVICE, &data, &size, &flags);
        if (received == UBII_OK || received == UBII_ERR_TOO_LARGE) {
            if (received == UBII_OK) {
                ubii__parse_reply(data, size, &reply, &error_storage);
            } else { /* the port dropped a reply over its size limit */
                ubii__reply_with_status(&reply, UBII_ERR_TOO_LARGE);
            }
            if (reply.status == UBII_ERR_DECODE || reply.status == UBII_ERR_TOO_LARGE) {
                node->stats.decode_errors++;
            }
            ubii__call call = pop_head(node);
            deliver(node, &call, &reply);
            continue;
        }
        if (ubii__now(node) < node->call_deadline_ms) {
            return;
        }
        node->stats.service_timeouts++;
        ubii__call call = pop_head(node);
        reset_service_channel(node);
        ubii__reply_with_status(&reply, UBII_ERR_TIMEOUT);
        deliver(node, &call, &reply);
    }
}

/* ---- the application's calls ----------------------------------------------------------------- */

ubii_status ubii_call(ubii_node *node, const ubii_services_ServiceRequest *request,
                      uint32_t timeout_ms, ubii_reply_fn fn, void *user)
{
    if (node == NULL || request == NULL || request->topic[0] == '\0') {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    if (node->state != UBII_STATE_READY) {
        return UBII_ERR_NOT_CONNECTED;
    }
    return ubii__enqueue(node, request, timeout_ms, UBII__APPLICATION_CALL, fn, user);
}

ubii_status ubii_call_topic(ubii_node *node, const char *topic, uint32_t timeout_ms,
                            ubii_reply_fn fn, void *user)
{
    if (topic == NULL) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    ubii_services_ServiceRequest request;
    memset(&request, 0, sizeof request);
    if (!ubii__copy_string(request.topic, sizeof request.topic, topic)) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    return ubii_call(node, &request, timeout_ms, fn, user);
}

/* A request encoded elsewhere (another protobuf runtime, e.g. the C++ layer's) must at least be
 * protobuf with a topic (field 1), or the master could not route it. */
static bool names_a_topic(const uint8_t *request, size_t size)
{
    ubii_wire_scan scan;
    ubii_wire_field field;
    bool malformed = false;
    bool topic = false;
    ubii_wire_scan_init(&scan, request, size);
    while (ubii_wire_scan_next(&scan, &field, &malformed)) {
        if (field.number == ubii_services_ServiceRequest_topic_tag) {
            topic = field.wire_type == PB_WT_STRING && field.size > 0;
        }
    }
    return !malformed && topic;
}

ubii_status ubii_call_encoded(ubii_node *node, const uint8_t *request, size_t size,
                              uint32_t timeout_ms, ubii_reply_fn fn, void *user)
{
    if (node == NULL || request == NULL || !names_a_topic(request, size)) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    if (node->state != UBII_STATE_READY) {
        return UBII_ERR_NOT_CONNECTED;
    }
    uint8_t *bytes = NULL;
    ubii_status status =
        reserve_call(node, size, timeout_ms, UBII__APPLICATION_CALL, fn, user, &bytes);
    if (status != UBII_OK) {
        return status;
    }
    memcpy(bytes, request, size);
    commit_call(node);
    return UBII_OK;
}

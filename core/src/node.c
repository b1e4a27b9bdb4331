/* The node's lifecycle: the connection sequence as a state machine driven from poll(). */
#include <string.h>

#include <pb_decode.h>

#include "copy_string.h"
#include "node_events.h"
#include "record.h"
#include "service_queue.h"
#include "subscriptions.h"
#include "ubii/servers/server.pb.h"
#include "ubii/url.h"

enum {
    STOP_POLL_SLICE_MS = 20,
    DEFAULT_SERVICE_TIMEOUT_MS = 5000,
    DEFAULT_PING_TIMEOUT_MS = 5000,
    DEFAULT_RECONNECT_MIN_MS = 250,
    DEFAULT_RECONNECT_MAX_MS = 8000,
    LONGEST_WAIT_MS = 0x7fffffff, /* what fits poll()'s int timeout */
    KEEPALIVE_SIZE = 4
};

/* The master's keep-alive on the topic channel, and the node's answer (docs/PROTOCOL.md §2.5). */
static const char keepalive_ping[KEEPALIVE_SIZE] = {'P', 'I', 'N', 'G'};
static const char keepalive_pong[KEEPALIVE_SIZE] = {'P', 'O', 'N', 'G'};

static void on_server_configuration(ubii_node *node, const ubii_reply *reply, void *unused);
static void on_registration(ubii_node *node, const ubii_reply *reply, void *unused);
static void on_release(ubii_node *node, const ubii_reply *reply, void *unused);
static void on_deregistration(ubii_node *node, const ubii_reply *reply, void *unused);

uint64_t ubii_node_monotonic_ms(const ubii_node *node)
{
    return node != NULL ? node->port.vtable->monotonic_ms(node->port.context) : 0;
}

size_t ubii_node_size(void)
{
    return sizeof(ubii_node);
}

void ubii_config_init(ubii_config *config)
{
    if (config == NULL) {
        return;
    }
    memset(config, 0, sizeof *config);
    config->client_name = "libubii";
    config->service_timeout_ms = DEFAULT_SERVICE_TIMEOUT_MS;
    config->ping_timeout_ms = DEFAULT_PING_TIMEOUT_MS;
    config->reconnect_min_ms = DEFAULT_RECONNECT_MIN_MS;
    config->reconnect_max_ms = DEFAULT_RECONNECT_MAX_MS;
    config->stamp_records = true;
}

const char *ubii_state_name(ubii_state state)
{
    switch (state) {
    case UBII_STATE_STOPPED:
        return "stopped";
    case UBII_STATE_CONNECTING:
        return "connecting";
    case UBII_STATE_REGISTERING:
        return "registering";
    case UBII_STATE_OPENING:
        return "opening";
    case UBII_STATE_READY:
        return "ready";
    case UBII_STATE_RECONNECTING:
        return "reconnecting";
    case UBII_STATE_STOPPING:
        return "stopping";
    case UBII_STATE_FAILED:
        return "failed";
    }
    return "unknown";
}

static bool is_url(const char *url)
{
    ubii_url parsed;
    return ubii_url_parse(url, &parsed) == UBII_OK;
}

ubii_status ubii_node_init(ubii_node *node, size_t node_size, const ubii_config *config,
                           ubii_port port)
{
    if (node == NULL || node_size != sizeof(ubii_node) || config == NULL || port.vtable == NULL ||
        !is_url(config->service_url) || (config->topic_url != NULL && !is_url(config->topic_url))) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    memset(node, 0, sizeof *node);
    node->struct_size = node_size;
    node->port = port;
    node->config = *config;
    const char *name = config->client_name != NULL ? config->client_name : "libubii";
    if (!ubii__copy_string(node->service_url, sizeof node->service_url, config->service_url) ||
        (config->topic_url != NULL &&
         !ubii__copy_string(node->topic_url, sizeof node->topic_url, config->topic_url)) ||
        !ubii__copy_string(node->client_name, sizeof node->client_name, name)) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    node->config.service_url = node->service_url;
    node->config.topic_url = config->topic_url != NULL ? node->topic_url : NULL;
    node->config.client_name = node->client_name;
    if (node->config.service_timeout_ms == 0) {
        node->config.service_timeout_ms = DEFAULT_SERVICE_TIMEOUT_MS;
    }
    if (node->config.reconnect_min_ms == 0) {
        node->config.reconnect_min_ms = 1;
    }
    if (node->config.reconnect_max_ms < node->config.reconnect_min_ms) {
        node->config.reconnect_max_ms = node->config.reconnect_min_ms;
    }
    node->next_generation = 1;
    node->state = UBII_STATE_STOPPED;
    return UBII_OK;
}

static void announce(ubii_node *node, ubii_state previous, ubii_state current, ubii_status reason)
{
    if (node->config.on_state != NULL) {
        node->config.on_state(node, previous, current, reason, node->config.on_state_user);
    }
}

static void set_state(ubii_node *node, ubii_state state, ubii_status reason)
{
    ubii_state previous = node->state;
    if (previous == state) {
        return;
    }
    node->state = state;
    if (node->in_poll) {
        announce(node, previous, state, reason);
        return;
    }
    const uint32_t capacity = sizeof node->deferred_states / sizeof node->deferred_states[0];
    if (node->deferred_state_count < capacity) {
        node->deferred_states[node->deferred_state_count].previous = previous;
        node->deferred_states[node->deferred_state_count].current = state;
        node->deferred_states[node->deferred_state_count].reason = reason;
        node->deferred_state_count++;
    }
}

static void close_channels(ubii_node *node)
{
    node->port.vtable->close(node->port.context, UBII_CHANNEL_TOPIC);
    node->port.vtable->close(node->port.context, UBII_CHANNEL_SERVICE);
}

static ubii_status begin_connecting(ubii_node *node)
{
    node->client_id[0] = '\0';
    node->ping_seen = false;
    ubii_status status =
        node->port.vtable->open(node->port.context, UBII_CHANNEL_SERVICE, node->service_url, NULL);
    if (status != UBII_OK) {
        return status;
    }
    ubii_services_ServiceRequest request;
    memset(&request, 0, sizeof request);
    ubii__copy_string(request.topic, sizeof request.topic, UBII_SERVICE_SERVER_CONFIGURATION);
    status = ubii__enqueue(node, &request, 0, UBII__NODE_STEP, on_server_configuration, NULL);
    if (status != UBII_OK) {
        close_channels(node);
        return status;
    }
    set_state(node, UBII_STATE_CONNECTING, UBII_OK);
    return UBII_OK;
}

static void tear_down(ubii_node *node);

ubii_status ubii_node_start(ubii_node *node)
{
    if (node == NULL || node->struct_size != sizeof(ubii_node)) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    if (node->state != UBII_STATE_STOPPED && node->state != UBII_STATE_FAILED) {
        return UBII_ERR_STATE;
    }
    if (node->leaving) {
        tear_down(node); /* a failed connection's deregistration is abandoned */
    }
    node->reconnect_attempts = 0;
    node->stop_requested = false;
    return begin_connecting(node);
}

static uint64_t backoff_ms(const ubii_node *node)
{
    uint64_t wait = node->config.reconnect_min_ms;
    for (uint32_t i = 1; i < node->reconnect_attempts && wait < node->config.reconnect_max_ms;
         ++i) {
        wait *= 2;
    }
    return wait < node->config.reconnect_max_ms ? wait : node->config.reconnect_max_ms;
}

/* Ends the current connection: pending calls cancelled, channels closed, the master's copy of
 * the subscriptions forgotten (the application's stay), no client id. */
static void tear_down(ubii_node *node)
{
    ubii__cancel_calls(node, UBII_ERR_CANCELLED, UBII__SERVICE_CHANNEL_CLOSES);
    close_channels(node);
    ubii__subscriptions_reset_master(node);
    node->client_id[0] = '\0';
    node->leaving = false;
}

/* Queues the release of the node's subscriptions, then its deregistration. A release that does
 * not fit the queue is reported and left out: the deregistration matters more. */
static ubii_status enqueue_deregistration(ubii_node *node)
{
    ubii_status released = ubii__subscriptions_enqueue_release(node, on_release);
    if (released != UBII_OK) {
        ubii__report(node, released, "subscriptions could not be released before deregistering");
    }
    ubii_services_ServiceRequest request;
    memset(&request, 0, sizeof request);
    ubii__copy_string(request.topic, sizeof request.topic, UBII_SERVICE_CLIENT_DEREGISTRATION);
    request.which_type = ubii_services_ServiceRequest_client_tag;
    ubii__copy_string(request.type.client.id, sizeof request.type.client.id, node->client_id);
    ubii__copy_string(request.type.client.name, sizeof request.type.client.name, node->client_name);
    return ubii__enqueue(node, &request, 0, UBII__NODE_STEP, on_deregistration, NULL);
}

/* Ends the current connection like tear_down, except that a node the master registered, whose
 * service channel still works (only its topic data connection failed), releases its
 * subscriptions and deregisters first: every retry registers anew, and the master would otherwise
 * keep one stale client per attempt. The service channel closes when the deregistration is
 * answered or fails (deregistration_done). */
static void leave(ubii_node *node)
{
    void *port = node->port.context;
    bool registered = node->client_id[0] != '\0';
    if (!registered || node->port.vtable->state(port, UBII_CHANNEL_SERVICE) != UBII_CHANNEL_OPEN) {
        tear_down(node);
        return;
    }
    ubii__cancel_calls(node, UBII_ERR_CANCELLED, UBII__SERVICE_CHANNEL_REUSED);
    node->port.vtable->close(port, UBII_CHANNEL_TOPIC);
    if (enqueue_deregistration(node) != UBII_OK) {
        tear_down(node);
        return;
    }
    ubii__subscriptions_reset_master(node);
    node->client_id[0] = '\0';
    node->leaving = true;
}

static void finish_stop(ubii_node *node)
{
    tear_down(node);
    node->stop_requested = false;
    set_state(node, UBII_STATE_STOPPED, UBII_OK);
}

/* Gives up for good. */
static void fail(ubii_node *node, ubii_status reason)
{
    leave(node);
    set_state(node, UBII_STATE_FAILED, reason);
}

/* The deregistration of a stop or of a failed connection was answered, failed or given up.
 * Whatever of it is still queued goes too: the next connection starts with an empty queue. */
static void deregistration_done(ubii_node *node)
{
    bool was_leaving = node->leaving;
    node->leaving = false;
    if (node->state == UBII_STATE_STOPPING) {
        finish_stop(node);
    } else if (was_leaving) {
        ubii__cancel_calls(node, UBII_ERR_CANCELLED, UBII__SERVICE_CHANNEL_CLOSES);
        close_channels(node);
    }
}

/* Gives up on the current connection: close everything, then reconnect after a backoff. */
static void connection_lost(ubii_node *node, ubii_status reason)
{
    if (node->state == UBII_STATE_STOPPING) {
        finish_stop(node);
        return;
    }
    node->reconnect_attempts++;
    node->stats.reconnects++;
    if (node->config.max_reconnect_attempts != 0 &&
        node->reconnect_attempts > node->config.max_reconnect_attempts) {
        fail(node, reason);
        return;
    }
    leave(node);
    node->retry_at_ms = ubii__now(node) + backoff_ms(node);
    set_state(node, UBII_STATE_RECONNECTING, reason);
}

/* Appends `length` bytes of `text` at *used; false when the NUL would not fit. */
static bool append(char *destination, size_t capacity, size_t *used, const char *text,
                   size_t length)
{
    if (length >= capacity - *used) {
        return false;
    }
    memcpy(destination + *used, text, length);
    *used += length;
    destination[*used] = '\0';
    return true;
}

/* "scheme://host:port/..." -> "tcp://host:<port>" for the topic channel. */
static bool derive_topic_url(ubii_node *node, const char *port)
{
    ubii_url service;
    if (ubii_url_parse(node->service_url, &service) != UBII_OK || port[0] == '\0') {
        return false;
    }
    bool ipv6 = memchr(service.host, ':', service.host_length) != NULL;
    char *url = node->topic_url;
    size_t capacity = sizeof node->topic_url;
    size_t used = 0;
    bool fits = append(url, capacity, &used, "tcp://", 6) &&
                append(url, capacity, &used, "[", ipv6 ? 1 : 0) &&
                append(url, capacity, &used, service.host, service.host_length) &&
                append(url, capacity, &used, "]", ipv6 ? 1 : 0) &&
                append(url, capacity, &used, ":", 1) &&
                append(url, capacity, &used, port, strlen(port));
    return fits && is_url(url);
}

static void on_server_configuration(ubii_node *node, const ubii_reply *reply, void *unused)
{
    (void)unused;
    if (node->state != UBII_STATE_CONNECTING) {
        return;
    }
    ubii_servers_Server server;
    memset(&server, 0, sizeof server);
    ubii_status status = ubii_reply_decode(reply, ubii_services_ServiceReply_server_tag,
                                           ubii_servers_Server_fields, &server);
    if (status != UBII_OK && status != UBII_ERR_TOO_LARGE) {
        ubii__report(node, status, "server configuration failed");
        connection_lost(node, status);
        return;
    }
    if (status == UBII_ERR_TOO_LARGE && node->config.topic_url == NULL) {
        /* A small port cannot take the configuration (its constants make it ~6.5 kB); only a
         * configured topic URL lets the node go on without it. */
        ubii__report(node, status, "server configuration too large for the port; set topic_url");
        connection_lost(node, status);
        return;
    }
    if (node->config.topic_url == NULL && !derive_topic_url(node, server.port_topic_data_zmq)) {
        ubii__report(node, UBII_ERR_UNEXPECTED_REPLY, "the master reported no topic data port");
        connection_lost(node, UBII_ERR_UNEXPECTED_REPLY);
        return;
    }
    ubii_services_ServiceRequest request;
    memset(&request, 0, sizeof request);
    ubii__copy_string(request.topic, sizeof request.topic, UBII_SERVICE_CLIENT_REGISTRATION);
    request.which_type = ubii_services_ServiceRequest_client_tag;
    ubii__copy_string(request.type.client.name, sizeof request.type.client.name, node->client_name);
    request.type.client.is_dedicated_processing_node = node->config.is_dedicated_processing_node;
    if (node->complete_registration != NULL) {
        node->complete_registration(node, &request.type.client);
    }
    status = ubii__enqueue(node, &request, 0, UBII__NODE_STEP, on_registration, NULL);
    if (status != UBII_OK) {
        /* TOO_LARGE: the offered processing modules (ubii/processing.h) overfill the queue. */
        ubii__report(node, status, "cannot queue the registration request");
        connection_lost(node, status);
        return;
    }
    set_state(node, UBII_STATE_REGISTERING, UBII_OK);
}

static void on_registration(ubii_node *node, const ubii_reply *reply, void *unused)
{
    (void)unused;
    if (node->state != UBII_STATE_REGISTERING) {
        return;
    }
    ubii_clients_Client client;
    memset(&client, 0, sizeof client);
    ubii_status status = ubii_reply_decode(reply, ubii_services_ServiceReply_client_tag,
                                           ubii_clients_Client_fields, &client);
    if (status == UBII_OK && client.id[0] == '\0') {
        status = UBII_ERR_UNEXPECTED_REPLY;
    }
    if (status != UBII_OK) {
        ubii__report(node, status,
                     reply->error_message[0] ? reply->error_message : "registration failed");
        connection_lost(node, status);
        return;
    }
    if (!ubii__copy_string(node->client_id, sizeof node->client_id, client.id)) {
        ubii__report(node, UBII_ERR_UNEXPECTED_REPLY,
                     "the master's client id is longer than UBII_MAX_CLIENT_ID_SIZE");
        fail(node, UBII_ERR_UNEXPECTED_REPLY);
        return;
    }
    status = node->port.vtable->open(node->port.context, UBII_CHANNEL_TOPIC, node->topic_url,
                                     node->client_id);
    if (status == UBII_ERR_UNSUPPORTED || status == UBII_ERR_INVALID_ARGUMENT) {
        /* A topic URL the port cannot serve: a configuration error that no retry mends. */
        ubii__report(node, status, "the port cannot open the topic data URL");
        fail(node, status);
        return;
    }
    if (status != UBII_OK) {
        ubii__report(node, status, "cannot open the topic data connection");
        connection_lost(node, status);
        return;
    }
    node->open_deadline_ms = ubii__now(node) + node->config.service_timeout_ms;
    set_state(node, UBII_STATE_OPENING, UBII_OK);
}

static void on_release(ubii_node *node, const ubii_reply *reply, void *unused)
{
    (void)unused;
    if (reply->status != UBII_OK && reply->status != UBII_ERR_CANCELLED) {
        ubii__report(node, reply->status, "releasing the subscriptions failed");
    }
    if (reply->status == UBII_ERR_TIMEOUT &&
        (node->leaving || node->state == UBII_STATE_STOPPING)) {
        /* A master that does not answer will not answer the deregistration either: leaving
         * stays bounded by one service timeout. */
        deregistration_done(node);
    }
}

static void on_deregistration(ubii_node *node, const ubii_reply *reply, void *unused)
{
    (void)unused;
    if (reply->status != UBII_OK && reply->status != UBII_ERR_CANCELLED) {
        ubii__report(node, reply->status, "deregistration failed");
    }
    deregistration_done(node);
}

static void begin_stopping(ubii_node *node)
{
    node->stop_requested = false;
    if (node->state == UBII_STATE_STOPPED || node->state == UBII_STATE_STOPPING) {
        return;
    }
    if (node->leaving) {
        set_state(node, UBII_STATE_STOPPING, UBII_OK); /* its deregistration is under way */
        return;
    }
    bool registered = node->state == UBII_STATE_OPENING || node->state == UBII_STATE_READY;
    if (!registered) {
        finish_stop(node);
        return;
    }
    ubii__cancel_calls(node, UBII_ERR_CANCELLED, UBII__SERVICE_CHANNEL_REUSED);
    if (enqueue_deregistration(node) != UBII_OK) {
        finish_stop(node);
        return;
    }
    set_state(node, UBII_STATE_STOPPING, UBII_OK);
}

ubii_status ubii_node_stop(ubii_node *node)
{
    if (node == NULL || node->struct_size != sizeof(ubii_node)) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    if (node->state != UBII_STATE_STOPPED) {
        node->stop_requested = true;
    }
    return UBII_OK;
}

static void answer_ping(ubii_node *node, unsigned flags)
{
    uint8_t *buffer = NULL;
    ubii_status status = node->port.vtable->send_begin(node->port.context, UBII_CHANNEL_TOPIC,
                                                       KEEPALIVE_SIZE, &buffer);
    if (status == UBII_OK) {
        memcpy(buffer, keepalive_pong, KEEPALIVE_SIZE);
        status = node->port.vtable->send_commit(node->port.context, UBII_CHANNEL_TOPIC, flags);
    }
    if (status != UBII_OK) {
        ubii__report(node, status, "could not answer the master's PING");
        return;
    }
    node->ping_seen = true;
    node->last_ping_ms = ubii__now(node);
    node->stats.pings++;
}

static bool topic_channel_in_use(const ubii_node *node)
{
    return node->state == UBII_STATE_OPENING || node->state == UBII_STATE_READY ||
           node->state == UBII_STATE_STOPPING;
}

/* Drains the topic channel whenever it is open, so nothing piles up in the port: PINGs are
 * answered in every such state, records are passed on only when READY (before, no subscription
 * is confirmed; while stopping, the application has asked to hear no more). */
static void receive_topic_data(ubii_node *node)
{
    const uint8_t *data;
    size_t size;
    unsigned flags;
    ubii_status status;
    while (topic_channel_in_use(node) &&
           ((status = node->port.vtable->receive(node->port.context, UBII_CHANNEL_TOPIC, &data,
                                                 &size, &flags)) == UBII_OK ||
            status == UBII_ERR_TOO_LARGE)) {
        if (status == UBII_ERR_TOO_LARGE) {
            node->stats.decode_errors++;
            ubii__report(node, status, "topic data over the port's size limit was dropped");
        } else if (size == KEEPALIVE_SIZE && memcmp(data, keepalive_ping, KEEPALIVE_SIZE) == 0) {
            answer_ping(node, flags);
        } else if (node->state == UBII_STATE_READY) {
            ubii__handle_topic_data(node, data, size);
        }
    }
}

static void check_channels(ubii_node *node, uint64_t now)
{
    ubii_state state = node->state;
    if (state == UBII_STATE_STOPPED || state == UBII_STATE_RECONNECTING ||
        state == UBII_STATE_FAILED) {
        return;
    }
    void *port = node->port.context;
    if (node->port.vtable->state(port, UBII_CHANNEL_SERVICE) == UBII_CHANNEL_LOST) {
        connection_lost(node, UBII_ERR_TRANSPORT);
        return;
    }
    if (state != UBII_STATE_OPENING && state != UBII_STATE_READY) {
        return;
    }
    ubii_channel_state topic = node->port.vtable->state(port, UBII_CHANNEL_TOPIC);
    if (topic == UBII_CHANNEL_LOST) {
        connection_lost(node, UBII_ERR_TRANSPORT);
    } else if (state == UBII_STATE_OPENING && topic == UBII_CHANNEL_OPEN) {
        node->reconnect_attempts = 0;
        set_state(node, UBII_STATE_READY, UBII_OK);
        node->subscriptions_dirty = true;
    } else if (state == UBII_STATE_OPENING && now >= node->open_deadline_ms) {
        ubii__report(node, UBII_ERR_TIMEOUT, "the topic data connection did not open");
        connection_lost(node, UBII_ERR_TIMEOUT);
    }
}

static void step(ubii_node *node)
{
    uint64_t now = ubii__now(node);
    if (node->stop_requested) {
        begin_stopping(node);
    }
    check_channels(node, now);
    receive_topic_data(node);
    ubii__service_step(node);
    if (node->leaving) {
        /* A lost service channel never answers: the deregistration is given up. */
        ubii_channel_state service =
            node->port.vtable->state(node->port.context, UBII_CHANNEL_SERVICE);
        if (service == UBII_CHANNEL_LOST || service == UBII_CHANNEL_CLOSED) {
            deregistration_done(node);
        }
    }
    now = ubii__now(node);
    if (node->state == UBII_STATE_READY && node->ping_seen && node->config.ping_timeout_ms != 0 &&
        now - node->last_ping_ms > node->config.ping_timeout_ms) {
        ubii__report(node, UBII_ERR_TIMEOUT, "no PING from the master");
        connection_lost(node, UBII_ERR_TIMEOUT);
    }
    if (node->state == UBII_STATE_RECONNECTING && !node->leaving && now >= node->retry_at_ms) {
        ubii_status status = begin_connecting(node);
        if (status != UBII_OK) {
            connection_lost(node, status);
        }
    }
    if (node->state == UBII_STATE_READY) {
        ubii__subscriptions_sync(node);
    }
}

int ubii_node_next_timeout_ms(ubii_node *node)
{
    if (node == NULL) {
        return -1;
    }
    uint64_t now = ubii__now(node);
    uint64_t deadline = UINT64_MAX;
    bool unsent_call = node->call_count > 0 && !node->call_sent;
    bool unsent_subscriptions = node->state == UBII_STATE_READY && node->subscriptions_dirty &&
                                !node->subscription_call_pending;
    if (node->stop_requested || node->deferred_state_count > 0 || unsent_call ||
        unsent_subscriptions) {
        return 0; /* work is waiting: do not sleep before it is sent */
    }
    if (node->call_sent && node->call_deadline_ms < deadline) {
        deadline = node->call_deadline_ms;
    }
    if (node->state == UBII_STATE_RECONNECTING && !node->leaving && node->retry_at_ms < deadline) {
        deadline = node->retry_at_ms;
    }
    if (node->state == UBII_STATE_OPENING && node->open_deadline_ms < deadline) {
        deadline = node->open_deadline_ms;
    }
    if (node->state == UBII_STATE_READY && node->ping_seen && node->config.ping_timeout_ms != 0) {
        uint64_t ping_deadline = node->last_ping_ms + node->config.ping_timeout_ms + 1;
        if (ping_deadline < deadline) {
            deadline = ping_deadline;
        }
    }
    if (deadline == UINT64_MAX) {
        return -1;
    }
    if (deadline <= now) {
        return 0;
    }
    uint64_t wait = deadline - now;
    return wait > LONGEST_WAIT_MS ? LONGEST_WAIT_MS : (int)wait;
}

ubii_status ubii_node_poll(ubii_node *node, int timeout_ms)
{
    if (node == NULL || node->struct_size != sizeof(ubii_node)) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    if (node->in_poll) {
        return UBII_ERR_STATE;
    }
    node->in_poll = true;
    for (uint32_t i = 0; i < node->deferred_state_count; ++i) {
        announce(node, node->deferred_states[i].previous, node->deferred_states[i].current,
                 node->deferred_states[i].reason);
    }
    node->deferred_state_count = 0;

    int wait = timeout_ms < 0 ? -1 : timeout_ms;
    int due = ubii_node_next_timeout_ms(node);
    if (due >= 0 && (wait < 0 || due < wait)) {
        wait = due;
    }
    ubii_status status =
        node->port.vtable->wait(node->port.context, wait < 0 ? LONGEST_WAIT_MS : wait);
    step(node);
    node->in_poll = false;
    return status == UBII_ERR_WOULD_BLOCK || status == UBII_ERR_TIMEOUT ? UBII_OK : status;
}

ubii_status ubii_node_stop_wait(ubii_node *node, int timeout_ms)
{
    ubii_status status = ubii_node_stop(node);
    if (status != UBII_OK) {
        return status;
    }
    if (node->in_poll) {
        return UBII_ERR_STATE;
    }
    uint64_t deadline = ubii__now(node) + (uint64_t)(timeout_ms > 0 ? timeout_ms : 0);
    while (node->state != UBII_STATE_STOPPED && ubii__now(node) < deadline) {
        ubii_node_poll(node, STOP_POLL_SLICE_MS);
    }
    if (node->state != UBII_STATE_STOPPED) {
        node->in_poll = true;
        finish_stop(node);
        node->in_poll = false;
        return UBII_ERR_TIMEOUT;
    }
    return UBII_OK;
}

ubii_state ubii_node_state(const ubii_node *node)
{
    return node != NULL ? node->state : UBII_STATE_STOPPED;
}

const char *ubii_node_client_id(const ubii_node *node)
{
    return node != NULL ? node->client_id : "";
}

void ubii_node_stats(const ubii_node *node, ubii_stats *stats)
{
    if (node != NULL && stats != NULL) {
        *stats = node->stats;
    }
}

int ubii_node_pollfds(ubii_node *node, ubii_pollfd *fds, int capacity)
{
    if (node == NULL || (fds == NULL && capacity > 0)) {
        return 0;
    }
    return node->port.vtable->pollfds(node->port.context, fds, capacity);
}

/* WebSocket topic data (ws://, wss://) and binary HTTP services (http://, https://) through
 * libwebsockets, and the connections, queues and frame writing they share with the in-thread ZMQ
 * engine (lws_zmtp.c).
 *
 * Debian's libwebsockets is built without external-poll support, so lws drives the waiting: it
 * alone knows when its sockets need POLLOUT (e.g. during a non-blocking connect). ZMQ's fds are
 * adopted into it (as dup'd raw descriptors) so that ZMQ traffic wakes it as well, and a
 * scheduled timer bounds every wait.
 *
 * Each WebSocket, HTTP or ZMTP connection has a record that outlives the channel if need be:
 * closing a channel detaches the record and asks lws to kill the connection; lws frees it on
 * WSI_DESTROY. */
#define _POSIX_C_SOURCE 200809L /* dup */

#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <libwebsockets.h>

#include "lws_internal.h"
#include "websocket_frame.h"
#include "zmtp_wire.h"

/* ---- queues -----------------------------------------------------------------------------------
 */

static queued_message *new_message(size_t size, size_t headroom)
{
    queued_message *message = malloc(sizeof *message + headroom + size);
    if (message == NULL) {
        return NULL;
    }
    message->next = NULL;
    message->size = size;
    message->flags = 0;
    message->data = (uint8_t *)(message + 1) + headroom;
    return message;
}

static void push(message_queue *queue, queued_message *message)
{
    if (queue->tail != NULL) {
        queue->tail->next = message;
    } else {
        queue->head = message;
    }
    queue->tail = message;
    queue->count++;
    queue->bytes += message->size;
}

static queued_message *pop(message_queue *queue)
{
    queued_message *message = queue->head;
    if (message != NULL) {
        queue->head = message->next;
        if (queue->head == NULL) {
            queue->tail = NULL;
        }
        queue->count--;
        queue->bytes -= message->size;
        message->next = NULL;
    }
    return message;
}

static void clear(message_queue *queue)
{
    queued_message *message;
    while ((message = pop(queue)) != NULL) {
        free(message);
    }
}

/* ---- helpers ----------------------------------------------------------------------------------
 */

void ubii__lws_set_error(ubii_linux_port *port, const char *what, const char *detail)
{
    snprintf(port->last_error, sizeof port->last_error, "%s%s%s", what, detail ? ": " : "",
             detail ? detail : "");
}

lws_channel *ubii__lws_channel_of(lws_connection *connection)
{
    return connection->port != NULL ? &connection->port->channels[connection->which].lws : NULL;
}

void ubii__lws_lose(lws_connection *connection, const char *what, const char *detail)
{
    /* The first reason is the one to tell: the close that follows a refusal is no news. */
    if (connection->port == NULL ||
        connection->port->channels[connection->which].state == UBII_CHANNEL_LOST) {
        return;
    }
    ubii__lws_set_error(connection->port, what, detail);
    connection->port->channels[connection->which].state = UBII_CHANNEL_LOST;
}

static void detach(lws_connection *connection)
{
    free(connection->assembly);
    connection->assembly = NULL;
    free(connection->batch);
    connection->batch = NULL;
    free(connection->sending);
    connection->sending = NULL;
    free(connection->request);
    connection->request = NULL;
    connection->port = NULL;
}

/* Parses scheme://host[:port][/path]; IPv6 hosts in brackets. tcp:// needs the port. */
static bool parse_url(const char *url, lws_channel *ch, transport_kind *kind)
{
    static const struct {
        const char *scheme;
        transport_kind kind;
        bool tls;
        int default_port;
    } schemes[] = {{"ws://", TRANSPORT_WEBSOCKET, false, 80},
                   {"wss://", TRANSPORT_WEBSOCKET, true, 443},
                   {"http://", TRANSPORT_HTTP, false, 80},
                   {"https://", TRANSPORT_HTTP, true, 443},
                   {"tcp://", TRANSPORT_ZMTP, false, 0}};
    size_t which = 0;
    while (strncmp(url, schemes[which].scheme, strlen(schemes[which].scheme)) != 0) {
        if (++which == sizeof schemes / sizeof schemes[0]) {
            return false;
        }
    }
    *kind = schemes[which].kind;
    ch->tls = schemes[which].tls;
    const char *rest = url + strlen(schemes[which].scheme);
    const char *host_end;
    const char *host = rest;
    if (*rest == '[') {
        host = rest + 1;
        host_end = strchr(host, ']');
        if (host_end == NULL) {
            return false;
        }
        rest = host_end + 1;
    } else {
        host_end = rest + strcspn(rest, ":/?");
        rest = host_end;
    }
    size_t host_length = (size_t)(host_end - host);
    if (host_length == 0 || host_length >= sizeof ch->host) {
        return false;
    }
    memcpy(ch->host, host, host_length);
    ch->host[host_length] = '\0';
    ch->port = schemes[which].default_port;
    if (*rest == ':') {
        char *end;
        long port = strtol(rest + 1, &end, 10);
        if (end == rest + 1 || port <= 0 || port > 65535) {
            return false;
        }
        ch->port = (int)port;
        rest = end;
    }
    if (ch->port == 0 || (*kind == TRANSPORT_ZMTP && *rest != '\0')) {
        return false; /* tcp:// is host and port, nothing more */
    }
    const char *path = *rest != '\0' ? rest : "/";
    if (strlen(path) + 1 > sizeof ch->path) {
        return false;
    }
    snprintf(ch->path, sizeof ch->path, "%s%s", path[0] == '/' ? "" : "/", path);
    return true;
}

/* ---- outgoing frames (WebSocket and ZMTP) ------------------------------------------------------
 */

static const uint8_t *next_mask(lws_connection *connection, struct lws *wsi)
{
    if (connection->masks_left < 4) {
        if (lws_get_random(lws_get_context(wsi), connection->masks, MASK_POOL) != MASK_POOL) {
            return NULL;
        }
        connection->masks_left = MASK_POOL;
    }
    connection->masks_left -= 4;
    return connection->masks + connection->masks_left;
}

static size_t framing_size(const lws_connection *connection, size_t size)
{
    return connection->zmtp ? ubii__zmtp_header_size(connection->zmtp_request, size)
                            : ubii__ws_client_header_size(size);
}

/* Frames the message at `payload` in place: header written just before it, and for WebSocket
 * the payload masked. Returns where the frame starts, or NULL without a masking key. */
static uint8_t *frame_in_place(lws_connection *connection, struct lws *wsi, uint8_t *payload,
                               size_t size, unsigned flags)
{
    uint8_t *header = payload - framing_size(connection, size);
    if (connection->zmtp) {
        ubii__zmtp_write_header(header, connection->zmtp_request, size);
        return header;
    }
    const uint8_t *mask = next_mask(connection, wsi);
    if (mask == NULL) {
        return NULL;
    }
    int opcode = flags & UBII_MESSAGE_TEXT ? UBII_WS_OPCODE_TEXT : UBII_WS_OPCODE_BINARY;
    ubii__ws_write_client_header(header, opcode, size, mask);
    ubii__ws_mask(payload, size, mask);
    return header;
}

/* Writes the next piece of the frame in `sending`, at most RX_CHUNK bytes: lws sends a larger write
 * only in part and keeps the rest, to send one piece per service pass. */
static const char *write_piece(lws_connection *connection, struct lws *wsi)
{
    size_t piece = connection->sending_left < RX_CHUNK ? connection->sending_left : RX_CHUNK;
    if (lws_write(wsi, connection->sending_next, piece, LWS_WRITE_RAW) < 0) {
        return "write to the master failed";
    }
    connection->sending_next += piece;
    connection->sending_left -= piece;
    if (connection->sending_left == 0) {
        free(connection->sending);
        connection->sending = NULL;
    }
    return NULL;
}

/* Writes the outbox's first messages as whole frames in one lws_write: as many as fit
 * BATCH_BYTES; or starts one larger message, framed in its own headroom, that goes in pieces.
 * (libwebsockets would frame each WebSocket message with a write, and a read of its random
 * source, of its own.) The frames go as raw bytes; lws keeps whatever the socket does not take
 * and sends it before anything else. */
static const char *write_frames(lws_connection *connection, lws_channel *ch, struct lws *wsi)
{
    static const char no_mask[] = "no random bytes for WebSocket masking keys";
    queued_message *message = ch->outbox.head;
    size_t framed = framing_size(connection, message->size) + message->size;
    uint8_t *start;
    size_t length;
    if (framed > BATCH_BYTES) {
        pop(&ch->outbox);
        start = frame_in_place(connection, wsi, message->data, message->size, message->flags);
        if (start == NULL) {
            free(message);
            return no_mask;
        }
        connection->sending = message;
        connection->sending_next = start;
        connection->sending_left = framed;
        return write_piece(connection, wsi);
    }
    if (connection->batch == NULL && (connection->batch = malloc(LWS_PRE + BATCH_BYTES)) == NULL) {
        return "out of memory for outgoing frames";
    }
    start = connection->batch + LWS_PRE;
    length = 0;
    while ((message = ch->outbox.head) != NULL &&
           length + (framed = framing_size(connection, message->size) + message->size) <=
               BATCH_BYTES) {
        pop(&ch->outbox);
        uint8_t *payload = start + length + (framed - message->size);
        memcpy(payload, message->data, message->size);
        bool framed_ok =
            frame_in_place(connection, wsi, payload, message->size, message->flags) != NULL;
        free(message);
        if (!framed_ok) {
            return no_mask;
        }
        length += framed;
    }
    return lws_write(wsi, start, length, LWS_WRITE_RAW) < 0 ? "write to the master failed" : NULL;
}

static bool output_waits(const lws_connection *connection, const lws_channel *ch)
{
    return connection->sending != NULL || ch->outbox.count > 0;
}

int ubii__lws_write_outbox(lws_connection *connection, lws_channel *ch, struct lws *wsi)
{
    /* As much as the socket takes now: one message per callback would cap a node polled once per
     * frame at one message per frame. */
    while (output_waits(connection, ch)) {
        const char *failure = connection->sending != NULL ? write_piece(connection, wsi)
                                                          : write_frames(connection, ch, wsi);
        if (failure != NULL) {
            ubii__lws_lose(connection, failure, NULL);
            return -1;
        }
        if (!output_waits(connection, ch) || lws_send_pipe_choked(wsi)) {
            break;
        }
    }
    if (output_waits(connection, ch)) {
        lws_callback_on_writable(wsi);
    }
    return 0;
}

lws_connection *ubii__lws_new_connection(ubii_linux_port *port, ubii_channel which)
{
    lws_connection *connection = calloc(1, sizeof *connection);
    if (connection != NULL) {
        connection->port = port;
        connection->owner = port;
        connection->which = which;
        port->lws_connections++;
    }
    return connection;
}

void ubii__lws_connect(ubii_linux_port *port, ubii_channel which, lws_connection *connection,
                       struct lws_client_connect_info *info, const char *failure)
{
    lws_channel *ch = &port->channels[which].lws;
    ch->connection = connection;
    connection->wsi = lws_client_connect_via_info(info);
    if (connection->wsi == NULL && ch->connection == connection) {
        /* Failed at once (lws may already have reported it and freed nothing). */
        ch->connection = NULL;
        port->lws_connections--;
        detach(connection);
        free(connection);
        port->channels[which].state = UBII_CHANNEL_LOST;
        ubii__lws_set_error(port, failure, NULL);
    }
}

void ubii__lws_connection_destroyed(lws_connection *connection, struct lws *wsi, const char *what)
{
    lws_channel *ch = ubii__lws_channel_of(connection);
    if (ch != NULL) {
        ch->connection = NULL;
        if (connection->port->channels[connection->which].state != UBII_CHANNEL_CLOSED) {
            ubii__lws_lose(connection, what, NULL);
        }
    }
    connection->owner->lws_connections--;
    detach(connection);
    free(connection);
    lws_set_opaque_user_data(wsi, NULL);
}

/* ---- the lws context ----------------------------------------------------------------------------
 */

static int on_websocket(struct lws *wsi, enum lws_callback_reasons reason, void *user, void *in,
                        size_t len);
static int on_http(struct lws *wsi, enum lws_callback_reasons reason, void *user, void *in,
                   size_t len);
static int on_zmq_wakeup(struct lws *wsi, enum lws_callback_reasons reason, void *user, void *in,
                         size_t len);

static const struct lws_protocols protocols[] = {
    {"ubii-ws", on_websocket, 0, RX_CHUNK, 0, NULL, 0},
    {"ubii-http", on_http, 0, RX_CHUNK, 0, NULL, 0},
    {"ubii-zmq-wakeup", on_zmq_wakeup, 0, 0, 0, NULL, 0},
    {"ubii-zmtp", ubii__lws_on_zmtp, 0, RX_CHUNK, 0, NULL, 0},
    {"ubii-wake", ubii__lws_on_wake, 0, 0, 0, NULL, 0},
    {NULL, NULL, 0, 0, 0, NULL, 0}};

bool ubii__lws_start(ubii_linux_port *port)
{
    if (port->lws != NULL) {
        return true;
    }
    if (port->options.libwebsockets_log_level != 0) {
        lws_set_log_level(port->options.libwebsockets_log_level, NULL);
    }
    struct lws_context_creation_info info;
    memset(&info, 0, sizeof info);
    info.port = CONTEXT_PORT_NO_LISTEN;
    info.protocols = protocols;
    /* TLS needs lws's OpenSSL set-up, which is process-wide: see enable_tls in port_linux.h. */
    info.options = port->options.enable_tls ? LWS_SERVER_OPTION_DO_SSL_GLOBAL_INIT : 0;
    info.gid = -1;
    info.uid = -1;
    /* lws reads a socket into this buffer, once per service pass (4 KB by default). */
    info.pt_serv_buf_size = LWS_PRE + RX_CHUNK;
    info.user = port;
    port->lws = lws_create_context(&info);
    if (port->lws == NULL) {
        ubii__lws_set_error(port, "libwebsockets context could not be created", NULL);
        return false;
    }
    port->vhost = lws_get_vhost_by_name(port->lws, "default");
    ubii__lws_adopt_wake(port);
    for (int i = 0; i < UBII_CHANNEL_COUNT; ++i) {
        if (port->channels[i].kind == TRANSPORT_ZMQ) {
            ubii__lws_adopt_zmq(port, port->channels[i].zmq.socket);
            ubii__lws_adopt_zmq(port, port->channels[i].zmq.monitor);
        }
    }
    return true;
}

void ubii__lws_destroy(ubii_linux_port *port)
{
    if (port->lws != NULL) {
        lws_context_destroy(port->lws);
        port->lws = NULL;
        port->vhost = NULL;
    }
    for (int i = 0; i < MAX_ZMQ_WAKEUPS; ++i) {
        free(port->wakeups[i]);
        port->wakeups[i] = NULL;
    }
}

/* ---- ZMQ fds inside lws
 * -------------------------------------------------------------------------- */

void ubii__lws_adopt_zmq(ubii_linux_port *port, void *socket)
{
    if (port->lws == NULL || socket == NULL) {
        return;
    }
    int fd = -1;
    size_t length = sizeof fd;
    if (zmq_getsockopt(socket, ZMQ_FD, &fd, &length) != 0) {
        return;
    }
    for (int i = 0; i < MAX_ZMQ_WAKEUPS; ++i) {
        if (port->wakeups[i] != NULL) {
            continue;
        }
        zmq_wakeup *wakeup = calloc(1, sizeof *wakeup);
        if (wakeup == NULL) {
            return;
        }
        /* lws closes what it adopts: it gets a duplicate, never libzmq's own fd. */
        lws_adopt_desc_t desc;
        memset(&desc, 0, sizeof desc);
        desc.vh = port->vhost;
        desc.type = LWS_ADOPT_RAW_FILE_DESC;
        desc.fd.filefd = dup(fd);
        desc.vh_prot_name = "ubii-zmq-wakeup";
        desc.opaque = wakeup;
        wakeup->port = port;
        wakeup->socket = socket;
        port->wakeups[i] = wakeup;
        wakeup->wsi = desc.fd.filefd >= 0 ? lws_adopt_descriptor_vhost_via_info(&desc) : NULL;
        if (wakeup->wsi == NULL) {
            port->wakeups[i] = NULL;
            free(wakeup);
        }
        return;
    }
}

void ubii__lws_release_zmq(ubii_linux_port *port, void *socket)
{
    for (int i = 0; i < MAX_ZMQ_WAKEUPS; ++i) {
        zmq_wakeup *wakeup = port->wakeups[i];
        if (wakeup == NULL || wakeup->socket != socket) {
            continue;
        }
        wakeup->socket = NULL; /* its callback must not touch the socket about to close */
        port->wakeups[i] = NULL;
        if (wakeup->wsi != NULL) {
            lws_set_timeout(wakeup->wsi, PENDING_TIMEOUT_USER_OK, LWS_TO_KILL_SYNC);
        } else {
            free(wakeup);
        }
    }
}

static int on_zmq_wakeup(struct lws *wsi, enum lws_callback_reasons reason, void *user, void *in,
                         size_t len)
{
    (void)user;
    (void)in;
    (void)len;
    zmq_wakeup *wakeup = lws_get_opaque_user_data(wsi);
    if (wakeup == NULL) {
        return 0;
    }
    if (reason == LWS_CALLBACK_RAW_RX_FILE && wakeup->socket != NULL) {
        /* Reading ZMQ_EVENTS lets libzmq consume its signal, so the fd stops being readable. */
        int events = 0;
        size_t length = sizeof events;
        zmq_getsockopt(wakeup->socket, ZMQ_EVENTS, &events, &length);
    } else if (reason == LWS_CALLBACK_RAW_CLOSE_FILE) {
        lws_set_opaque_user_data(wsi, NULL);
        if (wakeup->socket == NULL) {
            free(wakeup); /* released: nobody else holds it */
        } else {
            wakeup->wsi = NULL;
        }
    }
    return 0;
}

/* ---- WebSocket ---------------------------------------------------------------------------------
 */

bool ubii__lws_append(lws_connection *connection, const void *in, size_t len, size_t limit)
{
    if (connection->assembled + len > limit) {
        return false;
    }
    if (connection->assembled + len > connection->assembly_capacity) {
        size_t capacity = connection->assembly_capacity ? connection->assembly_capacity : 4096;
        while (capacity < connection->assembled + len) {
            capacity *= 2;
        }
        uint8_t *grown = realloc(connection->assembly, capacity);
        if (grown == NULL) {
            return false;
        }
        connection->assembly = grown;
        connection->assembly_capacity = capacity;
    }
    memcpy(connection->assembly + connection->assembled, in, len);
    connection->assembled += len;
    connection->owner->lws_bytes_read += len;
    return true;
}

void ubii__lws_deliver(lws_connection *connection, lws_channel *ch, const uint8_t *data,
                       size_t size, unsigned flags)
{
    queued_message *message = new_message(size, 0);
    if (message == NULL) {
        ubii__lws_lose(connection, "out of memory for a received message", NULL);
        return;
    }
    memcpy(message->data, data, size);
    message->flags = flags;
    push(&ch->inbox, message);
    if (ch->inbox.count > INBOX_LIMIT_COUNT || ch->inbox.bytes > INBOX_LIMIT_BYTES) {
        ubii__lws_lose(connection, "received messages piled up unread (is the node being polled?)",
                       NULL);
    }
}

static void deliver_assembled(lws_connection *connection, lws_channel *ch)
{
    ubii__lws_deliver(connection, ch, connection->assembly, connection->assembled,
                      connection->assembly_flags);
    connection->assembled = 0;
}

static int on_websocket(struct lws *wsi, enum lws_callback_reasons reason, void *user, void *in,
                        size_t len)
{
    (void)user;
    lws_connection *connection = lws_get_opaque_user_data(wsi);
    if (connection == NULL) {
        return 0;
    }
    lws_channel *ch = ubii__lws_channel_of(connection);
    switch (reason) {
    case LWS_CALLBACK_CLIENT_APPEND_HANDSHAKE_HEADER:
        connection->setup_written = true; /* lws writes the upgrade request now */
        break;
    case LWS_CALLBACK_CLIENT_ESTABLISHED:
        if (ch != NULL) {
            connection->port->channels[connection->which].state = UBII_CHANNEL_OPEN;
            if (ch->outbox.count > 0) {
                lws_callback_on_writable(wsi);
            }
        }
        break;
    case LWS_CALLBACK_CLIENT_RECEIVE:
        if (ch == NULL) {
            return -1;
        }
        if (lws_is_first_fragment(wsi)) {
            connection->assembled = 0;
            connection->assembly_flags = lws_frame_is_binary(wsi) ? 0 : UBII_MESSAGE_TEXT;
        }
        if (!ubii__lws_append(connection, in, len, connection->port->options.max_message_size)) {
            ubii__lws_lose(connection, "message over the size limit", NULL);
            return -1;
        }
        if (lws_is_final_fragment(wsi) && lws_remaining_packet_payload(wsi) == 0) {
            deliver_assembled(connection, ch);
        }
        break;
    case LWS_CALLBACK_CLIENT_WRITEABLE:
        if (ch == NULL) {
            return -1; /* the channel was closed: end the connection */
        }
        return ubii__lws_write_outbox(connection, ch, wsi);
    case LWS_CALLBACK_CLIENT_CONNECTION_ERROR:
        ubii__lws_lose(connection, "WebSocket connection failed",
                       in != NULL ? (const char *)in : NULL);
        break;
    case LWS_CALLBACK_CLIENT_CLOSED:
        ubii__lws_lose(connection, "WebSocket closed by the master", NULL);
        break;
    case LWS_CALLBACK_WSI_DESTROY:
        ubii__lws_connection_destroyed(connection, wsi, "WebSocket connection ended");
        break;
    default:
        break;
    }
    return 0;
}

/* What both kinds of connection tell lws: where to, TLS, and the record to report to. */
void ubii__lws_describe_connection(ubii_linux_port *port, const lws_channel *ch,
                                   lws_connection *connection, const char *path,
                                   struct lws_client_connect_info *info)
{
    memset(info, 0, sizeof *info);
    info->context = port->lws;
    info->address = ch->host;
    info->port = ch->port;
    info->path = path;
    info->host = ch->host;
    info->origin = ch->host;
    info->opaque_user_data = connection;
    if (ch->tls) {
        info->ssl_connection = LCCSCF_USE_SSL;
        if (port->options.allow_self_signed) {
            info->ssl_connection |=
                LCCSCF_ALLOW_SELFSIGNED | LCCSCF_SKIP_SERVER_CERT_HOSTNAME_CHECK;
        }
    }
}

static ubii_status connect_websocket(ubii_linux_port *port, ubii_channel which,
                                     const char *client_id)
{
    lws_channel *ch = &port->channels[which].lws;
    char path[sizeof ch->path + 320];
    if (client_id == NULL || client_id[0] == '\0' || strlen(client_id) > 255) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    snprintf(path, sizeof path, "%s%sclientID=%s", ch->path, strchr(ch->path, '?') ? "&" : "?",
             client_id);
    lws_connection *connection = ubii__lws_new_connection(port, which);
    if (connection == NULL) {
        return UBII_ERR_TRANSPORT;
    }
    struct lws_client_connect_info info;
    ubii__lws_describe_connection(port, ch, connection, path, &info);
    info.ietf_version_or_minus_one = -1;
    info.local_protocol_name = "ubii-ws"; /* no Sec-WebSocket-Protocol: the master offers none */
    port->channels[which].state = UBII_CHANNEL_CONNECTING;
    ubii__lws_connect(port, which, connection, &info, "WebSocket connection could not be started");
    return UBII_OK;
}

/* ---- HTTP -------------------------------------------------------------------------------------
 */

static int on_http(struct lws *wsi, enum lws_callback_reasons reason, void *user, void *in,
                   size_t len)
{
    (void)user;
    lws_connection *connection = lws_get_opaque_user_data(wsi);
    if (connection == NULL) {
        return 0;
    }
    lws_channel *ch = ubii__lws_channel_of(connection);
    switch (reason) {
    case LWS_CALLBACK_CLIENT_APPEND_HANDSHAKE_HEADER: {
        if (ch == NULL) {
            return -1;
        }
        unsigned char **p = in;
        unsigned char *end = *p + len;
        static const char type[] = "application/octet-stream";
        if (lws_add_http_header_by_token(wsi, WSI_TOKEN_HTTP_CONTENT_TYPE,
                                         (const unsigned char *)type, (int)sizeof type - 1, p,
                                         end) ||
            lws_add_http_header_content_length(wsi, connection->request_size, p, end)) {
            return -1;
        }
        lws_client_http_body_pending(wsi, 1);
        lws_callback_on_writable(wsi);
        break;
    }
    case LWS_CALLBACK_CLIENT_HTTP_WRITEABLE:
        if (ch == NULL || connection->request == NULL) {
            return -1;
        }
        if (lws_write(wsi, connection->request + LWS_PRE, connection->request_size,
                      LWS_WRITE_HTTP_FINAL) < 0) {
            ubii__lws_lose(connection, "HTTP request could not be written", NULL);
            return -1;
        }
        lws_client_http_body_pending(wsi, 0);
        connection->setup_written = true;
        break;
    case LWS_CALLBACK_ESTABLISHED_CLIENT_HTTP:
        connection->status = (int)lws_http_client_http_response(wsi);
        connection->assembled = 0;
        break;
    case LWS_CALLBACK_RECEIVE_CLIENT_HTTP: {
        char buffer[LWS_PRE + 4096];
        char *start = buffer + LWS_PRE;
        int length = (int)sizeof buffer - LWS_PRE;
        if (lws_http_client_read(wsi, &start, &length) < 0) {
            return -1;
        }
        break;
    }
    case LWS_CALLBACK_RECEIVE_CLIENT_HTTP_READ:
        if (ch == NULL) {
            return -1;
        }
        if (!ubii__lws_append(connection, in, len, connection->port->options.max_message_size)) {
            ubii__lws_lose(connection, "HTTP reply over the size limit", NULL);
            return -1;
        }
        break;
    case LWS_CALLBACK_COMPLETED_CLIENT_HTTP:
        if (ch != NULL) {
            if (connection->status == 200) {
                connection->assembly_flags = 0;
                deliver_assembled(connection, ch);
            } else {
                char status[32];
                snprintf(status, sizeof status, "%d", connection->status);
                ubii__lws_lose(connection, "HTTP service answered with status", status);
            }
            ch->connection = NULL;
            detach(connection);
        }
        return -1; /* one request per connection */
    case LWS_CALLBACK_CLIENT_CONNECTION_ERROR:
        ubii__lws_lose(connection, "HTTP connection failed", in != NULL ? (const char *)in : NULL);
        break;
    case LWS_CALLBACK_WSI_DESTROY:
        if (ch != NULL && ch->connection == connection) {
            ch->connection = NULL;
        }
        connection->owner->lws_connections--;
        detach(connection);
        free(connection);
        lws_set_opaque_user_data(wsi, NULL);
        break;
    default:
        break;
    }
    return 0;
}

static ubii_status post_request(ubii_linux_port *port, ubii_channel which, queued_message *body)
{
    lws_channel *ch = &port->channels[which].lws;
    lws_connection *connection = ubii__lws_new_connection(port, which);
    if (connection == NULL) {
        free(body);
        return UBII_ERR_TRANSPORT;
    }
    connection->http = true;
    /* The message was allocated with LWS_PRE bytes of headroom; keep that layout. */
    connection->request = malloc(LWS_PRE + body->size);
    if (connection->request == NULL) {
        free(body);
        port->lws_connections--;
        free(connection);
        return UBII_ERR_TRANSPORT;
    }
    memcpy(connection->request + LWS_PRE, body->data, body->size);
    connection->request_size = body->size;
    free(body);

    struct lws_client_connect_info info;
    ubii__lws_describe_connection(port, ch, connection, ch->path, &info);
    info.method = "POST";
    info.local_protocol_name = "ubii-http";
    ubii__lws_connect(port, which, connection, &info, "HTTP request could not be started");
    return UBII_OK;
}

/* ---- the port functions ------------------------------------------------------------------------
 */

ubii_status ubii__lws_open(ubii_linux_port *port, ubii_channel which, const char *url,
                           const char *client_id)
{
    channel *c = &port->channels[which];
    lws_channel *ch = &c->lws;
    transport_kind kind;
    memset(ch, 0, sizeof *ch);
    if (!parse_url(url, ch, &kind)) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    if ((kind == TRANSPORT_HTTP && which == UBII_CHANNEL_TOPIC) ||
        (kind == TRANSPORT_WEBSOCKET && which == UBII_CHANNEL_SERVICE)) {
        return UBII_ERR_UNSUPPORTED; /* topic data over WebSocket, services over HTTP */
    }
    if (ch->tls && !port->options.enable_tls) {
        ubii__lws_set_error(port, "TLS URL on a port created without enable_tls", url);
        return UBII_ERR_UNSUPPORTED;
    }
    if (port->lws == NULL) {
        return port->options.zmq_only ? UBII_ERR_UNSUPPORTED : UBII_ERR_TRANSPORT;
    }
    c->kind = kind;
    if (kind == TRANSPORT_WEBSOCKET) {
        return connect_websocket(port, which, client_id);
    }
    if (kind == TRANSPORT_ZMTP) {
        return ubii__lws_connect_zmtp(port, which, client_id);
    }
    c->state = UBII_CHANNEL_OPEN; /* each request makes its own connection */
    return UBII_OK;
}

void ubii__lws_close(ubii_linux_port *port, ubii_channel which)
{
    lws_channel *ch = &port->channels[which].lws;
    if (ch->connection != NULL) {
        /* Killed at once, not at lws's next round: a TLS connection with buffered input would
         * otherwise be serviced again and again for a channel that no longer takes it. The core
         * never calls the port from inside an lws callback, so this is safe here. */
        lws_connection *connection = ch->connection;
        struct lws *wsi = connection->wsi;
        ch->connection = NULL;
        detach(connection);
        if (wsi != NULL) {
            lws_set_timeout(wsi, PENDING_TIMEOUT_USER_OK, LWS_TO_KILL_SYNC); /* frees connection */
        }
    }
    clear(&ch->inbox);
    clear(&ch->outbox);
    free(ch->taken);
    ch->taken = NULL;
    free(ch->reserved);
    ch->reserved = NULL;
}

ubii_status ubii__lws_send_begin(ubii_linux_port *port, ubii_channel which, size_t size,
                                 uint8_t **buffer)
{
    lws_channel *ch = &port->channels[which].lws;
    if (size > port->options.max_message_size) {
        return UBII_ERR_TOO_LARGE;
    }
    if (ch->outbox.count >= OUTBOX_LIMIT_COUNT) {
        return UBII_ERR_WOULD_BLOCK;
    }
    free(ch->reserved);
    ch->reserved = new_message(size, LWS_PRE);
    if (ch->reserved == NULL) {
        return UBII_ERR_TRANSPORT;
    }
    *buffer = ch->reserved->data;
    return UBII_OK;
}

ubii_status ubii__lws_send_commit(ubii_linux_port *port, ubii_channel which, unsigned flags)
{
    channel *c = &port->channels[which];
    lws_channel *ch = &c->lws;
    queued_message *message = ch->reserved;
    if (message == NULL) {
        return UBII_ERR_STATE;
    }
    ch->reserved = NULL;
    message->flags = flags;
    if (c->kind == TRANSPORT_HTTP) {
        if (ch->connection != NULL) {
            free(message);
            return UBII_ERR_WOULD_BLOCK; /* one request at a time, as over ZMQ */
        }
        return post_request(port, which, message);
    }
    push(&ch->outbox, message); /* written at the next wait (flush_outboxes) */
    return UBII_OK;
}

ubii_status ubii__lws_receive(ubii_linux_port *port, ubii_channel which, const uint8_t **data,
                              size_t *size, unsigned *flags)
{
    lws_channel *ch = &port->channels[which].lws;
    free(ch->taken);
    ch->taken = pop(&ch->inbox);
    if (ch->taken == NULL) {
        return UBII_ERR_WOULD_BLOCK;
    }
    *data = ch->taken->data;
    *size = ch->taken->size;
    *flags = ch->taken->flags;
    return UBII_OK;
}

static void wake_up(lws_sorted_usec_list_t *timer)
{
    (void)timer; /* lws_service returns once it has run */
}

/* The connection of an open WebSocket or ZMTP channel, which writes its outbox itself. */
static lws_connection *writer_of(channel *c)
{
    lws_connection *connection = c->lws.connection;
    bool writes = (c->kind == TRANSPORT_WEBSOCKET || c->kind == TRANSPORT_ZMTP) &&
                  c->state == UBII_CHANNEL_OPEN && connection != NULL && connection->wsi != NULL;
    return writes ? connection : NULL;
}

/* Writes what was queued since the last wait, before waiting. Left to lws's writable callback,
 * the write would be the event that ends the wait: a loop that publishes once per
 * ubii_node_poll(node, 16) would spin instead of being paced. Only a socket that takes less than
 * everything asks lws to say when it is writable again. */
static void flush_outboxes(ubii_linux_port *port)
{
    for (int i = 0; i < UBII_CHANNEL_COUNT; ++i) {
        lws_connection *connection = writer_of(&port->channels[i]);
        if (connection != NULL && output_waits(connection, &port->channels[i].lws)) {
            ubii__lws_write_outbox(connection, &port->channels[i].lws, connection->wsi);
        }
    }
}

/* lws_service() ignores its timeout argument and sleeps until the next scheduled timer; a timer
 * already due when it looks is run first and then no longer bounds the sleep. So a zero wait uses
 * lws's non-blocking form (-1), and a positive wait gets a second, later timer as a safety net in
 * case the first one falls due before lws polls. */
static void service_once(ubii_linux_port *port, int timeout_ms)
{
    enum { SAFETY_MARGIN_MS = 20 };
    if (timeout_ms <= 0) {
        lws_service(port->lws, -1);
        return;
    }
    lws_sorted_usec_list_t timer, safety;
    memset(&timer, 0, sizeof timer);
    memset(&safety, 0, sizeof safety);
    lws_sul_schedule(port->lws, 0, &timer, wake_up, (lws_usec_t)timeout_ms * LWS_US_PER_MS);
    lws_sul_schedule(port->lws, 0, &safety, wake_up,
                     (lws_usec_t)(timeout_ms + SAFETY_MARGIN_MS) * LWS_US_PER_MS);
    lws_service(port->lws, 0);
    lws_sul_cancel(&timer);
    lws_sul_cancel(&safety);
}

/* Bytes lws holds back, or an open channel's messages not yet handed to lws. */
static bool has_output(channel *c, lws_connection *connection)
{
    return lws_partial_buffered(connection->wsi) ||
           (writer_of(c) != NULL && output_waits(connection, &c->lws));
}

/* A connection holding output its socket has room for now. */
static bool output_can_go_on(ubii_linux_port *port)
{
    for (int i = 0; i < UBII_CHANNEL_COUNT; ++i) {
        lws_connection *connection = writer_of(&port->channels[i]);
        if (connection != NULL && has_output(&port->channels[i], connection) &&
            !lws_send_pipe_choked(connection->wsi)) {
            return true;
        }
    }
    return false;
}

void ubii__lws_service(ubii_linux_port *port, int timeout_ms)
{
    /* A pass reads each socket once (RX_CHUNK at most) and lws sends what one write left over
     * once, so a node polled once per frame would move 64 KB per frame each way (a megabyte image
     * in 15 frames). Passes go on without waiting while they read a near-full buffer or have
     * output the socket takes, up to SERVICE_PASSES (4 MB each way per wait). */
    for (int pass = 0; pass < SERVICE_PASSES; ++pass) {
        flush_outboxes(port);
        port->lws_bytes_read = 0;
        service_once(port, pass == 0 ? timeout_ms : 0);
        if (port->lws_bytes_read < RX_CHUNK / 2 && !output_can_go_on(port)) {
            break;
        }
    }
}

/* POLLOUT only while a connection has something to write: lws keeps its own poll set, which
 * Debian's build does not expose (no external-poll support), so an external loop learns it here. */
static short events_of(channel *c, lws_connection *connection)
{
    bool writing = !connection->setup_written || has_output(c, connection);
    return (short)(POLLIN | (writing ? POLLOUT : 0));
}

int ubii__lws_fds(ubii_linux_port *port, ubii_pollfd *fds, int capacity)
{
    int count = 0;
    for (int i = 0; i < UBII_CHANNEL_COUNT; ++i) {
        lws_connection *connection = port->channels[i].lws.connection;
        if (connection == NULL || connection->wsi == NULL) {
            continue;
        }
        int fd = (int)lws_get_socket_fd(connection->wsi);
        if (fd >= 0) {
            if (count < capacity) {
                fds[count].fd = fd;
                fds[count].events = events_of(&port->channels[i], connection);
            }
            count++;
        }
    }
    return count;
}

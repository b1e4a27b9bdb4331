/* The libwebsockets context and the wait: Debian's libwebsockets is built without external-poll
 * support, so lws drives the waiting; it alone knows when its sockets need POLLOUT (e.g. during a
 * non-blocking connect). Other fds are adopted into it (lws_foreign_fds.c) and a scheduled timer
 * bounds every wait. */
#include <poll.h>
#include <stdlib.h>
#include <string.h>

#include "lws_internal.h"

static const struct lws_protocols protocols[] = {
    {"ubii-ws", ubii__lws_on_websocket, 0, RX_CHUNK, 0, NULL, 0},
    {"ubii-http", ubii__lws_on_http, 0, RX_CHUNK, 0, NULL, 0},
    {"ubii-foreign-fd", ubii__lws_on_foreign_fd, 0, 0, 0, NULL, 0},
    {NULL, NULL, 0, 0, 0, NULL, 0}};

bool ubii__lws_start(ubii_linux_port *port)
{
    if (port->lws != NULL) {
        return true;
    }
    if (!ubii__lws_library_load(&port->lws_api, port->last_error, sizeof port->last_error)) {
        return false;
    }
    if (port->options.libwebsockets_log_level != 0) {
        LWS(port)->set_log_level(port->options.libwebsockets_log_level, NULL);
    }
    struct lws_context_creation_info info;
    memset(&info, 0, sizeof info);
    info.port = CONTEXT_PORT_NO_LISTEN;
    info.protocols = protocols;
    /* TLS needs lws's OpenSSL set-up, which is process-wide: see enable_tls in port_linux.h. */
    info.options = port->options.enable_tls ? LWS_SERVER_OPTION_DO_SSL_GLOBAL_INIT : 0;
    info.client_ssl_ca_filepath = port->options.enable_tls ? port->options.ca_file : NULL;
    info.gid = -1;
    info.uid = -1;
    /* lws reads a socket into this buffer, once per service pass (4 KB by default). */
    info.pt_serv_buf_size = LWS_PRE + RX_CHUNK;
    info.user = port;
    port->lws = LWS(port)->create_context(&info);
    if (port->lws == NULL) {
        ubii__port_error(port, "libwebsockets context could not be created", NULL);
        return false;
    }
    port->vhost = LWS(port)->get_vhost_by_name(port->lws, "default");
    ubii__lws_adopt_fd(port, &port->wake_fd, port->wake_fd, NULL);
    for (int i = 0; i < UBII_CHANNEL_COUNT; ++i) {
        channel *ch = &port->channels[i];
        if (ch->kind == TRANSPORT_ZMQ) {
            ubii__lws_adopt_zmq(port, ch->zmq.socket);
            ubii__lws_adopt_zmq(port, ch->zmq.monitor);
        } else if (ch->kind == TRANSPORT_ZMTP) {
            ubii__lws_adopt_fd(port, &ch->zmtp, ch->zmtp.fd, NULL);
        }
    }
    return true;
}

void ubii__lws_destroy(ubii_linux_port *port)
{
    if (port->lws != NULL) {
        LWS(port)->context_destroy(port->lws);
        port->lws = NULL;
        port->vhost = NULL;
    }
    for (int i = 0; i < MAX_FOREIGN_FDS; ++i) {
        free(port->foreign_fds[i]);
        port->foreign_fds[i] = NULL;
    }
    ubii__lws_library_unload(&port->lws_api);
}

static void wake_up(lws_sorted_usec_list_t *timer)
{
    (void)timer; /* lws_service returns once it has run */
}

/* The connection of an open WebSocket channel, which writes its outbox itself. */
static lws_connection *writer_of(channel *c)
{
    lws_connection *connection = c->lws.connection;
    bool writes = c->kind == TRANSPORT_WEBSOCKET && c->state == UBII_CHANNEL_OPEN &&
                  connection != NULL && connection->wsi != NULL;
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
        if (connection != NULL && ubii__lws_output_waits(connection, &port->channels[i].lws)) {
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
        LWS(port)->service(port->lws, -1);
        return;
    }
    lws_sorted_usec_list_t timer, safety;
    memset(&timer, 0, sizeof timer);
    memset(&safety, 0, sizeof safety);
    LWS(port)->sul_schedule(port->lws, 0, &timer, wake_up, (lws_usec_t)timeout_ms * LWS_US_PER_MS);
    LWS(port)->sul_schedule(port->lws, 0, &safety, wake_up,
                            (lws_usec_t)(timeout_ms + SAFETY_MARGIN_MS) * LWS_US_PER_MS);
    LWS(port)->service(port->lws, 0);
    LWS(port)->sul_cancel(&timer);
    LWS(port)->sul_cancel(&safety);
}

/* Bytes lws holds back, or an open channel's messages not yet handed to lws. */
static bool has_output(channel *c, lws_connection *connection)
{
    return LWS(connection->owner)->partial_buffered(connection->wsi) ||
           (writer_of(c) != NULL && ubii__lws_output_waits(connection, &c->lws));
}

/* A connection holding output its socket has room for now. */
static bool output_can_go_on(ubii_linux_port *port)
{
    for (int i = 0; i < UBII_CHANNEL_COUNT; ++i) {
        lws_connection *connection = writer_of(&port->channels[i]);
        if (connection != NULL && has_output(&port->channels[i], connection) &&
            !LWS(port)->send_pipe_choked(connection->wsi)) {
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
        int fd = (int)LWS(port)->get_socket_fd(connection->wsi);
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

/* The Linux port's channel functions for the libwebsockets transports: WebSocket topic data
 * (ws://, wss://) and binary HTTP services (http://, https://). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lws_internal.h"
#include "ubii/url.h"

/* The channel's host, port and path from the URL (ubii/url.h), and its transport. */
static bool parse_url(const char *url, lws_channel *ch, transport_kind *kind)
{
    ubii_url parsed;
    if (ubii_url_parse(url, &parsed) != UBII_OK) {
        return false;
    }
    switch (parsed.scheme) {
    case UBII_URL_WS:
    case UBII_URL_WSS:
        *kind = TRANSPORT_WEBSOCKET;
        break;
    case UBII_URL_HTTP:
    case UBII_URL_HTTPS:
        *kind = TRANSPORT_HTTP;
        break;
    default:
        return false;
    }
    ch->tls = parsed.tls;
    if (parsed.host_length >= sizeof ch->host) {
        return false;
    }
    memcpy(ch->host, parsed.host, parsed.host_length);
    ch->host[parsed.host_length] = '\0';
    ch->port = parsed.port;
    int written =
        snprintf(ch->path, sizeof ch->path, "%s%s", parsed.path[0] == '/' ? "" : "/", parsed.path);
    return written > 0 && (size_t)written < sizeof ch->path;
}

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
        ubii__port_error(port, "TLS URL on a port created without enable_tls", url);
        return UBII_ERR_UNSUPPORTED;
    }
    if (port->options.zmq_only) {
        return UBII_ERR_UNSUPPORTED;
    }
    if (!ubii__lws_start(port)) {
        return port->lws_api.handle == NULL ? UBII_ERR_UNSUPPORTED : UBII_ERR_TRANSPORT;
    }
    c->kind = kind;
    if (kind == TRANSPORT_WEBSOCKET) {
        return ubii__lws_connect_websocket(port, which, client_id);
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
        ubii__lws_detach(connection);
        if (wsi != NULL) {
            LWS(port)->set_timeout(wsi, PENDING_TIMEOUT_USER_OK,
                                   LWS_TO_KILL_SYNC); /* frees connection */
        }
    }
    ubii__lws_clear(&ch->inbox);
    ubii__lws_clear(&ch->outbox);
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
    ch->reserved = ubii__lws_new_message(size, LWS_PRE);
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
        return ubii__lws_post_request(port, which, message);
    }
    ubii__lws_push(&ch->outbox, message); /* written at the next wait (flush_outboxes) */
    return UBII_OK;
}

ubii_status ubii__lws_receive(ubii_linux_port *port, ubii_channel which, const uint8_t **data,
                              size_t *size, unsigned *flags)
{
    lws_channel *ch = &port->channels[which].lws;
    free(ch->taken);
    ch->taken = ubii__lws_pop(&ch->inbox);
    if (ch->taken == NULL) {
        return UBII_ERR_WOULD_BLOCK;
    }
    *data = ch->taken->data;
    *size = ch->taken->size;
    *flags = ch->taken->flags;
    return UBII_OK;
}

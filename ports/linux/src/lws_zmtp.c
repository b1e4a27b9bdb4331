/* ZMQ's wire protocol (ZMTP 3, ports/common/zmtp_wire.c) spoken in the caller's thread over a
 * libwebsockets raw socket: the tcp:// engine of UBII_LINUX_ZMQ_IN_THREAD.
 *
 * Why: libzmq's I/O thread wakes for every message that arrives, which costs more kernel time
 * than all the rest of receiving it. Here bytes wait in the socket until the node is polled, so a
 * node polled once per frame takes a frame's worth of messages in a few reads; outgoing messages
 * go out together in one write. The master sees the same REQ or DEALER peer either way. */
#include <stdlib.h>
#include <string.h>

#include "lws_internal.h"

/* Takes every whole unit off the front of the stream; false if the connection must end. */
static bool take_units(lws_connection *connection, lws_channel *ch)
{
    size_t at = 0;
    bool keep = true;
    while (keep) {
        ubii_zmtp_found found;
        ubii_zmtp_unit unit = ubii__zmtp_next(&connection->zmtp_step, connection->assembly + at,
                                              connection->assembled - at,
                                              connection->port->options.max_message_size, &found);
        switch (unit) {
        case UBII_ZMTP_NEED_MORE:
            keep = false;
            continue;
        case UBII_ZMTP_SKIP:
            if (connection->zmtp_step == UBII_ZMTP_STEP_OPEN &&
                connection->port->channels[connection->which].state == UBII_CHANNEL_CONNECTING) {
                connection->port->channels[connection->which].state = UBII_CHANNEL_OPEN;
                if (ch->outbox.count > 0) {
                    lws_callback_on_writable(connection->wsi);
                }
            }
            break;
        case UBII_ZMTP_MESSAGE:
            ubii__lws_deliver(connection, ch, connection->assembly + at + found.payload,
                              (size_t)found.size, 0);
            break;
        case UBII_ZMTP_MISSHAPEN: /* dropped whole, as libzmq's DEALER and REQ do */
            ubii__lws_set_error(connection->port,
                                "a ZMQ message of a shape the master never sends"
                                " was dropped",
                                NULL);
            break;
        case UBII_ZMTP_TOO_LARGE:
            ubii__lws_lose(connection, "message over the size limit", NULL);
            return false;
        case UBII_ZMTP_ERROR:
            ubii__lws_lose(connection, found.error, NULL);
            return false;
        }
        at += found.consumed;
    }
    /* What remains is the start of a unit: keep it at the front for the rest to join. */
    memmove(connection->assembly, connection->assembly + at, connection->assembled - at);
    connection->assembled -= at;
    return connection->port != NULL &&
           connection->port->channels[connection->which].state != UBII_CHANNEL_LOST;
}

int ubii__lws_on_zmtp(struct lws *wsi, enum lws_callback_reasons reason, void *user, void *in,
                      size_t len)
{
    (void)user;
    lws_connection *connection = lws_get_opaque_user_data(wsi);
    if (connection == NULL) {
        return 0;
    }
    lws_channel *ch = ubii__lws_channel_of(connection);
    switch (reason) {
    case LWS_CALLBACK_RAW_CONNECTED:
        if (ch == NULL) {
            return -1;
        }
        /* Our greeting and READY; messages wait for the master's READY (take_units). */
        if (lws_write(wsi, connection->request, connection->request_size, LWS_WRITE_RAW) < 0) {
            ubii__lws_lose(connection, "ZMTP handshake could not be written", NULL);
            return -1;
        }
        connection->setup_written = true;
        break;
    case LWS_CALLBACK_RAW_RX:
        if (ch == NULL) {
            return -1;
        }
        /* A message and its framing, and the start of the next unit. */
        if (!ubii__lws_append(connection, in, len,
                              connection->port->options.max_message_size +
                                  2 * UBII_ZMTP_MAX_HEADER + len)) {
            ubii__lws_lose(connection, "no memory for received bytes", NULL);
            return -1;
        }
        return take_units(connection, ch) ? 0 : -1;
    case LWS_CALLBACK_RAW_WRITEABLE:
        if (ch == NULL) {
            return -1; /* the channel was closed: end the connection */
        }
        if (connection->zmtp_step != UBII_ZMTP_STEP_OPEN) {
            return 0; /* once the master is ready */
        }
        return ubii__lws_write_outbox(connection, ch, wsi);
    case LWS_CALLBACK_CLIENT_CONNECTION_ERROR:
        ubii__lws_lose(connection, "ZMQ connection failed", in != NULL ? (const char *)in : NULL);
        break;
    case LWS_CALLBACK_RAW_CLOSE:
        ubii__lws_lose(connection, "ZMQ connection closed by the master", NULL);
        break;
    case LWS_CALLBACK_WSI_DESTROY:
        ubii__lws_connection_destroyed(connection, wsi, "ZMQ connection ended");
        break;
    default:
        break;
    }
    return 0;
}

ubii_status ubii__lws_connect_zmtp(ubii_linux_port *port, ubii_channel which, const char *client_id)
{
    bool dealer = which == UBII_CHANNEL_TOPIC;
    if (dealer && (client_id == NULL || client_id[0] == '\0')) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    lws_connection *connection = ubii__lws_new_connection(port, which);
    if (connection == NULL) {
        return UBII_ERR_TRANSPORT;
    }
    connection->zmtp = true;
    connection->zmtp_request = !dealer;
    connection->zmtp_step = UBII_ZMTP_STEP_GREETING;
    connection->request = malloc(UBII_ZMTP_HANDSHAKE_MAX);
    connection->request_size =
        connection->request != NULL
            ? ubii__zmtp_handshake(connection->request, UBII_ZMTP_HANDSHAKE_MAX, dealer,
                                   dealer ? client_id : "")
            : 0;
    if (connection->request_size == 0) {
        ubii_status status =
            connection->request != NULL ? UBII_ERR_INVALID_ARGUMENT : UBII_ERR_TRANSPORT;
        free(connection->request);
        port->lws_connections--;
        free(connection);
        return status; /* an identity too long for the READY command, or no memory */
    }
    lws_channel *ch = &port->channels[which].lws;
    struct lws_client_connect_info info;
    ubii__lws_describe_connection(port, ch, connection, "", &info);
    info.method = "RAW";
    info.local_protocol_name = "ubii-zmtp";
    port->channels[which].state = UBII_CHANNEL_CONNECTING;
    ubii__lws_connect(port, which, connection, &info, "ZMQ connection could not be started");
    return UBII_OK;
}

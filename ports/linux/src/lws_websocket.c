/* Topic data over WebSocket (ws://, wss://): the client side of the master's WebSocket server,
 * one binary message per TopicData, the client id in the URL's query. */
#include <stdlib.h>
#include <string.h>

#include "lws_internal.h"

int ubii__lws_on_websocket(struct lws *wsi, enum lws_callback_reasons reason, void *user, void *in,
                           size_t len)
{
    lws_connection *connection = ubii__lws_connection_of(user);
    if (connection == NULL) {
        return 0;
    }
    const ubii__lws_library *lws = LWS(connection->owner);
    lws_channel *ch = ubii__lws_channel_of(connection);
    switch (reason) {
    case LWS_CALLBACK_CLIENT_APPEND_HANDSHAKE_HEADER:
        connection->setup_written = true; /* lws writes the upgrade request now */
        break;
    case LWS_CALLBACK_CLIENT_ESTABLISHED:
        if (ch != NULL) {
            connection->port->channels[connection->which].state = UBII_CHANNEL_OPEN;
            if (ch->outbox.count > 0) {
                lws->callback_on_writable(wsi);
            }
        }
        break;
    case LWS_CALLBACK_CLIENT_RECEIVE:
        if (ch == NULL) {
            return -1;
        }
        if (lws->is_first_fragment(wsi)) {
            connection->assembled = 0;
            connection->assembly_flags = lws->frame_is_binary(wsi) ? 0 : UBII_MESSAGE_TEXT;
        }
        if (!ubii__lws_append(connection, in, len, connection->port->options.max_message_size)) {
            ubii__lws_lose(connection, "message over the size limit", NULL);
            return -1;
        }
        if (lws->is_final_fragment(wsi) && lws->remaining_packet_payload(wsi) == 0) {
            ubii__lws_deliver_assembled(connection, ch);
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
        /* Every connection's end comes here, the HTTP ones' too (the first protocol's). */
        ubii__lws_connection_destroyed(connection, wsi,
                                       connection->http ? "HTTP connection ended"
                                                        : "WebSocket connection ended");
        break;
    default:
        break;
    }
    return 0;
}

ubii_status ubii__lws_connect_websocket(ubii_linux_port *port, ubii_channel which,
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

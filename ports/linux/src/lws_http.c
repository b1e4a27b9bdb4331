/* Binary services over HTTP (http://, https://): each request a POST on a connection of its
 * own, its reply the body of a 200 response. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lws_internal.h"

int ubii__lws_on_http(struct lws *wsi, enum lws_callback_reasons reason, void *user, void *in,
                      size_t len)
{
    lws_connection *connection = ubii__lws_connection_of(user);
    if (connection == NULL) {
        return 0;
    }
    const ubii__lws_library *lws = LWS(connection->owner);
    lws_channel *ch = ubii__lws_channel_of(connection);
    switch (reason) {
    case LWS_CALLBACK_CLIENT_APPEND_HANDSHAKE_HEADER: {
        if (ch == NULL) {
            return -1;
        }
        unsigned char **p = in;
        unsigned char *end = *p + len;
        static const char type[] = "application/octet-stream";
        if (lws->add_http_header_by_token(wsi, WSI_TOKEN_HTTP_CONTENT_TYPE,
                                          (const unsigned char *)type, (int)sizeof type - 1, p,
                                          end) ||
            lws->add_http_header_content_length(wsi, connection->request_size, p, end)) {
            return -1;
        }
        lws->client_http_body_pending(wsi, 1);
        lws->callback_on_writable(wsi);
        break;
    }
    case LWS_CALLBACK_CLIENT_HTTP_WRITEABLE:
        if (ch == NULL || connection->request == NULL) {
            return -1;
        }
        if (lws->write(wsi, connection->request + LWS_PRE, connection->request_size,
                       LWS_WRITE_HTTP_FINAL) < 0) {
            ubii__lws_lose(connection, "HTTP request could not be written", NULL);
            return -1;
        }
        lws->client_http_body_pending(wsi, 0);
        connection->setup_written = true;
        break;
    case LWS_CALLBACK_ESTABLISHED_CLIENT_HTTP:
        connection->status = (int)lws->http_client_http_response(wsi);
        connection->assembled = 0;
        break;
    case LWS_CALLBACK_RECEIVE_CLIENT_HTTP: {
        char buffer[LWS_PRE + 4096];
        char *start = buffer + LWS_PRE;
        int length = (int)sizeof buffer - LWS_PRE;
        if (lws->http_client_read(wsi, &start, &length) < 0) {
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
                ubii__lws_deliver_assembled(connection, ch);
            } else {
                char status[32];
                snprintf(status, sizeof status, "%d", connection->status);
                ubii__lws_lose(connection, "HTTP service answered with status", status);
            }
            ch->connection = NULL;
            ubii__lws_detach(connection);
        }
        return -1; /* one request per connection */
    case LWS_CALLBACK_CLIENT_CONNECTION_ERROR:
        ubii__lws_lose(connection, "HTTP connection failed", in != NULL ? (const char *)in : NULL);
        break;
    default:
        break;
    }
    return 0;
}

ubii_status ubii__lws_post_request(ubii_linux_port *port, ubii_channel which, queued_message *body)
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

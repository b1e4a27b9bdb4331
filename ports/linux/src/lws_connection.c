/* The connection records of the libwebsockets transports: their message queues, their lifetime
 * (a record outlives its channel if need be: closing a channel detaches the record and asks lws to
 * kill the connection; lws frees it on WSI_DESTROY), and what arrives on them. The protocol
 * files (lws_websocket.c, lws_http.c) frame and parse; this file owns. */
#include <stdlib.h>
#include <string.h>

#include "lws_internal.h"

/* ---- queues ---- */

queued_message *ubii__lws_new_message(size_t size, size_t headroom)
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

void ubii__lws_push(message_queue *queue, queued_message *message)
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

queued_message *ubii__lws_pop(message_queue *queue)
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

void ubii__lws_clear(message_queue *queue)
{
    queued_message *message;
    while ((message = ubii__lws_pop(queue)) != NULL) {
        free(message);
    }
}

/* ---- records ---- */

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
    ubii__port_error(connection->port, what, detail);
    connection->port->channels[connection->which].state = UBII_CHANNEL_LOST;
}

void ubii__lws_detach(lws_connection *connection)
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

lws_connection *ubii__lws_new_connection(ubii_linux_port *port, ubii_channel which)
{
    lws_connection *connection = calloc(1, sizeof *connection);
    if (connection != NULL) {
        connection->kind = LWS_RECORD_CONNECTION;
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
    connection->wsi = LWS(port)->client_connect_via_info(info);
    if (connection->wsi == NULL && ch->connection == connection) {
        /* Failed at once (lws may already have reported it and freed nothing). */
        ch->connection = NULL;
        port->lws_connections--;
        ubii__lws_detach(connection);
        free(connection);
        port->channels[which].state = UBII_CHANNEL_LOST;
        ubii__port_error(port, failure, NULL);
    }
}

lws_connection *ubii__lws_connection_of(void *user)
{
    return user != NULL && *(const lws_record_kind *)user == LWS_RECORD_CONNECTION ? user : NULL;
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
    ubii_linux_port *owner = connection->owner;
    owner->lws_connections--;
    ubii__lws_detach(connection);
    free(connection);
    LWS(owner)->set_wsi_user(wsi, NULL);
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
    info->userdata = connection; /* each callback's `user` (ubii__lws_connection_of) */
    if (ch->tls) {
        info->ssl_connection = LCCSCF_USE_SSL;
        if (port->options.allow_self_signed) {
            info->ssl_connection |=
                LCCSCF_ALLOW_SELFSIGNED | LCCSCF_SKIP_SERVER_CERT_HOSTNAME_CHECK;
        }
    }
}

/* ---- received messages ---- */

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
    queued_message *message = ubii__lws_new_message(size, 0);
    if (message == NULL) {
        ubii__lws_lose(connection, "out of memory for a received message", NULL);
        return;
    }
    memcpy(message->data, data, size);
    message->flags = flags;
    ubii__lws_push(&ch->inbox, message);
    if (ch->inbox.count > INBOX_LIMIT_COUNT || ch->inbox.bytes > INBOX_LIMIT_BYTES) {
        ubii__lws_lose(connection, "received messages piled up unread (is the node being polled?)",
                       NULL);
    }
}

void ubii__lws_deliver_assembled(lws_connection *connection, lws_channel *ch)
{
    ubii__lws_deliver(connection, ch, connection->assembly, connection->assembled,
                      connection->assembly_flags);
    connection->assembled = 0;
}

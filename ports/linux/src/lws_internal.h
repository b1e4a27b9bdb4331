#ifndef UBII_LWS_INTERNAL_H
#define UBII_LWS_INTERNAL_H

/* Shared by the Linux port's libwebsockets files: lws_channel.c (the port's functions),
 * lws_context.c (the context and the wait), lws_connection.c (the connection records, which it
 * alone owns), lws_outbox.c (outgoing frames), and the protocols over them: lws_websocket.c,
 * lws_http.c. */

#include <libwebsockets.h>

#include "linux_port.h"
#include "websocket_frame.h"

enum {
    RX_CHUNK = 64 * 1024,
    /* Received messages waiting for the node, at most. The node drains the inbox at every poll,
     * so this is only reached by an application that stops polling under a flood; the connection
     * is then dropped (LOST, with a reason). Pausing the socket instead (lws_rx_flow_control)
     * makes libwebsockets 4.1 spin in its forced-service loop on TLS connections. */
    INBOX_LIMIT_COUNT = 16384,
    INBOX_LIMIT_BYTES = 256 * 1024 * 1024,
    OUTBOX_LIMIT_COUNT = 4096,
    /* Frames handed to libwebsockets in one write: below its per-write limit (RX_CHUNK), so one
     * send(2) carries them all. */
    BATCH_BYTES = 32 * 1024,
    /* lws_service passes in one wait, at most (ubii__lws_service). */
    SERVICE_PASSES = 64,
    MASK_POOL = 256
};

/* Outgoing messages keep LWS_PRE bytes before their data: room for a frame header. */
typedef char headroom_holds_a_websocket_header[LWS_PRE >= UBII_WS_MAX_CLIENT_HEADER ? 1 : -1];

/* The port's libwebsockets functions (lws_library.h): every call into lws goes through them. */
#define LWS(port) (&(port)->lws_api)

typedef struct lws_connection {
    lws_record_kind kind;   /* LWS_RECORD_CONNECTION */
    ubii_linux_port *port;  /* NULL once the channel has let go of it */
    ubii_linux_port *owner; /* the port, always: counts its live connections */
    ubii_channel which;
    struct lws *wsi;
    bool http;
    /* What the connection writes before its outbox (the WebSocket upgrade, the HTTP request) has
     * been handed to lws: until then it waits to write (pollfds says POLLOUT). */
    bool setup_written;
    /* WebSocket: the message being assembled from fragments. */
    uint8_t *assembly;
    size_t assembled;
    size_t assembly_capacity;
    unsigned assembly_flags;
    /* WebSocket: outgoing frames gathered for one write (LWS_PRE + BATCH_BYTES), and masking
     * keys fetched from lws's random source MASK_POOL bytes at a time. */
    uint8_t *batch;
    /* A message larger than BATCH_BYTES, framed in place, while it goes out in pieces. */
    queued_message *sending;
    uint8_t *sending_next;
    size_t sending_left;
    uint8_t masks[MASK_POOL];
    size_t masks_left;
    /* HTTP: the request body (after LWS_PRE bytes) and the response. */
    uint8_t *request;
    size_t request_size;
    int status;
} lws_connection;

/* lws_connection.c: the records, their queues, and what arrives on them. */
queued_message *ubii__lws_new_message(size_t size, size_t headroom);
void ubii__lws_push(message_queue *queue, queued_message *message);
queued_message *ubii__lws_pop(message_queue *queue);
void ubii__lws_clear(message_queue *queue);
/* The channel the connection serves, or NULL once the channel has let go of it. */
lws_channel *ubii__lws_channel_of(lws_connection *connection);
/* Marks the channel LOST with a reason. */
void ubii__lws_lose(lws_connection *connection, const char *what, const char *detail);
/* Frees the record's buffers and lets go of the port (the record itself stays for lws). */
void ubii__lws_detach(lws_connection *connection);
/* A new connection record for a channel, counted as live. */
lws_connection *ubii__lws_new_connection(ubii_linux_port *port, ubii_channel which);
/* Starts connecting as `info` says; on failure at once, frees the record and marks the channel
 * LOST with `failure`. */
void ubii__lws_connect(ubii_linux_port *port, ubii_channel which, lws_connection *connection,
                       struct lws_client_connect_info *info, const char *failure);
/* The connection a callback's `user` is, or NULL if it is none (another record's end, or a
 * callback of lws itself). */
lws_connection *ubii__lws_connection_of(void *user);
/* WSI_DESTROY: reports the end to a channel still open, then frees the record. */
void ubii__lws_connection_destroyed(lws_connection *connection, struct lws *wsi, const char *what);
/* What every kind of connection tells lws: where to, TLS, and the record to report to. */
void ubii__lws_describe_connection(ubii_linux_port *port, const lws_channel *ch,
                                   lws_connection *connection, const char *path,
                                   struct lws_client_connect_info *info);
/* Appends to the connection's assembly buffer; false over `limit` or without memory. */
bool ubii__lws_append(lws_connection *connection, const void *in, size_t len, size_t limit);
/* Queues a copy of a received message for the node. */
void ubii__lws_deliver(lws_connection *connection, lws_channel *ch, const uint8_t *data,
                       size_t size, unsigned flags);
/* Delivers the assembly buffer as one message and empties it. */
void ubii__lws_deliver_assembled(lws_connection *connection, lws_channel *ch);

/* lws_outbox.c */
bool ubii__lws_output_waits(const lws_connection *connection, const lws_channel *ch);
/* Writes what the outbox holds, as much as the socket takes now; -1 to end the connection. */
int ubii__lws_write_outbox(lws_connection *connection, lws_channel *ch, struct lws *wsi);

/* The protocols: each an lws callback and a way to start a connection (host and port already in
 * the channel). */
int ubii__lws_on_websocket(struct lws *wsi, enum lws_callback_reasons reason, void *user, void *in,
                           size_t len);
ubii_status ubii__lws_connect_websocket(ubii_linux_port *port, ubii_channel which,
                                        const char *client_id);
int ubii__lws_on_http(struct lws *wsi, enum lws_callback_reasons reason, void *user, void *in,
                      size_t len);
/* Posts `body` (taken over) on a connection of its own. */
ubii_status ubii__lws_post_request(ubii_linux_port *port, ubii_channel which, queued_message *body);

/* lws_foreign_fds.c: descriptors that end the wait. */
int ubii__lws_on_foreign_fd(struct lws *wsi, enum lws_callback_reasons reason, void *user, void *in,
                            size_t len);

#endif

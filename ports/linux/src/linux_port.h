#ifndef UBII_LINUX_PORT_INTERNAL_H
#define UBII_LINUX_PORT_INTERNAL_H

/* Internal to the Linux port. */

#include <stdint.h>

#include <zmq.h>

#include "zmq_library.h"

#include "ubii/port_linux.h"

struct lws;
struct lws_context;
struct lws_vhost;

typedef enum transport_kind {
    TRANSPORT_NONE = 0,
    TRANSPORT_ZMQ = 1,
    TRANSPORT_WEBSOCKET = 2,
    TRANSPORT_HTTP = 3,
    TRANSPORT_ZMTP = 4 /* tcp:// spoken in the caller's thread over an lws raw socket */
} transport_kind;

/* A whole message waiting to be taken (received) or written (sent); data follows the header
 * (outgoing ones keep LWS_PRE bytes of headroom before it). */
typedef struct queued_message {
    struct queued_message *next;
    size_t size;
    unsigned flags;
    uint8_t *data;
} queued_message;

typedef struct message_queue {
    queued_message *head;
    queued_message *tail;
    size_t count;
    size_t bytes;
} message_queue;

struct lws_connection;

typedef struct lws_channel {
    struct lws_connection *connection; /* the live connection, NULL if none */
    char host[256];
    char path[512];
    int port;
    bool tls;
    message_queue inbox;
    queued_message *taken; /* lent to the core until the next receive */
    message_queue outbox;  /* WebSocket: waiting for the socket to be writable */
    queued_message *reserved;
} lws_channel;

/* A ZMQ fd adopted into libwebsockets, so that ZMQ traffic wakes lws_service(). */
typedef struct zmq_wakeup {
    struct ubii_linux_port *port;
    void *socket;
    struct lws *wsi;
} zmq_wakeup;

typedef struct zmq_channel {
    const ubii__zmq_library *api; /* the port's */
    void *socket;
    void *monitor; /* PAIR socket receiving the socket's connection events */
    zmq_msg_t incoming;
    bool holds_incoming;
    zmq_msg_t outgoing;
    bool holds_outgoing;
} zmq_channel;

typedef struct channel {
    transport_kind kind;
    ubii_channel_state state;
    zmq_channel zmq;
    lws_channel lws;
} channel;

enum { MAX_ZMQ_WAKEUPS = 2 * UBII_CHANNEL_COUNT };

struct ubii_linux_port {
    ubii_linux_port_options options;
    ubii__zmq_library zmq_api; /* loaded only for UBII_LINUX_ZMQ_LIBZMQ */
    void *zmq_context;
    uint32_t monitor_serial;
    channel channels[UBII_CHANNEL_COUNT];
    struct lws_context *lws; /* created on the first WebSocket or HTTP channel */
    struct lws_vhost *vhost;
    zmq_wakeup *wakeups[MAX_ZMQ_WAKEUPS];
    int lws_connections;   /* live WebSocket/HTTP connections, closing ones included */
    size_t lws_bytes_read; /* handed over by libwebsockets in the current service pass */
    char last_error[256];
    int wake_fd; /* eventfd: ubii_linux_port_wake() makes it readable, ending a wait */
};

/* lws_context.c: the libwebsockets context and the wait. */
/* Starts libwebsockets (once); false if it cannot. */
bool ubii__lws_start(ubii_linux_port *port);
/* Runs libwebsockets once, returning after at most timeout_ms. */
void ubii__lws_service(ubii_linux_port *port, int timeout_ms);
int ubii__lws_fds(ubii_linux_port *port, ubii_pollfd *fds, int capacity);
void ubii__lws_destroy(ubii_linux_port *port);

/* lws_channel.c: the port functions for ws://, wss://, http://, https:// and in-thread tcp://. */
ubii_status ubii__lws_open(ubii_linux_port *port, ubii_channel which, const char *url,
                           const char *client_id);
void ubii__lws_close(ubii_linux_port *port, ubii_channel which);
ubii_status ubii__lws_send_begin(ubii_linux_port *port, ubii_channel which, size_t size,
                                 uint8_t **buffer);
ubii_status ubii__lws_send_commit(ubii_linux_port *port, ubii_channel which, unsigned flags);
ubii_status ubii__lws_receive(ubii_linux_port *port, ubii_channel which, const uint8_t **data,
                              size_t *size, unsigned *flags);

/* lws_zmq_fds.c: keeps one adopted fd per ZMQ socket while libwebsockets runs. */
void ubii__lws_adopt_zmq(ubii_linux_port *port, void *socket);
void ubii__lws_release_zmq(ubii_linux_port *port, void *socket);

/* zmq_channel.c */
ubii_status ubii__zmq_open(ubii_linux_port *port, ubii_channel which, const char *url,
                           const char *client_id);
void ubii__zmq_close(channel *ch);
void ubii__zmq_update_state(channel *ch);
ubii_status ubii__zmq_send_begin(ubii_linux_port *port, channel *ch, size_t size, uint8_t **buffer);
ubii_status ubii__zmq_send_commit(channel *ch);
ubii_status ubii__zmq_receive(ubii_linux_port *port, ubii_channel which, const uint8_t **data,
                              size_t *size);
/* Adds the channel's sockets to `items`; returns how many. */
int ubii__zmq_poll_items(channel *ch, zmq_pollitem_t *items);
int ubii__zmq_fds(channel *ch, ubii_pollfd *fds, int capacity);

#endif

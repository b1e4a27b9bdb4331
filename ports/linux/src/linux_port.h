#ifndef UBII_LINUX_PORT_INTERNAL_H
#define UBII_LINUX_PORT_INTERNAL_H

/* Internal to the Linux port. */

#include <stdint.h>

#include <zmq.h>

#include "zmtp_wire.h"

#include "lws_library.h"
#include "zmq_library.h"

#include "ubii/port_linux.h"

struct addrinfo;
struct lws;
struct lws_context;
struct lws_vhost;

typedef enum transport_kind {
    TRANSPORT_NONE = 0,
    TRANSPORT_ZMQ = 1,
    TRANSPORT_WEBSOCKET = 2,
    TRANSPORT_HTTP = 3,
    TRANSPORT_ZMTP = 4 /* tcp:// spoken in the caller's thread (zmtp_channel.c) */
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

/* What a libwebsockets connection carries as its user pointer starts with one of these: lws hands
 * every connection's end (WSI_DESTROY) to the first protocol's callback, whatever its kind. */
typedef enum lws_record_kind {
    LWS_RECORD_CONNECTION = 1,
    LWS_RECORD_FOREIGN_FD = 2
} lws_record_kind;

/* Another descriptor adopted into libwebsockets (as a duplicate), so that its traffic ends
 * lws_service(): a libzmq socket's, a ZMTP connection's or the wake-up eventfd. */
typedef struct foreign_fd {
    lws_record_kind kind;
    struct ubii_linux_port *port;
    const void *owner; /* libzmq socket, ZMTP channel or &wake_fd; NULL once released */
    void *zmq_socket;  /* libzmq: ZMQ_EVENTS is read when it fires, consuming its signal */
    struct lws *wsi;
} foreign_fd;

typedef struct zmq_channel {
    const ubii__zmq_library *api; /* the port's */
    void *socket;
    void *monitor; /* PAIR socket receiving the socket's connection events */
    zmq_msg_t incoming;
    bool holds_incoming;
    zmq_msg_t outgoing;
    bool holds_outgoing;
} zmq_channel;

/* ZMTP on a plain socket: bytes read into rx (handed to the core in place, `lent` of them from
 * rx_start until the next receive), bytes to write in tx (our greeting first, then framed
 * messages). */
typedef struct zmtp_channel {
    int fd;         /* -1 without a connection */
    bool request;   /* REQ (service channel) or DEALER (topic channel) */
    bool connected; /* the non-blocking connect has completed */
    ubii_zmtp_step step;
    struct addrinfo *addresses; /* the host's, until connected; `trying` is the current one */
    struct addrinfo *trying;
    size_t greeting_unsent; /* written before the master's READY; messages only after it */
    uint8_t *rx;
    size_t rx_start, rx_end, rx_capacity, lent;
    size_t checked; /* bytes from rx_start known to be whole, well-formed units */
    uint8_t *tx;
    size_t tx_start, tx_end, tx_capacity;
    bool has_reservation; /* send_begin's room, at tx_end behind its frame header */
    size_t reserved_size;
} zmtp_channel;

typedef struct channel {
    transport_kind kind;
    ubii_channel_state state;
    zmq_channel zmq;
    lws_channel lws;
    zmtp_channel zmtp;
} channel;

/* Descriptors adopted into libwebsockets while it drives the wait (lws_foreign_fds.c): at most
 * two per channel (libzmq's socket and monitor), and the wake-up eventfd. */
enum { MAX_FOREIGN_FDS = 2 * UBII_CHANNEL_COUNT + 1 };

struct ubii_linux_port {
    ubii_linux_port_options options;
    ubii__zmq_library zmq_api; /* loaded only for UBII_LINUX_ZMQ_LIBZMQ */
    ubii__lws_library lws_api; /* loaded with the first ws:// or http:// channel, or enable_tls */
    void *zmq_context;
    uint32_t monitor_serial;
    channel channels[UBII_CHANNEL_COUNT];
    struct lws_context *lws; /* created with the first ws:// or http:// channel, or enable_tls */
    struct lws_vhost *vhost;
    foreign_fd *foreign_fds[MAX_FOREIGN_FDS];
    int lws_connections;   /* live WebSocket/HTTP connections, closing ones included */
    size_t lws_bytes_read; /* handed over by libwebsockets in the current service pass */
    char last_error[256];
    int wake_fd; /* eventfd: ubii_linux_port_wake() makes it readable, ending a wait */
};

/* linux_port.c: sets the port's last error, "what: detail" (detail may be NULL). */
void ubii__port_error(ubii_linux_port *port, const char *what, const char *detail);

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

/* lws_foreign_fds.c: keeps a duplicate of each libzmq socket's and ZMTP connection's fd in
 * libwebsockets' wait while it runs (or from when it starts). */
void ubii__lws_adopt_fd(ubii_linux_port *port, const void *owner, int fd, void *zmq_socket);
void ubii__lws_adopt_zmq(ubii_linux_port *port, void *socket);
void ubii__lws_release_fd(ubii_linux_port *port, const void *owner);
/* The next lws wait ends when the owner's fd is writable as well. */
void ubii__lws_want_writable(ubii_linux_port *port, const void *owner);

/* zmtp_channel.c: tcp:// in the caller's thread. */
ubii_status ubii__zmtp_open(ubii_linux_port *port, ubii_channel which, const char *url,
                            const char *client_id);
void ubii__zmtp_close(ubii_linux_port *port, channel *ch);
/* Writes what is queued (before a wait). */
void ubii__zmtp_flush(ubii_linux_port *port, ubii_channel which);
/* Connects, writes, reads (after a wait). */
void ubii__zmtp_service(ubii_linux_port *port, ubii_channel which);
/* poll(2) events the channel's fd waits for; 0 without one. */
short ubii__zmtp_events(const ubii_linux_port *port, const channel *ch);
ubii_status ubii__zmtp_send_begin(ubii_linux_port *port, channel *ch, size_t size,
                                  uint8_t **buffer);
ubii_status ubii__zmtp_send_commit(channel *ch);
ubii_status ubii__zmtp_receive(ubii_linux_port *port, channel *ch, const uint8_t **data,
                               size_t *size);

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

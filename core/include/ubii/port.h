#ifndef UBII_PORT_H
#define UBII_PORT_H

/* The one boundary a transport port implements (ports/linux, ports/embedded, or your own).
 *
 * A node uses two message channels: SERVICE (request, then exactly one reply) and TOPIC (TopicData
 * both ways plus the PING/PONG keepalive). The port turns URLs into connections, frames whole
 * messages, and does all I/O; the core never sees a socket. Every function is non-blocking except
 * wait(), which blocks at most the time it is given. None is called from two threads at once.
 *
 * Memory: the port object is owned by the application and outlives the node. A received message
 * is lent to the core until the next receive() or close() on that channel, and on the SERVICE
 * channel also until the next send_begin() (a reply is done with before the next request, so a
 * port may keep both in one buffer). */

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "ubii/status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum ubii_channel {
    UBII_CHANNEL_SERVICE = 0, /* tcp://host:port (ZMQ REQ) or http(s)://host:port/services/binary */
    UBII_CHANNEL_TOPIC = 1,   /* tcp://host:port (ZMQ DEALER) or ws(s)://host:port */
    UBII_CHANNEL_COUNT = 2
} ubii_channel;

typedef enum ubii_channel_state {
    UBII_CHANNEL_CLOSED = 0,     /* never opened, or closed by the core */
    UBII_CHANNEL_CONNECTING = 1, /* opened; the connection is not established yet */
    UBII_CHANNEL_OPEN = 2,       /* messages flow */
    UBII_CHANNEL_LOST = 3 /* was open or connecting and failed; the core closes and retries */
} ubii_channel_state;

/* Message flags. A WebSocket text frame carries UBII_MESSAGE_TEXT (the master's PING is one). */
#define UBII_MESSAGE_TEXT 1u

/* An fd and the poll(2) events to watch for an external event loop. */
typedef struct ubii_pollfd {
    int fd;
    short events;
} ubii_pollfd;

typedef struct ubii_port_vtable {
    /* Starts connecting `channel` to `url`. For the topic channel, `client_id` is the identity the
     * master knows the node by (ZMQ routing id, or WebSocket ?clientID=). UBII_ERR_UNSUPPORTED for
     * a URL scheme the port lacks. Opening an open channel first closes it. */
    ubii_status (*open)(void *port, ubii_channel channel, const char *url, const char *client_id);
    /* Closes the channel and drops whatever it has queued in either direction. */
    void (*close)(void *port, ubii_channel channel);
    ubii_channel_state (*state)(void *port, ubii_channel channel);
    /* Reserves room for one whole outgoing message of exactly `size` bytes and lends it through
     * *buffer until send_commit(); UBII_ERR_WOULD_BLOCK when the channel cannot take it now,
     * UBII_ERR_TOO_LARGE over the port's limit. */
    ubii_status (*send_begin)(void *port, ubii_channel channel, size_t size, uint8_t **buffer);
    /* Queues the message written into the reserved buffer; `flags` may hold UBII_MESSAGE_TEXT.
     * A port may hold it back to send it together with others, but no later than the next
     * wait(), and it must then report the fd writable-interest in pollfds(). */
    ubii_status (*send_commit)(void *port, ubii_channel channel, unsigned flags);
    /* Takes the next whole received message: UBII_OK with data, size and flags set, or
     * UBII_ERR_WOULD_BLOCK when there is none. A message over the port's limit is dropped there
     * (never buffered) and reported once as UBII_ERR_TOO_LARGE; the channel stays usable. */
    ubii_status (*receive)(void *port, ubii_channel channel, const uint8_t **data, size_t *size,
                           unsigned *flags);
    /* Does pending I/O, waiting at most timeout_ms (0: not at all) for something to happen. */
    ubii_status (*wait)(void *port, int timeout_ms);
    /* Fills up to `capacity` fds an external loop should watch; returns how many there are. */
    int (*pollfds)(void *port, ubii_pollfd *fds, int capacity);
    /* Milliseconds on a monotonic clock, and since the Unix epoch (for record timestamps). */
    uint64_t (*monotonic_ms)(void *port);
    int64_t (*epoch_ms)(void *port);
} ubii_port_vtable;

typedef struct ubii_port {
    const ubii_port_vtable *vtable;
    void *context; /* passed as `port` to every function */
} ubii_port;

#ifdef __cplusplus
}
#endif

#endif

#ifndef UBII_PORT_EMBEDDED_H
#define UBII_PORT_EMBEDDED_H

/* The embedded port: ZMTP 3 (ZMQ's wire protocol, for tcp://), WebSocket (ws://) and HTTP/1.1
 * POST (http://) written directly over non-blocking BSD sockets. No third-party library, no heap,
 * no threads, no global state: the application owns the port object and every buffer is inside
 * it, sized by the macros below.
 *
 *     static ubii_embedded_port port;
 *     ubii_embedded_port_init(&port, ubii_embedded_posix_platform());
 *     ubii_node_init(&node, sizeof node, &config, ubii_embedded_port_get(&port));
 *
 * Hosts in URLs must be IPv4 addresses (no resolver is assumed). No TLS. */

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "ubii/embedded_config.h"
#include "ubii/export.h"
#include "ubii/port.h"
#include "ubii/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* What the port needs from the platform; a firmware supplies its own. */
typedef struct ubii_embedded_platform {
    uint64_t (*monotonic_ms)(void *user);
    int64_t (*epoch_ms)(void *user);
    /* Unpredictable bytes, for WebSocket keys and masks. */
    void (*random_bytes)(void *user, uint8_t *bytes, size_t count);
    void *user;
} ubii_embedded_platform;

/* Hooks for a POSIX system (clock_gettime, getrandom). */
UBII_API ubii_embedded_platform ubii_embedded_posix_platform(void);

/* One connection's state; the layout is not an API. */
typedef struct ubii__embedded_channel {
    int fd;
    uint8_t protocol; /* ZMTP, WebSocket or HTTP */
    uint8_t phase;    /* connecting, handshaking, open */
    uint8_t zmq_type; /* REQ or DEALER */
    uint8_t step;     /* within the handshake, or within an HTTP reply */
    uint8_t refills;  /* further reads receive() may still do before the next wait */
    bool drained;     /* the last read emptied the socket: another would find nothing */
    ubii_channel_state state;
    uint32_t address; /* IPv4, network order */
    uint16_t port;
    char path[UBII_EMBEDDED_MAX_PATH];
    char identity[UBII_MAX_CLIENT_ID_SIZE];
    char websocket_key[32];
    uint64_t discard; /* bytes of an over-size message still to skip as they arrive */
    bool lent;        /* rx[0..lent_size) holds the message lent to the core */
    size_t lent_size; /* bytes to drop from rx when the loan ends */
    /* Both point into the port. The service channel's are the same buffer: REQ and HTTP carry a
     * request, then its reply, so the buffer holds one direction at a time. */
    uint8_t *rx;
    uint8_t *tx;
    size_t rx_used;
    size_t tx_used;     /* bytes queued */
    size_t tx_sent;     /* of which already written to the socket */
    size_t reserved;    /* send_begin: payload size reserved */
    size_t reserved_at; /* offset of the reserved payload in tx */
    size_t header_room; /* bytes kept before it for the frame header */
    size_t body_size;   /* HTTP: reply body bytes gathered at the front of rx */
    size_t body_left;   /* HTTP: body bytes still to come (of the reply, or of the chunk) */
} ubii__embedded_channel;

/* The application owns it; it must not be moved while a channel is open (its channels point into
 * its own buffers). */
typedef struct ubii_embedded_port {
    ubii_embedded_platform platform;
    ubii__embedded_channel channels[UBII_CHANNEL_COUNT];
    uint8_t service_buffer[UBII_EMBEDDED_BUFFER];
    uint8_t topic_rx[UBII_EMBEDDED_BUFFER];
    uint8_t topic_tx[UBII_EMBEDDED_BUFFER];
    /* WebSocket masking keys, drawn from the platform in bulk: a getrandom per message would cost
     * more kernel time than the rest of sending it. */
    uint8_t mask_pool[UBII_EMBEDDED_MASK_POOL];
    uint8_t mask_pool_left;
    uint32_t decode_errors; /* malformed frames from the master, dropped */
    char last_error[UBII_EMBEDDED_ERROR_SIZE];
} ubii_embedded_port;

UBII_API ubii_status ubii_embedded_port_init(ubii_embedded_port *port,
                                             ubii_embedded_platform platform);
UBII_API ubii_port ubii_embedded_port_get(ubii_embedded_port *port);
/* Closes both connections. */
UBII_API void ubii_embedded_port_close(ubii_embedded_port *port);
UBII_API const char *ubii_embedded_port_last_error(const ubii_embedded_port *port);

#ifdef __cplusplus
}
#endif

#endif

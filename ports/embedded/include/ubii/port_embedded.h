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

#include "ubii/export.h"
#include "ubii/port.h"
#include "ubii/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Largest message payload either way (a TopicData, a ServiceRequest or ServiceReply). */
#ifndef UBII_EMBEDDED_MAX_MESSAGE
#define UBII_EMBEDDED_MAX_MESSAGE 2048
#endif

/* Room for frame headers and HTTP/WebSocket handshake text next to a message. */
#ifndef UBII_EMBEDDED_HEADROOM
#define UBII_EMBEDDED_HEADROOM 512
#endif

#define UBII_EMBEDDED_BUFFER (UBII_EMBEDDED_MAX_MESSAGE + UBII_EMBEDDED_HEADROOM)

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
    uint8_t step;     /* within the handshake */
    ubii_channel_state state;
    uint32_t address; /* IPv4, network order */
    uint16_t port;
    char path[128];
    char identity[48];
    char websocket_key[32];
    uint64_t discard; /* bytes of an over-size message still to skip as they arrive */
    bool lent;        /* rx[0..lent_size) holds the message lent to the core */
    size_t lent_size; /* bytes to drop from rx when the loan ends */
    uint8_t rx[UBII_EMBEDDED_BUFFER];
    size_t rx_used;
    uint8_t tx[UBII_EMBEDDED_BUFFER];
    size_t tx_used;     /* bytes queued */
    size_t tx_sent;     /* of which already written to the socket */
    size_t reserved;    /* send_begin: payload size reserved */
    size_t reserved_at; /* offset of the reserved payload in tx */
    size_t header_room; /* bytes kept before it for the frame header */
    int http_status;
} ubii__embedded_channel;

typedef struct ubii_embedded_port {
    ubii_embedded_platform platform;
    ubii__embedded_channel channels[UBII_CHANNEL_COUNT];
    uint32_t decode_errors; /* malformed frames from the master, dropped */
    char last_error[96];
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

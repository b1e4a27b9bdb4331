#ifndef UBII_EMBEDDED_INTERNAL_H
#define UBII_EMBEDDED_INTERNAL_H

/* Shared by the embedded port's files: the socket machinery (embedded_port.c) and one driver per
 * protocol (zmtp.c, websocket.c, http.c). A driver works on a channel's buffers only. */

#include "ubii/port_embedded.h"

enum protocol { PROTOCOL_NONE = 0, PROTOCOL_ZMTP, PROTOCOL_WEBSOCKET, PROTOCOL_HTTP };
enum phase { PHASE_IDLE = 0, PHASE_CONNECTING, PHASE_HANDSHAKE, PHASE_OPEN };
enum zmq_type { ZMQ_TYPE_REQ = 0, ZMQ_TYPE_DEALER };

/* What a driver found at the start of rx. */
typedef enum parse_result {
    PARSE_NEED_MORE = 0, /* not a whole unit yet */
    PARSE_SKIP,          /* consumed bytes to drop (handshake, command, control frame) */
    PARSE_MESSAGE,       /* a message: data and size point into rx; consumed is dropped when done */
    PARSE_ERROR,         /* the peer broke the protocol; port->last_error says how */
    PARSE_TOO_LARGE      /* a message over the limit: *consumed bytes and ch->discard more go */
} parse_result;

typedef struct protocol_driver {
    /* Queues what the client says first, once TCP is connected. */
    ubii_status (*on_connected)(ubii_embedded_port *port, ubii__embedded_channel *ch);
    parse_result (*parse)(ubii_embedded_port *port, ubii__embedded_channel *ch,
                          const uint8_t **data, size_t *size, unsigned *flags, size_t *consumed);
    /* Bytes of framing before a payload of `size`. */
    size_t (*header_size)(const ubii__embedded_channel *ch, size_t size);
    /* Writes the framing into tx[at - header_size, at) (and masks the payload if needed). */
    void (*frame)(ubii_embedded_port *port, ubii__embedded_channel *ch, size_t at, size_t size,
                  unsigned flags);
} protocol_driver;

extern const protocol_driver ubii__zmtp_driver;
extern const protocol_driver ubii__websocket_driver;
extern const protocol_driver ubii__http_driver;

/* embedded_port.c */
void ubii__embedded_error(ubii_embedded_port *port, const char *what);
/* Drops a message whose frame of `size` payload bytes starts at rx[payload]: what has arrived
 * goes with *consumed, the rest is skipped as it streams in. Returns PARSE_TOO_LARGE. */
parse_result ubii__embedded_drop(ubii_embedded_port *port, ubii__embedded_channel *ch,
                                 size_t payload, uint64_t size, size_t *consumed);
/* Appends bytes to tx; false if they do not fit. */
bool ubii__embedded_queue(ubii__embedded_channel *ch, const void *bytes, size_t size);

/* websocket.c: the handshake's accept value, base64(SHA-1(key + GUID)). */
void ubii__websocket_accept(const char *key, char accept[32]);
size_t ubii__base64(const uint8_t *bytes, size_t size, char *out);
void ubii__sha1(const uint8_t *data, size_t size, uint8_t digest[20]);

#endif

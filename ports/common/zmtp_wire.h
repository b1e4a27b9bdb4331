#ifndef UBII_ZMTP_WIRE_H
#define UBII_ZMTP_WIRE_H

/* ZMTP 3.0 (rfc.zeromq.org 23/ZMTP) with the NULL mechanism, as a REQ or DEALER peer of the
 * master's REP and ROUTER sockets: the bytes only, no sockets. Shared by the ports that speak ZMTP
 * themselves (the embedded port; the Linux port's in-thread engine).
 *
 * Greeting (64 bytes): 0xFF, 8 padding bytes, 0x7F, version 3.0, mechanism "NULL" padded to 20,
 * as-server 0, 31 filler bytes. Then a READY command with the properties Socket-Type and Identity.
 * Frames: a flags byte (MORE 0x01, LONG 0x02, COMMAND 0x04), a size (1 byte, or 8 big-endian bytes
 * when LONG), the body. REQ puts an empty delimiter frame before each request; REP and ROUTER put
 * one before what they send, which is taken off here. */

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

enum {
    UBII_ZMTP_GREETING_SIZE = 64,
    /* Greeting plus READY with both properties and an identity of up to 47 bytes. */
    UBII_ZMTP_HANDSHAKE_MAX = UBII_ZMTP_GREETING_SIZE + 2 + 6 + 64 + 48,
    UBII_ZMTP_MAX_HEADER = 2 + 9 /* REQ's delimiter, then a LONG frame header */
};

/* Where the handshake is: waiting for the peer's greeting, for its READY, or done. */
typedef enum ubii_zmtp_step {
    UBII_ZMTP_STEP_GREETING = 0,
    UBII_ZMTP_STEP_READY = 1,
    UBII_ZMTP_STEP_OPEN = 2
} ubii_zmtp_step;

typedef enum ubii_zmtp_unit {
    UBII_ZMTP_NEED_MORE = 0, /* not a whole unit at the front yet */
    UBII_ZMTP_SKIP,          /* handshake or command bytes to drop (`consumed`) */
    UBII_ZMTP_MESSAGE,       /* a message's payload, at `payload`, `size` bytes */
    UBII_ZMTP_MISSHAPEN,     /* a whole message not shaped [delimiter,] payload: drop it */
    UBII_ZMTP_TOO_LARGE,     /* a frame over the limit: its body starts at `payload`, `size` long */
    UBII_ZMTP_ERROR          /* the peer broke the protocol: `error` says how */
} ubii_zmtp_unit;

typedef struct ubii_zmtp_found {
    size_t consumed; /* bytes the unit takes from the front */
    size_t payload;
    uint64_t size;
    const char *error;
} ubii_zmtp_found;

/* Writes the greeting and the READY command into `out`; returns their size, 0 if `capacity` (or
 * the identity's 255-byte limit) is too small. A DEALER announces `identity` (the master routes
 * topic data by it); REQ sends none. */
size_t ubii__zmtp_handshake(uint8_t *out, size_t capacity, bool dealer, const char *identity);

/* Looks at the front of bytes[0, used). At step OPEN a message is frames up to one without MORE;
 * both of the master's sockets send [empty delimiter, payload]. `step` advances as the peer's
 * greeting and READY are seen; `max_message` bounds every frame. */
ubii_zmtp_unit ubii__zmtp_next(ubii_zmtp_step *step, const uint8_t *bytes, size_t used,
                               uint64_t max_message, ubii_zmtp_found *found);

/* Framing before an outgoing payload of `size`: REQ's empty delimiter, then the frame header. */
size_t ubii__zmtp_header_size(bool request, size_t size);
void ubii__zmtp_write_header(uint8_t *header, bool request, size_t size);

#endif

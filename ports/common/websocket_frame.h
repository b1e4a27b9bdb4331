#ifndef UBII_WEBSOCKET_FRAME_H
#define UBII_WEBSOCKET_FRAME_H

/* Client-side WebSocket framing (RFC 6455 §5.2), shared by the ports that frame messages
 * themselves: the embedded port always, the Linux port to hand libwebsockets many frames in one
 * write. A client frame is always masked. */

#include <stddef.h>
#include <stdint.h>
#include <string.h>

enum {
    UBII_WS_OPCODE_CONTINUATION = 0,
    UBII_WS_OPCODE_TEXT = 1,
    UBII_WS_OPCODE_BINARY = 2,
    UBII_WS_OPCODE_CLOSE = 8,
    UBII_WS_OPCODE_PING = 9,
    UBII_WS_OPCODE_PONG = 10,
    UBII_WS_FIN = 0x80,
    UBII_WS_MASKED = 0x80,
    UBII_WS_MAX_CLIENT_HEADER = 14
};

/* Bytes of header before a payload of `size`, masking key included. */
static inline size_t ubii__ws_client_header_size(size_t size)
{
    return (size < 126 ? 2 : size <= 0xFFFF ? 4 : 10) + 4;
}

/* Writes the header of a final frame into header[0, ubii__ws_client_header_size(size)). */
static inline void ubii__ws_write_client_header(uint8_t *header, int opcode, size_t size,
                                                const uint8_t mask[4])
{
    uint8_t *p = header;
    *p++ = (uint8_t)(UBII_WS_FIN | opcode);
    if (size < 126) {
        *p++ = (uint8_t)(UBII_WS_MASKED | size);
    } else if (size <= 0xFFFF) {
        *p++ = UBII_WS_MASKED | 126;
        *p++ = (uint8_t)(size >> 8);
        *p++ = (uint8_t)size;
    } else {
        *p++ = UBII_WS_MASKED | 127;
        for (int shift = 56; shift >= 0; shift -= 8) {
            *p++ = (uint8_t)((uint64_t)size >> shift);
        }
    }
    memcpy(p, mask, 4);
}

/* XORs the payload with the key in place, eight bytes at a time where it can (both the key and
 * the bytes are taken in memory order, so this holds on either byte order). */
static inline void ubii__ws_mask(uint8_t *payload, size_t size, const uint8_t mask[4])
{
    uint32_t key4;
    memcpy(&key4, mask, 4);
    uint64_t key8 = (uint64_t)key4 | (uint64_t)key4 << 32;
    size_t i = 0;
    for (; i + 8 <= size; i += 8) {
        uint64_t word;
        memcpy(&word, payload + i, 8);
        word ^= key8;
        memcpy(payload + i, &word, 8);
    }
    for (; i < size; ++i) {
        payload[i] ^= mask[i & 3];
    }
}

#endif

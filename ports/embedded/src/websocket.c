/* WebSocket client (RFC 6455) for topic data: the HTTP/1.1 upgrade with a random key, then frames.
 * Client frames are masked; the master's are not. A fragmented message is joined in place in the
 * receive buffer. WebSocket-level PING is answered with PONG; CLOSE ends the channel. The master's
 * keepalive is a text message "PING" (not a control frame) and goes to the node like any other. */
#include <stdio.h>
#include <string.h>
#include <strings.h>

#include "embedded_internal.h"
#include "websocket_frame.h"

static ubii_status on_connected(ubii_embedded_port *port, ubii__embedded_channel *ch)
{
    uint8_t nonce[16];
    port->platform.random_bytes(port->platform.user, nonce, sizeof nonce);
    ubii__base64(nonce, sizeof nonce, ch->websocket_key);
    uint8_t ip[4];
    memcpy(ip, &ch->address, 4);
    char request[UBII_EMBEDDED_HEADROOM];
    int length = snprintf(request, sizeof request,
                          "GET %s HTTP/1.1\r\nHost: %u.%u.%u.%u:%u\r\nUpgrade: websocket\r\n"
                          "Connection: Upgrade\r\nSec-WebSocket-Key: %s\r\n"
                          "Sec-WebSocket-Version: 13\r\n\r\n",
                          ch->path, ip[0], ip[1], ip[2], ip[3], ch->port, ch->websocket_key);
    if (length < 0 || (size_t)length >= sizeof request ||
        !ubii__embedded_queue(ch, request, (size_t)length)) {
        ubii__embedded_error(port, "WebSocket handshake does not fit the buffer");
        return UBII_ERR_TOO_LARGE;
    }
    return UBII_OK;
}

/* The end of the HTTP head in rx (just after the blank line), or 0. */
static size_t head_end(const ubii__embedded_channel *ch)
{
    for (size_t i = 3; i < ch->rx_used; ++i) {
        if (memcmp(ch->rx + i - 3, "\r\n\r\n", 4) == 0) {
            return i + 1;
        }
    }
    return 0;
}

/* The value of header `name` in the head, copied NUL-terminated; false if absent. */
static bool header_value(const ubii__embedded_channel *ch, size_t end, const char *name,
                         char *value, size_t capacity)
{
    size_t name_size = strlen(name);
    for (size_t i = 0; i + name_size + 1 < end; ++i) {
        bool line_start = i >= 2 && ch->rx[i - 1] == '\n';
        if (!line_start || strncasecmp((const char *)ch->rx + i, name, name_size) != 0 ||
            ch->rx[i + name_size] != ':') {
            continue;
        }
        size_t at = i + name_size + 1;
        while (at < end && ch->rx[at] == ' ') {
            at++;
        }
        size_t length = 0;
        while (at + length < end && ch->rx[at + length] != '\r' && length + 1 < capacity) {
            length++;
        }
        memcpy(value, ch->rx + at, length);
        value[length] = '\0';
        return true;
    }
    return false;
}

static parse_result parse_handshake(ubii_embedded_port *port, ubii__embedded_channel *ch,
                                    size_t *consumed)
{
    size_t end = head_end(ch);
    if (end == 0) {
        if (ch->rx_used == UBII_EMBEDDED_BUFFER) {
            ubii__embedded_error(port, "WebSocket handshake reply too long");
            return PARSE_ERROR;
        }
        return PARSE_NEED_MORE;
    }
    char expected[32], accept[64];
    ubii__websocket_accept(ch->websocket_key, expected);
    if (end < 12 || memcmp(ch->rx, "HTTP/1.1 101", 12) != 0) {
        ubii__embedded_error(port, "WebSocket upgrade refused");
        return PARSE_ERROR;
    }
    if (!header_value(ch, end, "Sec-WebSocket-Accept", accept, sizeof accept) ||
        strcmp(accept, expected) != 0) {
        ubii__embedded_error(port, "WebSocket upgrade: wrong Sec-WebSocket-Accept");
        return PARSE_ERROR;
    }
    ch->phase = PHASE_OPEN;
    ch->state = UBII_CHANNEL_OPEN;
    *consumed = end;
    return PARSE_SKIP;
}

/* One frame header at rx[at]: fin, opcode, payload offset and size; false if incomplete. */
static bool read_header(const ubii__embedded_channel *ch, size_t at, bool *fin, int *opcode,
                        size_t *payload, uint64_t *size, bool *masked)
{
    if (ch->rx_used < at + 2) {
        return false;
    }
    *fin = ch->rx[at] & UBII_WS_FIN;
    *opcode = ch->rx[at] & 0x0F;
    *masked = ch->rx[at + 1] & UBII_WS_MASKED;
    uint64_t length = ch->rx[at + 1] & 0x7F;
    size_t header = 2;
    if (length == 126 || length == 127) {
        size_t extra = length == 126 ? 2 : 8;
        if (ch->rx_used < at + 2 + extra) {
            return false;
        }
        length = 0;
        for (size_t i = 0; i < extra; ++i) {
            length = length << 8 | ch->rx[at + 2 + i];
        }
        header += extra;
    }
    *payload = at + header + (*masked ? 4 : 0);
    *size = length;
    return ch->rx_used >= *payload;
}

static void send_control(ubii_embedded_port *port, ubii__embedded_channel *ch, int opcode,
                         const uint8_t *payload, size_t size);

static parse_result parse(ubii_embedded_port *port, ubii__embedded_channel *ch,
                          const uint8_t **data, size_t *size, unsigned *flags, size_t *consumed)
{
    if (ch->phase != PHASE_OPEN) {
        return parse_handshake(port, ch, consumed);
    }
    /* First check that a whole message (or a control frame) is there without touching rx, so
     * that a half-received fragmented message is left intact for the next call. */
    size_t at = 0;
    bool complete = false;
    int message_opcode = -1;
    for (;;) {
        bool fin, masked;
        int opcode;
        size_t payload;
        uint64_t frame_size;
        if (!read_header(ch, at, &fin, &opcode, &payload, &frame_size, &masked)) {
            break;
        }
        if (masked) {
            ubii__embedded_error(port, "masked frame from the server");
            return PARSE_ERROR;
        }
        if (frame_size > UBII_EMBEDDED_MAX_MESSAGE) {
            if (at != 0 || opcode == UBII_WS_OPCODE_CONTINUATION) {
                ubii__embedded_error(port, "WebSocket fragment over UBII_EMBEDDED_MAX_MESSAGE");
                return PARSE_ERROR;
            }
            return ubii__embedded_drop(port, ch, payload, frame_size, consumed);
        }
        if (ch->rx_used < payload + frame_size) {
            break;
        }
        size_t next = payload + (size_t)frame_size;
        if (opcode >= UBII_WS_OPCODE_CLOSE) {
            if (opcode == UBII_WS_OPCODE_CLOSE) {
                ubii__embedded_error(port, "WebSocket closed by the master");
                return PARSE_ERROR;
            }
            if (message_opcode < 0) { /* a control frame on its own */
                if (opcode == UBII_WS_OPCODE_PING) {
                    send_control(port, ch, UBII_WS_OPCODE_PONG, ch->rx + payload,
                                 (size_t)frame_size);
                }
                *consumed = next;
                return PARSE_SKIP;
            }
            at = next; /* between fragments: dealt with when joining */
            continue;
        }
        if ((message_opcode < 0) != (opcode != UBII_WS_OPCODE_CONTINUATION) ||
            (opcode != UBII_WS_OPCODE_CONTINUATION && opcode != UBII_WS_OPCODE_TEXT &&
             opcode != UBII_WS_OPCODE_BINARY)) {
            ubii__embedded_error(port, "WebSocket fragments out of order");
            return PARSE_ERROR;
        }
        if (message_opcode < 0) {
            message_opcode = opcode;
        }
        at = next;
        if (fin) {
            complete = true;
            break;
        }
    }
    if (!complete) {
        if (ch->rx_used == UBII_EMBEDDED_BUFFER) {
            ubii__embedded_error(port, "WebSocket message larger than the receive buffer");
            return PARSE_ERROR;
        }
        return PARSE_NEED_MORE;
    }
    /* Then join the fragments' payloads at the front of rx, answering PINGs met between them. */
    size_t joined = 0;
    at = 0;
    for (;;) {
        /* The first pass checked every header; the initial values only quiet -O3's
         * maybe-uninitialized analysis, which cannot see that. */
        bool fin = true, masked = false;
        int opcode = UBII_WS_OPCODE_CLOSE;
        size_t payload = 0;
        uint64_t frame_size = 0;
        read_header(ch, at, &fin, &opcode, &payload, &frame_size, &masked);
        size_t next = payload + (size_t)frame_size;
        if (opcode == UBII_WS_OPCODE_PING) {
            send_control(port, ch, UBII_WS_OPCODE_PONG, ch->rx + payload, (size_t)frame_size);
        }
        if (opcode < UBII_WS_OPCODE_CLOSE) {
            memmove(ch->rx + joined, ch->rx + payload, (size_t)frame_size);
            joined += (size_t)frame_size;
        }
        /* The framing between the joined bytes and the next frame is spent: close the gap. */
        memmove(ch->rx + joined, ch->rx + next, ch->rx_used - next);
        ch->rx_used -= next - joined;
        at = joined;
        if (opcode < UBII_WS_OPCODE_CLOSE && fin) {
            break;
        }
    }
    *data = ch->rx;
    *size = joined;
    *flags = message_opcode == UBII_WS_OPCODE_TEXT ? UBII_MESSAGE_TEXT : 0;
    *consumed = joined;
    return PARSE_MESSAGE;
}

static size_t header_size(const ubii__embedded_channel *ch, size_t size)
{
    (void)ch;
    return ubii__ws_client_header_size(size);
}

static void frame_opcode(ubii_embedded_port *port, ubii__embedded_channel *ch, size_t at,
                         size_t size, int opcode)
{
    if (port->mask_pool_left < 4) {
        port->platform.random_bytes(port->platform.user, port->mask_pool, sizeof port->mask_pool);
        port->mask_pool_left = sizeof port->mask_pool;
    }
    port->mask_pool_left -= 4;
    const uint8_t *mask = port->mask_pool + port->mask_pool_left;
    ubii__ws_write_client_header(ch->tx + at - header_size(ch, size), opcode, size, mask);
    ubii__ws_mask(ch->tx + at, size, mask);
}

static void frame(ubii_embedded_port *port, ubii__embedded_channel *ch, size_t at, size_t size,
                  unsigned flags)
{
    frame_opcode(port, ch, at, size,
                 flags & UBII_MESSAGE_TEXT ? UBII_WS_OPCODE_TEXT : UBII_WS_OPCODE_BINARY);
}

static void send_control(ubii_embedded_port *port, ubii__embedded_channel *ch, int opcode,
                         const uint8_t *payload, size_t size)
{
    size_t header = header_size(ch, size);
    /* Not while the core writes a message into tx (header_room), nor without room. */
    if (size > 125 || ch->header_room != 0 || ch->tx_used + header + size > UBII_EMBEDDED_BUFFER) {
        return; /* the peer will ask again */
    }
    size_t at = ch->tx_used + header;
    memcpy(ch->tx + at, payload, size);
    frame_opcode(port, ch, at, size, opcode);
    ch->tx_used = at + size;
}

const protocol_driver ubii__websocket_driver = {on_connected, parse, header_size, frame};

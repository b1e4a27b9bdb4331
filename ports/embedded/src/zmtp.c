/* ZMTP 3.0 (rfc.zeromq.org 23/ZMTP) with the NULL mechanism, as a REQ or DEALER peer of the
 * master's REP and ROUTER sockets.
 *
 * Greeting (64 bytes): 0xFF, 8 padding bytes, 0x7F, version 3.0, mechanism "NULL" padded to 20,
 * as-server 0, 31 filler bytes. Then a READY command with the properties Socket-Type and Identity.
 * Frames: a flags byte (MORE 0x01, LONG 0x02, COMMAND 0x04), a size (1 byte, or 8 big-endian bytes
 * when LONG), the body. REQ puts an empty delimiter frame before each request; REP and ROUTER put
 * one before what they send, which is taken off here. */
#include <string.h>

#include "embedded_internal.h"

enum {
    GREETING_SIZE = 64,
    FLAG_MORE = 0x01,
    FLAG_LONG = 0x02,
    FLAG_COMMAND = 0x04,
    STEP_GREETING = 0, /* waiting for the master's greeting */
    STEP_READY = 1     /* waiting for its READY command */
};

static bool put_property(uint8_t *out, size_t capacity, size_t *used, const char *name,
                         const char *value)
{
    size_t name_size = strlen(name), value_size = strlen(value);
    if (*used + 1 + name_size + 4 + value_size > capacity) {
        return false;
    }
    out[(*used)++] = (uint8_t)name_size;
    memcpy(out + *used, name, name_size);
    *used += name_size;
    out[(*used)++] = (uint8_t)(value_size >> 24);
    out[(*used)++] = (uint8_t)(value_size >> 16);
    out[(*used)++] = (uint8_t)(value_size >> 8);
    out[(*used)++] = (uint8_t)value_size;
    memcpy(out + *used, value, value_size);
    *used += value_size;
    return true;
}

static ubii_status on_connected(ubii_embedded_port *port, ubii__embedded_channel *ch)
{
    uint8_t greeting[GREETING_SIZE];
    memset(greeting, 0, sizeof greeting);
    greeting[0] = 0xFF;
    greeting[9] = 0x7F;
    greeting[10] = 3; /* version 3.0 */
    greeting[11] = 0;
    memcpy(greeting + 12, "NULL", 4);

    uint8_t ready[2 + 6 + 64 + 48];
    size_t used = 2;
    ready[used++] = 5;
    memcpy(ready + used, "READY", 5);
    used += 5;
    bool fits = put_property(ready, sizeof ready, &used, "Socket-Type",
                             ch->zmq_type == ZMQ_TYPE_DEALER ? "DEALER" : "REQ");
    if (ch->zmq_type == ZMQ_TYPE_DEALER) {
        fits = fits && put_property(ready, sizeof ready, &used, "Identity", ch->identity);
    }
    ready[0] = FLAG_COMMAND;
    ready[1] = (uint8_t)(used - 2);
    ch->step = STEP_GREETING;
    if (!fits || !ubii__embedded_queue(ch, greeting, sizeof greeting) ||
        !ubii__embedded_queue(ch, ready, used)) {
        ubii__embedded_error(port, "ZMTP handshake does not fit the buffer");
        return UBII_ERR_TOO_LARGE;
    }
    return UBII_OK;
}

/* One frame at rx[at]: its flags, body offset and size; false if not all there yet. */
static bool read_frame(const ubii__embedded_channel *ch, size_t at, uint8_t *flags, size_t *body,
                       uint64_t *size)
{
    if (ch->rx_used < at + 2) {
        return false;
    }
    *flags = ch->rx[at];
    if (*flags & FLAG_LONG) {
        if (ch->rx_used < at + 9) {
            return false;
        }
        *size = 0;
        for (int i = 1; i <= 8; ++i) {
            *size = *size << 8 | ch->rx[at + (size_t)i];
        }
        *body = at + 9;
    } else {
        *size = ch->rx[at + 1];
        *body = at + 2;
    }
    return true;
}

static parse_result parse_handshake(ubii_embedded_port *port, ubii__embedded_channel *ch,
                                    size_t *consumed)
{
    if (ch->step == STEP_GREETING) {
        if (ch->rx_used < GREETING_SIZE) {
            return PARSE_NEED_MORE;
        }
        if (ch->rx[0] != 0xFF || (ch->rx[9] & 1) != 1 || ch->rx[10] < 3 ||
            memcmp(ch->rx + 12, "NULL", 4) != 0) {
            ubii__embedded_error(port, "the peer does not speak ZMTP 3 with the NULL mechanism");
            return PARSE_ERROR;
        }
        ch->step = STEP_READY;
        *consumed = GREETING_SIZE;
        return PARSE_SKIP;
    }
    uint8_t flags;
    size_t body;
    uint64_t size;
    if (!read_frame(ch, 0, &flags, &body, &size)) {
        return PARSE_NEED_MORE;
    }
    if (!(flags & FLAG_COMMAND) || size > UBII_EMBEDDED_BUFFER - body) {
        ubii__embedded_error(port, "ZMTP handshake: expected a READY command");
        return PARSE_ERROR;
    }
    if (ch->rx_used < body + size) {
        return PARSE_NEED_MORE;
    }
    if (size < 6 || ch->rx[body] != 5 || memcmp(ch->rx + body + 1, "READY", 5) != 0) {
        ubii__embedded_error(port, "ZMTP handshake refused by the peer");
        return PARSE_ERROR;
    }
    ch->phase = PHASE_OPEN;
    ch->state = UBII_CHANNEL_OPEN;
    *consumed = body + (size_t)size;
    return PARSE_SKIP;
}

/* A message is frames up to one without MORE. Both of the master's sockets send
 * [empty delimiter, payload]; anything else is dropped whole. */
static parse_result parse(ubii_embedded_port *port, ubii__embedded_channel *ch,
                          const uint8_t **data, size_t *size, unsigned *message_flags,
                          size_t *consumed)
{
    if (ch->phase != PHASE_OPEN) {
        return parse_handshake(port, ch, consumed);
    }
    size_t at = 0;
    int frames = 0;
    size_t payload = 0, payload_size = 0;
    bool shaped = true;
    for (;;) {
        uint8_t flags;
        size_t body;
        uint64_t frame_size;
        if (!read_frame(ch, at, &flags, &body, &frame_size)) {
            break;
        }
        if (frame_size > UBII_EMBEDDED_MAX_MESSAGE) {
            return ubii__embedded_drop(port, ch, body, frame_size, consumed);
        }
        if (ch->rx_used < body + frame_size) {
            break;
        }
        at = body + (size_t)frame_size;
        if (flags & FLAG_COMMAND) { /* e.g. a heartbeat: not part of any message */
            *consumed = at;
            return PARSE_SKIP;
        }
        frames++;
        bool delimiter = frames == 1 && frame_size == 0 && (flags & FLAG_MORE);
        if (!delimiter) {
            shaped = shaped && payload_size == 0 && payload == 0;
            payload = body;
            payload_size = (size_t)frame_size;
        }
        if (!(flags & FLAG_MORE)) {
            *consumed = at;
            if (!shaped || frames > 2) {
                port->decode_errors++;
                return PARSE_SKIP;
            }
            *data = ch->rx + payload;
            *size = payload_size;
            *message_flags = 0;
            return PARSE_MESSAGE;
        }
        if (frames >= 2) { /* more than [delimiter, payload]: not from the master */
            shaped = false;
        }
    }
    if (ch->rx_used == UBII_EMBEDDED_BUFFER) {
        ubii__embedded_error(port, "ZMTP message larger than the receive buffer");
        return PARSE_ERROR;
    }
    return PARSE_NEED_MORE;
}

static size_t frame_header(size_t size)
{
    return size > 255 ? 9 : 2;
}

static size_t header_size(const ubii__embedded_channel *ch, size_t size)
{
    return (ch->zmq_type == ZMQ_TYPE_REQ ? 2 : 0) + frame_header(size);
}

static void frame(ubii_embedded_port *port, ubii__embedded_channel *ch, size_t at, size_t size,
                  unsigned flags)
{
    (void)port;
    (void)flags;
    uint8_t *p = ch->tx + at - header_size(ch, size);
    if (ch->zmq_type == ZMQ_TYPE_REQ) {
        *p++ = FLAG_MORE; /* the empty delimiter */
        *p++ = 0;
    }
    if (size > 255) {
        *p++ = FLAG_LONG;
        for (int shift = 56; shift >= 0; shift -= 8) {
            *p++ = (uint8_t)((uint64_t)size >> shift);
        }
    } else {
        *p++ = 0;
        *p++ = (uint8_t)size;
    }
}

const protocol_driver ubii__zmtp_driver = {on_connected, parse, header_size, frame};

#include "zmtp_wire.h"

#include "ubii/config.h"

#include <string.h>

enum { FLAG_MORE = 0x01, FLAG_LONG = 0x02, FLAG_COMMAND = 0x04, FLAGS_RESERVED = 0xF8 };

static bool put_property(uint8_t *out, size_t capacity, size_t *used, const char *name,
                         const char *value)
{
    size_t name_size = strlen(name), value_size = strlen(value);
    if (name_size > 255 || *used + 1 + name_size + 4 + value_size > capacity) {
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

size_t ubii__zmtp_handshake(uint8_t *out, size_t capacity, bool dealer, const char *identity)
{
    if (capacity < UBII_ZMTP_GREETING_SIZE + 8) {
        return 0;
    }
    memset(out, 0, UBII_ZMTP_GREETING_SIZE);
    out[0] = 0xFF;
    out[9] = 0x7F;
    out[10] = 3; /* version 3.0 */
    out[11] = 0;
    memcpy(out + 12, "NULL", 4);

    uint8_t *ready = out + UBII_ZMTP_GREETING_SIZE;
    size_t room = capacity - UBII_ZMTP_GREETING_SIZE;
    if (room > 2 + 255) {
        room = 2 + 255; /* a short frame: the command's size fits one byte */
    }
    size_t used = 2;
    ready[used++] = 5;
    memcpy(ready + used, "READY", 5);
    used += 5;
    bool fits = put_property(ready, room, &used, "Socket-Type", dealer ? "DEALER" : "REQ");
    if (dealer) {
        fits = fits && put_property(ready, room, &used, "Identity", identity);
    }
    if (!fits) {
        return 0;
    }
    ready[0] = FLAG_COMMAND;
    ready[1] = (uint8_t)(used - 2);
    return UBII_ZMTP_GREETING_SIZE + used;
}

/* One frame at bytes[at]: its flags, body offset and size; false if its header is not all there. */
static bool read_frame(const uint8_t *bytes, size_t used, size_t at, uint8_t *flags, size_t *body,
                       uint64_t *size)
{
    if (used < at + 2) {
        return false;
    }
    *flags = bytes[at];
    if (*flags & FLAG_LONG) {
        if (used < at + 9) {
            return false;
        }
        *size = 0;
        for (int i = 1; i <= 8; ++i) {
            *size = *size << 8 | bytes[at + (size_t)i];
        }
        *body = at + 9;
    } else {
        *size = bytes[at + 1];
        *body = at + 2;
    }
    return true;
}

static ubii_zmtp_unit fail(ubii_zmtp_found *found, const char *error)
{
    found->error = error;
    return UBII_ZMTP_ERROR;
}

static ubii_zmtp_unit next_handshake_unit(ubii_zmtp_step *step, const uint8_t *bytes, size_t used,
                                          uint64_t max_message, ubii_zmtp_found *found)
{
    if (*step == UBII_ZMTP_STEP_GREETING) {
        if (used < UBII_ZMTP_GREETING_SIZE) {
            return UBII_ZMTP_NEED_MORE;
        }
        if (bytes[0] != 0xFF || (bytes[9] & 1) != 1 || bytes[10] < 3 ||
            memcmp(bytes + 12, "NULL", 4) != 0) {
            return fail(found, "the peer does not speak ZMTP 3 with the NULL mechanism");
        }
        *step = UBII_ZMTP_STEP_READY;
        found->consumed = UBII_ZMTP_GREETING_SIZE;
        return UBII_ZMTP_SKIP;
    }
    uint8_t flags;
    size_t body;
    uint64_t size;
    if (!read_frame(bytes, used, 0, &flags, &body, &size)) {
        return UBII_ZMTP_NEED_MORE;
    }
    if (!(flags & FLAG_COMMAND) || size > max_message) {
        return fail(found, "ZMTP handshake: expected a READY command");
    }
    if (used - body < size) {
        return UBII_ZMTP_NEED_MORE;
    }
    if (size < 6 || bytes[body] != 5 || memcmp(bytes + body + 1, "READY", 5) != 0) {
        return fail(found, "ZMTP handshake refused by the peer");
    }
    *step = UBII_ZMTP_STEP_OPEN;
    found->consumed = body + (size_t)size;
    return UBII_ZMTP_SKIP;
}

ubii_zmtp_unit ubii__zmtp_next(ubii_zmtp_step *step, const uint8_t *bytes, size_t used,
                               uint64_t max_message, ubii_zmtp_found *found)
{
    memset(found, 0, sizeof *found);
    if (*step != UBII_ZMTP_STEP_OPEN) {
        return next_handshake_unit(step, bytes, used, max_message, found);
    }
    size_t at = 0;
    int frames = 0;
    size_t payload = 0, payload_size = 0;
    bool shaped = true;
    for (;;) {
        uint8_t flags;
        size_t body;
        uint64_t frame_size;
        /* Bytes no ZMTP peer sends: the stream is broken (corrupted, or not ZMTP), and a size
         * read from it would have the receiver skip whatever follows. Seen in the first byte. */
        if (used > at && ((bytes[at] & FLAGS_RESERVED) ||
                          ((bytes[at] & FLAG_COMMAND) && (bytes[at] & FLAG_MORE)))) {
            return fail(found, "ZMTP frame with invalid flags: the stream is corrupt");
        }
        if (!read_frame(bytes, used, at, &flags, &body, &frame_size)) {
            return UBII_ZMTP_NEED_MORE;
        }
        if (frame_size > UBII_MAX_MESSAGE_SIZE) {
            return fail(found, "ZMTP frame larger than any message (UBII_MAX_MESSAGE_SIZE)");
        }
        if (frame_size > max_message) {
            found->payload = body;
            found->size = frame_size;
            return UBII_ZMTP_TOO_LARGE;
        }
        if (used - body < frame_size) {
            return UBII_ZMTP_NEED_MORE;
        }
        at = body + (size_t)frame_size;
        if (flags & FLAG_COMMAND) { /* e.g. a heartbeat: not part of any message */
            found->consumed = at;
            return UBII_ZMTP_SKIP;
        }
        frames++;
        bool delimiter = frames == 1 && frame_size == 0 && (flags & FLAG_MORE);
        if (!delimiter) {
            shaped = shaped && payload_size == 0 && payload == 0;
            payload = body;
            payload_size = (size_t)frame_size;
        }
        if (!(flags & FLAG_MORE)) {
            found->consumed = at;
            if (!shaped || frames > 2) {
                return UBII_ZMTP_MISSHAPEN;
            }
            found->payload = payload;
            found->size = payload_size;
            return UBII_ZMTP_MESSAGE;
        }
        if (frames >= 2) { /* more than [delimiter, payload]: not from the master */
            shaped = false;
        }
    }
}

size_t ubii__zmtp_header_size(bool request, size_t size)
{
    return (request ? 2u : 0u) + (size > 255 ? 9u : 2u);
}

void ubii__zmtp_write_header(uint8_t *header, bool request, size_t size)
{
    uint8_t *p = header;
    if (request) {
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

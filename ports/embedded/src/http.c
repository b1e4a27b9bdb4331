/* HTTP/1.1 client for binary services: POST path with Content-Type application/octet-stream, one
 * request per connection ("Connection: close"). The reply must be 200 and carry its body with a
 * Content-Length or in chunks (Transfer-Encoding: chunked; extensions and trailers are skipped).
 *
 * The reply is parsed as it arrives: head lines are dropped once read, chunk framing is removed
 * in place, and the body gathers at the front of rx (ch->body_size bytes; ch->body_left more to
 * come). So rx holds the body and at most one head line, never the whole head. */
#include <stdio.h>
#include <string.h>
#include <strings.h>

#include "embedded_internal.h"

enum reply_step {
    STATUS_LINE = 0,
    HEADER_LINE,         /* no framing known yet */
    HEADER_LINE_LENGTH,  /* Content-Length seen (in body_left) */
    HEADER_LINE_CHUNKED, /* Transfer-Encoding: chunked seen */
    HEADER_LINE_INTERIM, /* of a 1xx reply, which another reply follows */
    BODY,                /* Content-Length bytes */
    CHUNK_SIZE_START,
    CHUNK_SIZE,
    CHUNK_SIZE_LF,
    CHUNK_EXTENSION,
    CHUNK_DATA,
    CHUNK_DATA_CR,
    CHUNK_DATA_LF,
    TRAILER_START,
    TRAILER_LINE,
    TRAILER_END_LF,
    REPLY_DONE
};

static bool in_head(uint8_t step)
{
    return step <= HEADER_LINE_INTERIM;
}

static ubii_status on_connected(ubii_embedded_port *port, ubii__embedded_channel *ch)
{
    (void)port;
    (void)ch; /* the request is already queued */
    return UBII_OK;
}

static int request_head(const ubii__embedded_channel *ch, size_t size, char *out, size_t capacity)
{
    uint8_t ip[4];
    memcpy(ip, &ch->address, 4);
    return snprintf(out, capacity,
                    "POST %s HTTP/1.1\r\nHost: %u.%u.%u.%u:%u\r\n"
                    "Content-Type: application/octet-stream\r\nContent-Length: %zu\r\n"
                    "Connection: close\r\n\r\n",
                    ch->path, ip[0], ip[1], ip[2], ip[3], ch->port, size);
}

static size_t header_size(const ubii__embedded_channel *ch, size_t size)
{
    int length = request_head(ch, size, NULL, 0);
    return length > 0 ? (size_t)length : 0;
}

static void frame(ubii_embedded_port *port, ubii__embedded_channel *ch, size_t at, size_t size,
                  unsigned flags)
{
    (void)port;
    (void)flags;
    size_t head = header_size(ch, size);
    char *text = (char *)ch->tx + at - head;
    /* snprintf ends with a NUL where the body starts: it writes all but the last character (the
     * head's final '\n'), which is put back by hand. */
    request_head(ch, size, text, head);
    text[head - 1] = '\n';
}

static bool is_space(uint8_t c)
{
    return c == ' ' || c == '\t';
}

static int hex_value(uint8_t c)
{
    if (c >= '0' && c <= '9') {
        return c - '0';
    }
    if (c >= 'a' && c <= 'f') {
        return c - 'a' + 10;
    }
    if (c >= 'A' && c <= 'F') {
        return c - 'A' + 10;
    }
    return -1;
}

/* The value of a header line if its name is `name` (with the colon), else NULL; *length is the
 * value's length without surrounding whitespace. */
static const char *header_value(const char *line, size_t line_length, const char *name,
                                size_t *length)
{
    size_t name_length = strlen(name);
    if (line_length < name_length || strncasecmp(line, name, name_length) != 0) {
        return NULL;
    }
    const char *value = line + name_length, *end = line + line_length;
    while (value < end && is_space((uint8_t)*value)) {
        value++;
    }
    while (end > value && is_space((uint8_t)end[-1])) {
        end--;
    }
    *length = (size_t)(end - value);
    return value;
}

/* Digits only; a value over the limit becomes limit + 1 (it only has to be refused). */
static bool parse_length(const char *text, size_t length, size_t limit, size_t *value)
{
    if (length == 0) {
        return false;
    }
    *value = 0;
    for (size_t i = 0; i < length; ++i) {
        if (text[i] < '0' || text[i] > '9') {
            return false;
        }
        if (*value <= limit) {
            *value = *value * 10 + (size_t)(text[i] - '0');
        }
    }
    if (*value > limit) {
        *value = limit + 1;
    }
    return true;
}

/* "HTTP/1.x NNN reason": the status, or -1. */
static int status_of(const char *line, size_t length)
{
    if (length < 12 || memcmp(line, "HTTP/1.", 7) != 0 || line[8] != ' ' ||
        (length > 12 && line[12] != ' ')) {
        return -1;
    }
    int status = 0;
    for (int i = 9; i < 12; ++i) {
        if (line[i] < '0' || line[i] > '9') {
            return -1;
        }
        status = status * 10 + (line[i] - '0');
    }
    return status;
}

static parse_result fail(ubii_embedded_port *port, const char *why)
{
    ubii__embedded_error(port, why);
    return PARSE_ERROR;
}

/* One line of the head (without its line end); moves ch->step along. */
static parse_result head_line(ubii_embedded_port *port, ubii__embedded_channel *ch,
                              const char *line, size_t length)
{
    if (ch->step == STATUS_LINE) {
        int status = status_of(line, length);
        if (status < 0) {
            return fail(port, "not an HTTP reply");
        }
        if (status >= 100 && status < 200) {
            ch->step = HEADER_LINE_INTERIM;
            return PARSE_NEED_MORE;
        }
        if (status != 200) {
            char text[48];
            snprintf(text, sizeof text, "HTTP service answered with status %d", status);
            return fail(port, text);
        }
        ch->step = HEADER_LINE;
        return PARSE_NEED_MORE;
    }
    if (length == 0) { /* the end of the head */
        switch (ch->step) {
        case HEADER_LINE_INTERIM:
            ch->step = STATUS_LINE;
            return PARSE_NEED_MORE;
        case HEADER_LINE_CHUNKED:
            ch->step = CHUNK_SIZE_START;
            return PARSE_NEED_MORE;
        case HEADER_LINE_LENGTH:
            ch->step = BODY;
            return ch->body_left > UBII_EMBEDDED_MAX_MESSAGE ? PARSE_TOO_LARGE : PARSE_NEED_MORE;
        default:
            return fail(port, "HTTP reply without Content-Length or chunked encoding");
        }
    }
    if (ch->step == HEADER_LINE_INTERIM) {
        return PARSE_NEED_MORE;
    }
    size_t value_length;
    const char *value = header_value(line, length, "Transfer-Encoding:", &value_length);
    if (value != NULL) {
        /* Only chunked alone: another coding (gzip, ...) could not be undone here. */
        if (ch->step == HEADER_LINE_CHUNKED || value_length != 7 ||
            strncasecmp(value, "chunked", 7) != 0) {
            return fail(port, "HTTP transfer coding not supported");
        }
        ch->step = HEADER_LINE_CHUNKED; /* it overrides a Content-Length (RFC 9112 6.3) */
        ch->body_left = 0;
        return PARSE_NEED_MORE;
    }
    value = header_value(line, length, "Content-Length:", &value_length);
    if (value != NULL && ch->step != HEADER_LINE_CHUNKED) {
        size_t content_length;
        if (!parse_length(value, value_length, UBII_EMBEDDED_MAX_MESSAGE, &content_length) ||
            (ch->step == HEADER_LINE_LENGTH && content_length != ch->body_left)) {
            return fail(port, "HTTP reply with a bad Content-Length");
        }
        ch->body_left = content_length;
        ch->step = HEADER_LINE_LENGTH;
    }
    return PARSE_NEED_MORE;
}

/* Takes body bytes from rx[*at] on, which must follow the body gathered so far directly. */
static void take_body(ubii__embedded_channel *ch, size_t *at)
{
    if (*at != ch->body_size) { /* framing between: spent */
        memmove(ch->rx + ch->body_size, ch->rx + *at, ch->rx_used - *at);
        ch->rx_used -= *at - ch->body_size;
        *at = ch->body_size;
    }
    size_t available = ch->rx_used - *at;
    size_t take = available < ch->body_left ? available : ch->body_left;
    ch->body_size += take;
    ch->body_left -= take;
    *at += take;
}

/* One byte of chunk framing. */
static parse_result chunk_byte(ubii_embedded_port *port, ubii__embedded_channel *ch, uint8_t c)
{
    int digit = hex_value(c);
    switch (ch->step) {
    case CHUNK_SIZE_START:
    case CHUNK_SIZE:
        if (digit >= 0) {
            size_t room = UBII_EMBEDDED_MAX_MESSAGE - ch->body_size;
            if (ch->body_left > room / 16 || ch->body_left * 16 + (size_t)digit > room) {
                return PARSE_TOO_LARGE;
            }
            ch->body_left = ch->body_left * 16 + (size_t)digit;
            ch->step = CHUNK_SIZE;
            return PARSE_NEED_MORE;
        }
        if (ch->step == CHUNK_SIZE_START) {
            return fail(port, "HTTP chunk without a size");
        }
        if (c == ';' || is_space(c)) {
            ch->step = CHUNK_EXTENSION;
        } else if (c == '\r') {
            ch->step = CHUNK_SIZE_LF;
        } else if (c == '\n') {
            ch->step = ch->body_left > 0 ? CHUNK_DATA : TRAILER_START;
        } else {
            return fail(port, "HTTP chunk with a bad size");
        }
        return PARSE_NEED_MORE;
    case CHUNK_SIZE_LF:
        if (c != '\n') {
            return fail(port, "HTTP chunk with a bad size");
        }
        ch->step = ch->body_left > 0 ? CHUNK_DATA : TRAILER_START;
        return PARSE_NEED_MORE;
    case CHUNK_EXTENSION:
        if (c == '\n') {
            ch->step = ch->body_left > 0 ? CHUNK_DATA : TRAILER_START;
        }
        return PARSE_NEED_MORE;
    case CHUNK_DATA_CR:
    case CHUNK_DATA_LF:
        if (c == '\r' && ch->step == CHUNK_DATA_CR) {
            ch->step = CHUNK_DATA_LF;
        } else if (c == '\n') {
            ch->step = CHUNK_SIZE_START;
        } else {
            return fail(port, "HTTP chunk longer than its size");
        }
        return PARSE_NEED_MORE;
    case TRAILER_START:
        ch->step = c == '\n' ? REPLY_DONE : c == '\r' ? TRAILER_END_LF : TRAILER_LINE;
        return PARSE_NEED_MORE;
    case TRAILER_LINE:
        if (c == '\n') {
            ch->step = TRAILER_START;
        }
        return PARSE_NEED_MORE;
    default: /* TRAILER_END_LF; read_reply stops at REPLY_DONE */
        if (c != '\n') {
            return fail(port, "HTTP trailer section not ended by CRLF");
        }
        ch->step = REPLY_DONE;
        return PARSE_NEED_MORE;
    }
}

/* Reads rx from the body's end on; *at ends where reading stopped. PARSE_NEED_MORE while the reply
 * goes on, PARSE_SKIP when it is complete. */
static parse_result read_reply(ubii_embedded_port *port, ubii__embedded_channel *ch, size_t *at)
{
    while (*at < ch->rx_used) {
        parse_result result = PARSE_NEED_MORE;
        if (in_head(ch->step)) {
            const uint8_t *start = ch->rx + *at;
            const uint8_t *end = memchr(start, '\n', ch->rx_used - *at);
            if (end == NULL) {
                if (*at == 0 && ch->rx_used == UBII_EMBEDDED_BUFFER) {
                    return fail(port, "HTTP reply head line longer than the buffer");
                }
                return PARSE_NEED_MORE;
            }
            size_t length = (size_t)(end - start);
            *at += length + 1;
            if (length > 0 && start[length - 1] == '\r') {
                length--;
            }
            result = head_line(port, ch, (const char *)start, length);
            if (ch->step == BODY && ch->body_left == 0 && result == PARSE_NEED_MORE) {
                ch->step = REPLY_DONE; /* Content-Length: 0 */
            }
        } else if (ch->step == BODY || ch->step == CHUNK_DATA) {
            take_body(ch, at);
            if (ch->body_left == 0) {
                ch->step = ch->step == BODY ? REPLY_DONE : CHUNK_DATA_CR;
            }
        } else {
            result = chunk_byte(port, ch, ch->rx[(*at)++]);
        }
        if (result != PARSE_NEED_MORE) {
            return result;
        }
        if (ch->step == REPLY_DONE) {
            return PARSE_SKIP;
        }
    }
    return PARSE_NEED_MORE;
}

static parse_result parse(ubii_embedded_port *port, ubii__embedded_channel *ch,
                          const uint8_t **data, size_t *size, unsigned *flags, size_t *consumed)
{
    size_t at = ch->body_size;
    parse_result result = read_reply(port, ch, &at);
    if (result == PARSE_TOO_LARGE) { /* the connection closes after it anyway */
        *consumed = ch->rx_used;
        ch->step = STATUS_LINE;
        ch->body_size = ch->body_left = 0;
        ubii__embedded_error(port, "a reply over UBII_EMBEDDED_MAX_MESSAGE was dropped");
        return PARSE_TOO_LARGE;
    }
    if (result == PARSE_ERROR) {
        return PARSE_ERROR;
    }
    /* What was read after the body (head lines, chunk framing) is spent. */
    memmove(ch->rx + ch->body_size, ch->rx + at, ch->rx_used - at);
    ch->rx_used -= at - ch->body_size;
    if (result == PARSE_NEED_MORE) {
        return PARSE_NEED_MORE;
    }
    *data = ch->rx;
    *size = ch->body_size;
    *flags = 0;
    *consumed = ch->body_size;
    ch->step = STATUS_LINE;
    ch->body_size = 0;
    return PARSE_MESSAGE;
}

const protocol_driver ubii__http_driver = {on_connected, parse, header_size, frame};

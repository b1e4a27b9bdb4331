/* HTTP/1.1 client for binary services: POST path with Content-Type application/octet-stream, one
 * request per connection ("Connection: close"). The reply must be 200 with a Content-Length
 * (what the master sends for a binary reply); anything else ends the channel with a reason. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "embedded_internal.h"

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
    char text[UBII_EMBEDDED_HEADROOM];
    request_head(ch, size, text, sizeof text);
    memcpy(ch->tx + at - head, text, head); /* without snprintf's NUL, which the body follows */
}

static parse_result parse(ubii_embedded_port *port, ubii__embedded_channel *ch,
                          const uint8_t **data, size_t *size, unsigned *flags, size_t *consumed)
{
    size_t end = 0;
    for (size_t i = 3; i < ch->rx_used && end == 0; ++i) {
        if (memcmp(ch->rx + i - 3, "\r\n\r\n", 4) == 0) {
            end = i + 1;
        }
    }
    if (end == 0) {
        if (ch->rx_used == UBII_EMBEDDED_BUFFER) {
            ubii__embedded_error(port, "HTTP reply head too long");
            return PARSE_ERROR;
        }
        return PARSE_NEED_MORE;
    }
    if (end < 12 || memcmp(ch->rx, "HTTP/1.", 7) != 0) {
        ubii__embedded_error(port, "not an HTTP reply");
        return PARSE_ERROR;
    }
    ch->http_status = atoi((const char *)ch->rx + 9);
    if (ch->http_status != 200) {
        char text[48];
        snprintf(text, sizeof text, "HTTP service answered with status %d", ch->http_status);
        ubii__embedded_error(port, text);
        return PARSE_ERROR;
    }
    long length = -1;
    for (size_t i = 2; i < end; ++i) {
        if (ch->rx[i - 1] == '\n' &&
            strncasecmp((const char *)ch->rx + i, "Content-Length:", 15) == 0) {
            length = strtol((const char *)ch->rx + i + 15, NULL, 10);
        }
    }
    if (length < 0) {
        ubii__embedded_error(port, "HTTP reply without Content-Length");
        return PARSE_ERROR;
    }
    if ((size_t)length > UBII_EMBEDDED_MAX_MESSAGE) { /* the connection closes after it anyway */
        *consumed = ch->rx_used;
        ubii__embedded_error(port, "a reply over UBII_EMBEDDED_MAX_MESSAGE was dropped");
        return PARSE_TOO_LARGE;
    }
    if (ch->rx_used < end + (size_t)length) {
        return PARSE_NEED_MORE;
    }
    *data = ch->rx + end;
    *size = (size_t)length;
    *flags = 0;
    *consumed = end + (size_t)length;
    return PARSE_MESSAGE;
}

const protocol_driver ubii__http_driver = {on_connected, parse, header_size, frame};

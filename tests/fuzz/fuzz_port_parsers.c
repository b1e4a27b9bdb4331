/* libFuzzer target: the embedded port's ZMTP, WebSocket and HTTP parsers on arbitrary bytes from
 * the network, in every phase. The first byte picks protocol and phase, the second how many bytes
 * arrive at a time (0: all at once); the rest is what arrives. Every message parsed must lie inside
 * the receive buffer and within the size limit. */
#include <stdlib.h>
#include <string.h>

#include "embedded_internal.h"

static uint64_t fixed_ms(void *user)
{
    (void)user;
    return 0;
}

static int64_t fixed_epoch(void *user)
{
    (void)user;
    return 0;
}

static void zero_bytes(void *user, uint8_t *bytes, size_t count)
{
    (void)user;
    memset(bytes, 0, count);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static ubii_embedded_port port;
    if (size < 2) {
        return 0;
    }
    ubii_embedded_platform platform = {fixed_ms, fixed_epoch, zero_bytes, NULL};
    ubii_embedded_port_init(&port, platform);
    ubii__embedded_channel *ch = &port.channels[UBII_CHANNEL_TOPIC];
    const protocol_driver *drivers[3] = {&ubii__zmtp_driver, &ubii__websocket_driver,
                                         &ubii__http_driver};
    uint8_t selector = data[0];
    ch->protocol = (uint8_t)(PROTOCOL_ZMTP + selector % 3);
    ch->phase = selector & 0x10 ? PHASE_HANDSHAKE : PHASE_OPEN;
    ch->zmq_type = selector & 0x20 ? ZMQ_TYPE_DEALER : ZMQ_TYPE_REQ;
    strcpy(ch->path, "/");
    strcpy(ch->websocket_key, "dGhlIHNhbXBsZSBub25jZQ==");
    const protocol_driver *driver = drivers[selector % 3];
    size_t slice = data[1] != 0 ? data[1] : UBII_EMBEDDED_BUFFER;
    const uint8_t *input = data + 2, *input_end = data + size;
    for (int rounds = 0; rounds < 4096; ++rounds) {
        /* As read_input() does: the rest of a dropped message is skipped, what follows is
         * appended as far as there is room. */
        size_t room = UBII_EMBEDDED_BUFFER - ch->rx_used;
        size_t arriving = (size_t)(input_end - input);
        arriving = arriving < slice ? arriving : slice;
        arriving = arriving < room ? arriving : room;
        bool input_left = arriving > 0;
        size_t skipped = ch->discard < arriving ? (size_t)ch->discard : arriving;
        ch->discard -= skipped;
        input += skipped;
        arriving -= skipped;
        memcpy(ch->rx + ch->rx_used, input, arriving);
        ch->rx_used += arriving;
        input += arriving;
        const uint8_t *message = NULL;
        size_t message_size = 0, consumed = 0;
        unsigned flags = 0;
        size_t before = ch->rx_used;
        parse_result result = driver->parse(&port, ch, &message, &message_size, &flags, &consumed);
        if (result == PARSE_MESSAGE &&
            (message < ch->rx || message + message_size > ch->rx + ch->rx_used ||
             message_size > UBII_EMBEDDED_MAX_MESSAGE)) {
            abort(); /* a message outside the buffer or over the limit */
        }
        if (result == PARSE_ERROR) {
            break;
        }
        if (result == PARSE_NEED_MORE) {
            if (!input_left && ch->rx_used >= before) {
                break; /* no more input, and nothing left to parse */
            }
            continue;
        }
        /* Progress: bytes consumed, or framing removed in place (WebSocket joins fragments). */
        if ((consumed == 0 && ch->rx_used >= before) || consumed > ch->rx_used) {
            abort();
        }
        memmove(ch->rx, ch->rx + consumed, ch->rx_used - consumed);
        ch->rx_used -= consumed;
    }
    return 0;
}

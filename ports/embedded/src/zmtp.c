/* ZMTP for the embedded port: the wire format (ports/common/zmtp_wire.c) on a channel's buffers. */
#include <string.h>

#include "embedded_internal.h"
#include "zmtp_wire.h"

static ubii_status on_connected(ubii_embedded_port *port, ubii__embedded_channel *ch)
{
    uint8_t handshake[UBII_ZMTP_HANDSHAKE_MAX];
    size_t size = ubii__zmtp_handshake(handshake, sizeof handshake, ch->zmq_type == ZMQ_TYPE_DEALER,
                                       ch->identity);
    ch->step = UBII_ZMTP_STEP_GREETING;
    if (size == 0 || !ubii__embedded_queue(ch, handshake, size)) {
        ubii__embedded_error(port, "ZMTP handshake does not fit the buffer");
        return UBII_ERR_TOO_LARGE;
    }
    return UBII_OK;
}

static parse_result parse(ubii_embedded_port *port, ubii__embedded_channel *ch,
                          const uint8_t **data, size_t *size, unsigned *message_flags,
                          size_t *consumed)
{
    ubii_zmtp_step step = (ubii_zmtp_step)ch->step;
    ubii_zmtp_found found;
    ubii_zmtp_unit unit =
        ubii__zmtp_next(&step, ch->rx, ch->rx_used, UBII_EMBEDDED_MAX_MESSAGE, &found);
    ch->step = (uint8_t)step;
    *consumed = found.consumed;
    switch (unit) {
    case UBII_ZMTP_SKIP:
        if (step == UBII_ZMTP_STEP_OPEN && ch->phase != PHASE_OPEN) {
            ch->phase = PHASE_OPEN;
            ch->state = UBII_CHANNEL_OPEN;
        }
        return PARSE_SKIP;
    case UBII_ZMTP_MESSAGE:
        *data = ch->rx + found.payload;
        *size = (size_t)found.size;
        *message_flags = 0;
        return PARSE_MESSAGE;
    case UBII_ZMTP_MISSHAPEN:
        port->decode_errors++;
        return PARSE_SKIP;
    case UBII_ZMTP_TOO_LARGE:
        return ubii__embedded_drop(port, ch, found.payload, found.size, consumed);
    case UBII_ZMTP_ERROR:
        ubii__embedded_error(port, found.error);
        return PARSE_ERROR;
    case UBII_ZMTP_NEED_MORE:
        break;
    }
    if (ch->rx_used == UBII_EMBEDDED_BUFFER) {
        ubii__embedded_error(port, "ZMTP message larger than the receive buffer");
        return PARSE_ERROR;
    }
    return PARSE_NEED_MORE;
}

static size_t header_size(const ubii__embedded_channel *ch, size_t size)
{
    return ubii__zmtp_header_size(ch->zmq_type == ZMQ_TYPE_REQ, size);
}

static void frame(ubii_embedded_port *port, ubii__embedded_channel *ch, size_t at, size_t size,
                  unsigned flags)
{
    (void)port;
    (void)flags;
    ubii__zmtp_write_header(ch->tx + at - header_size(ch, size), ch->zmq_type == ZMQ_TYPE_REQ,
                            size);
}

const protocol_driver ubii__zmtp_driver = {on_connected, parse, header_size, frame};

/* Outgoing WebSocket frames: the outbox of an open channel written in batches, framed in
 * the messages' own headroom. */
#include <stdlib.h>
#include <string.h>

#include "lws_internal.h"

static const uint8_t *next_mask(lws_connection *connection, struct lws *wsi)
{
    const ubii__lws_library *lws = LWS(connection->owner);
    if (connection->masks_left < 4) {
        if (lws->get_random(lws->get_context(wsi), connection->masks, MASK_POOL) != MASK_POOL) {
            return NULL;
        }
        connection->masks_left = MASK_POOL;
    }
    connection->masks_left -= 4;
    return connection->masks + connection->masks_left;
}

/* Frames the message at `payload` in place: header written just before it, and for WebSocket
 * the payload masked. Returns where the frame starts, or NULL without a masking key. */
static uint8_t *frame_in_place(lws_connection *connection, struct lws *wsi, uint8_t *payload,
                               size_t size, unsigned flags)
{
    uint8_t *header = payload - ubii__ws_client_header_size(size);
    const uint8_t *mask = next_mask(connection, wsi);
    if (mask == NULL) {
        return NULL;
    }
    int opcode = flags & UBII_MESSAGE_TEXT ? UBII_WS_OPCODE_TEXT : UBII_WS_OPCODE_BINARY;
    ubii__ws_write_client_header(header, opcode, size, mask);
    ubii__ws_mask(payload, size, mask);
    return header;
}

/* Writes the next piece of the frame in `sending`, at most RX_CHUNK bytes: lws sends a larger write
 * only in part and keeps the rest, to send one piece per service pass. */
static const char *write_piece(lws_connection *connection, struct lws *wsi)
{
    const ubii__lws_library *lws = LWS(connection->owner);
    size_t piece = connection->sending_left < RX_CHUNK ? connection->sending_left : RX_CHUNK;
    if (lws->write(wsi, connection->sending_next, piece, LWS_WRITE_RAW) < 0) {
        return "write to the master failed";
    }
    connection->sending_next += piece;
    connection->sending_left -= piece;
    if (connection->sending_left == 0) {
        free(connection->sending);
        connection->sending = NULL;
    }
    return NULL;
}

/* Writes the outbox's first messages as whole frames in one lws_write: as many as fit
 * BATCH_BYTES; or starts one larger message, framed in its own headroom, that goes in pieces.
 * (libwebsockets would frame each WebSocket message with a write, and a read of its random
 * source, of its own.) The frames go as raw bytes; lws keeps whatever the socket does not take
 * and sends it before anything else. */
static const char *write_frames(lws_connection *connection, lws_channel *ch, struct lws *wsi)
{
    const ubii__lws_library *lws = LWS(connection->owner);
    static const char no_mask[] = "no random bytes for WebSocket masking keys";
    queued_message *message = ch->outbox.head;
    size_t framed = ubii__ws_client_header_size(message->size) + message->size;
    uint8_t *start;
    size_t length;
    if (framed > BATCH_BYTES) {
        ubii__lws_pop(&ch->outbox);
        start = frame_in_place(connection, wsi, message->data, message->size, message->flags);
        if (start == NULL) {
            free(message);
            return no_mask;
        }
        connection->sending = message;
        connection->sending_next = start;
        connection->sending_left = framed;
        return write_piece(connection, wsi);
    }
    if (connection->batch == NULL && (connection->batch = malloc(LWS_PRE + BATCH_BYTES)) == NULL) {
        return "out of memory for outgoing frames";
    }
    start = connection->batch + LWS_PRE;
    length = 0;
    while ((message = ch->outbox.head) != NULL &&
           length + (framed = ubii__ws_client_header_size(message->size) + message->size) <=
               BATCH_BYTES) {
        ubii__lws_pop(&ch->outbox);
        uint8_t *payload = start + length + (framed - message->size);
        memcpy(payload, message->data, message->size);
        bool framed_ok =
            frame_in_place(connection, wsi, payload, message->size, message->flags) != NULL;
        free(message);
        if (!framed_ok) {
            return no_mask;
        }
        length += framed;
    }
    return lws->write(wsi, start, length, LWS_WRITE_RAW) < 0 ? "write to the master failed" : NULL;
}

bool ubii__lws_output_waits(const lws_connection *connection, const lws_channel *ch)
{
    return connection->sending != NULL || ch->outbox.count > 0;
}

int ubii__lws_write_outbox(lws_connection *connection, lws_channel *ch, struct lws *wsi)
{
    const ubii__lws_library *lws = LWS(connection->owner);
    /* As much as the socket takes now: one message per callback would cap a node polled once per
     * frame at one message per frame. */
    while (ubii__lws_output_waits(connection, ch)) {
        const char *failure = connection->sending != NULL ? write_piece(connection, wsi)
                                                          : write_frames(connection, ch, wsi);
        if (failure != NULL) {
            ubii__lws_lose(connection, failure, NULL);
            return -1;
        }
        if (!ubii__lws_output_waits(connection, ch) || lws->send_pipe_choked(wsi)) {
            break;
        }
    }
    if (ubii__lws_output_waits(connection, ch)) {
        lws->callback_on_writable(wsi);
    }
    return 0;
}

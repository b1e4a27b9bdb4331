/* libFuzzer target: ZMTP as the Linux port's in-thread engine reads it (zmtp_channel.c): a byte
 * stream arriving in slices of any size, every whole unit taken off the front with the port's
 * limit of 16 MiB, the rest kept for the next slice. The first byte picks the slice size (0: all
 * at once); the rest is what the master sends. Every unit must lie inside the bytes at hand. */
#include <stdlib.h>
#include <string.h>

#include "ubii/config.h"
#include "zmtp_wire.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1) {
        return 0;
    }
    size_t slice = data[0] != 0 ? data[0] : size;
    const uint8_t *input = data + 1;
    size_t left = size - 1;
    uint8_t *stream = malloc(left + 1);
    if (stream == NULL) {
        return 0;
    }
    size_t used = 0;
    ubii_zmtp_step step = UBII_ZMTP_STEP_GREETING;
    while (left > 0) {
        size_t arriving = left < slice ? left : slice;
        memcpy(stream + used, input, arriving);
        used += arriving;
        input += arriving;
        left -= arriving;
        size_t at = 0;
        for (;;) {
            ubii_zmtp_found found;
            memset(&found, 0, sizeof found);
            ubii_zmtp_unit unit =
                ubii__zmtp_next(&step, stream + at, used - at, UBII_MAX_MESSAGE_SIZE, &found);
            if (unit == UBII_ZMTP_NEED_MORE) {
                break;
            }
            if (unit == UBII_ZMTP_ERROR || unit == UBII_ZMTP_TOO_LARGE) {
                if (unit == UBII_ZMTP_ERROR && found.error == NULL) {
                    abort(); /* every protocol error says what it was */
                }
                free(stream);
                return 0; /* the engine ends the connection */
            }
            if (found.consumed == 0 || found.consumed > used - at) {
                abort(); /* no progress, or a unit longer than the bytes at hand */
            }
            if (unit == UBII_ZMTP_MESSAGE &&
                (found.payload > found.consumed || found.size > found.consumed - found.payload)) {
                abort(); /* a payload outside its unit */
            }
            at += found.consumed;
        }
        memmove(stream, stream + at, used - at);
        used -= at;
    }
    free(stream);
    return 0;
}

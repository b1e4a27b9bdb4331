#ifndef UBII_WIRE_H
#define UBII_WIRE_H

/* Reading protobuf bytes in place, without decoding into a struct: the occurrences of one field
 * of a message, e.g. the strings of a StringList or the Clients of a ClientList (decode each with
 * pb_decode). No allocation; the bytes must stay valid while iterating. */

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "ubii/export.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct ubii_field_iter {
    const uint8_t *bytes;
    size_t size;
    size_t offset;
    uint32_t number;
    bool malformed; /* set when the bytes turned out not to be valid protobuf */
} ubii_field_iter;

/* Iterates the length-delimited occurrences of field `number` in message bytes[0..size). */
UBII_API void ubii_field_iter_init(ubii_field_iter *iter, const uint8_t *bytes, size_t size,
                                   uint32_t number);
/* The next occurrence's payload; false at the end (check iter->malformed). */
UBII_API bool ubii_field_iter_next(ubii_field_iter *iter, const uint8_t **payload, size_t *size);

#ifdef __cplusplus
}
#endif

#endif

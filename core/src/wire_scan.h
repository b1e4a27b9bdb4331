#ifndef UBII_WIRE_SCAN_H
#define UBII_WIRE_SCAN_H

/* Walks the top-level fields of a protobuf message in place, without decoding it into a struct:
 * envelopes (ServiceReply, TopicData) are read this way so that a member's bytes can be handed on
 * as a view of the receive buffer. Internal to libubii. */

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

typedef struct ubii_wire_field {
    uint32_t number;
    int wire_type;        /* pb_wire_type_t */
    const uint8_t *bytes; /* length-delimited fields: the payload; other wire types: NULL */
    size_t size;          /* payload size for length-delimited fields */
    uint64_t scalar;      /* varint fields: the value; fixed32/fixed64 fields: the raw bits */
} ubii_wire_field;

typedef struct ubii_wire_scan {
    const uint8_t *bytes;
    size_t size;
    size_t offset;
} ubii_wire_scan;

void ubii_wire_scan_init(ubii_wire_scan *scan, const uint8_t *bytes, size_t size);

/* Reads the next field into *field. Returns false at the end; sets *malformed when the bytes are
 * not valid protobuf (truncated field, bad wire type, bad varint). */
bool ubii_wire_scan_next(ubii_wire_scan *scan, ubii_wire_field *field, bool *malformed);

#endif

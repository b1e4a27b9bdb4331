#include "wire_scan.h"

#include <pb_decode.h>

void ubii_wire_scan_init(ubii_wire_scan *scan, const uint8_t *bytes, size_t size)
{
    scan->bytes = bytes;
    scan->size = size;
    scan->offset = 0;
}

bool ubii_wire_scan_next(ubii_wire_scan *scan, ubii_wire_field *field, bool *malformed)
{
    *malformed = false;
    if (scan->offset >= scan->size) {
        return false;
    }
    size_t remaining = scan->size - scan->offset;
    pb_istream_t stream = pb_istream_from_buffer(scan->bytes + scan->offset, remaining);
    pb_wire_type_t wire_type;
    uint32_t number;
    bool eof = false;
    if (!pb_decode_tag(&stream, &wire_type, &number, &eof) || eof) {
        *malformed = true;
        return false;
    }
    field->number = number;
    field->wire_type = (int)wire_type;
    field->bytes = NULL;
    field->size = 0;
    field->scalar = 0;

    bool ok;
    switch (wire_type) {
    case PB_WT_VARINT:
        ok = pb_decode_varint(&stream, &field->scalar);
        break;
    case PB_WT_64BIT:
        ok = pb_decode_fixed64(&stream, &field->scalar);
        break;
    case PB_WT_32BIT: {
        uint32_t bits = 0;
        ok = pb_decode_fixed32(&stream, &bits);
        field->scalar = bits;
        break;
    }
    case PB_WT_STRING: {
        uint32_t length;
        ok = pb_decode_varint32(&stream, &length) && length <= stream.bytes_left;
        if (ok) {
            field->bytes = scan->bytes + scan->offset + (remaining - stream.bytes_left);
            field->size = length;
            ok = pb_read(&stream, NULL, length);
        }
        break;
    }
    default:
        ok = pb_skip_field(&stream, wire_type);
        break;
    }
    if (!ok) {
        *malformed = true;
        return false;
    }
    scan->offset += remaining - stream.bytes_left;
    return true;
}

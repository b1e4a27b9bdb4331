#include "ubii/wire.h"

#include <pb.h>

#include "wire_scan.h"

void ubii_field_iter_init(ubii_field_iter *iter, const uint8_t *bytes, size_t size, uint32_t number)
{
    iter->bytes = bytes;
    iter->size = bytes != NULL ? size : 0;
    iter->offset = 0;
    iter->number = number;
    iter->malformed = false;
}

bool ubii_field_iter_next(ubii_field_iter *iter, const uint8_t **payload, size_t *size)
{
    ubii_wire_scan scan = {iter->bytes, iter->size, iter->offset};
    ubii_wire_field field;
    while (ubii_wire_scan_next(&scan, &field, &iter->malformed)) {
        if (field.number == iter->number && field.wire_type == PB_WT_STRING) {
            iter->offset = scan.offset;
            *payload = field.bytes;
            *size = field.size;
            return true;
        }
    }
    iter->offset = scan.offset;
    return false;
}

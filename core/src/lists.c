/* Records holding lists (ubii/lists.h; full schema only): elements read in place, numeric lists
 * written packed. */
#include <string.h>

#include <pb_decode.h>
#include <pb_encode.h>

#include "publish.h"
#include "record.h"
#include "ubii/lists.h"
#include "ubii/wire.h"
#include "wire_scan.h"

enum { LIST_ELEMENTS = 1 };

/* ---- reading -----------------------------------------------------------------------------------
 */

ubii_status ubii_record_list(const ubii_record *record, ubii_record_type type, ubii_list_iter *iter)
{
    if (record == NULL || iter == NULL || !ubii__record_type_known((uint32_t)type) ||
        ubii__record_wire_type((uint32_t)type) != PB_WT_STRING) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    if (record->type != type) {
        return UBII_ERR_WRONG_TYPE;
    }
    memset(iter, 0, sizeof *iter);
    iter->bytes = record->value;
    iter->size = record->value_size;
    return UBII_OK;
}

/* The next element of field 1 whose wire type is `element_wire_type`, from a packed run or alone.
 */
static bool next_scalar(ubii_list_iter *iter, int element_wire_type, uint64_t *value)
{
    for (;;) {
        if (iter->packed_left > 0) {
            pb_istream_t stream = pb_istream_from_buffer(iter->packed, iter->packed_left);
            bool ok;
            if (element_wire_type == PB_WT_64BIT) {
                ok = pb_decode_fixed64(&stream, value);
            } else if (element_wire_type == PB_WT_32BIT) {
                uint32_t bits = 0;
                ok = pb_decode_fixed32(&stream, &bits);
                *value = bits;
            } else {
                ok = pb_decode_varint(&stream, value);
            }
            if (!ok) {
                iter->malformed = true;
                iter->packed_left = 0;
                return false;
            }
            iter->packed += iter->packed_left - stream.bytes_left;
            iter->packed_left = stream.bytes_left;
            return true;
        }
        ubii_wire_scan scan = {iter->bytes, iter->size, iter->offset};
        ubii_wire_field field;
        bool found = false;
        while (!found && ubii_wire_scan_next(&scan, &field, &iter->malformed)) {
            found = field.number == LIST_ELEMENTS;
        }
        iter->offset = scan.offset;
        if (!found) {
            return false;
        }
        if (field.wire_type == PB_WT_STRING) {
            iter->packed = field.bytes;
            iter->packed_left = field.size;
        } else if (field.wire_type == element_wire_type) {
            *value = field.scalar;
            return true;
        } else {
            iter->malformed = true;
            return false;
        }
    }
}

bool ubii_list_next_double(ubii_list_iter *iter, double *value)
{
    uint64_t bits;
    if (iter == NULL || value == NULL || !next_scalar(iter, PB_WT_64BIT, &bits)) {
        return false;
    }
    memcpy(value, &bits, sizeof *value);
    return true;
}

bool ubii_list_next_float(ubii_list_iter *iter, float *value)
{
    uint64_t bits;
    if (iter == NULL || value == NULL || !next_scalar(iter, PB_WT_32BIT, &bits)) {
        return false;
    }
    uint32_t narrow = (uint32_t)bits;
    memcpy(value, &narrow, sizeof *value);
    return true;
}

bool ubii_list_next_int32(ubii_list_iter *iter, int32_t *value)
{
    uint64_t raw;
    if (iter == NULL || value == NULL || !next_scalar(iter, PB_WT_VARINT, &raw)) {
        return false;
    }
    *value = (int32_t)(uint32_t)raw;
    return true;
}

bool ubii_list_next_bool(ubii_list_iter *iter, bool *value)
{
    uint64_t raw;
    if (iter == NULL || value == NULL || !next_scalar(iter, PB_WT_VARINT, &raw)) {
        return false;
    }
    *value = raw != 0;
    return true;
}

bool ubii_list_next_bytes(ubii_list_iter *iter, const uint8_t **bytes, size_t *size)
{
    if (iter == NULL || bytes == NULL || size == NULL) {
        return false;
    }
    ubii_field_iter fields = {iter->bytes, iter->size, iter->offset, LIST_ELEMENTS, false};
    bool found = ubii_field_iter_next(&fields, bytes, size);
    iter->offset = fields.offset;
    iter->malformed = iter->malformed || fields.malformed;
    return found;
}

/* ---- publishing --------------------------------------------------------------------------------
 */

typedef struct list_value {
    const void *items;
    size_t count;
} list_value;

/* Packed numeric elements: tag, byte length, values. */
static bool write_packed(pb_ostream_t *stream, const list_value *list, size_t width,
                         bool (*write_one)(pb_ostream_t *, const void *))
{
    if (list->count == 0) {
        return true;
    }
    const uint8_t *item = list->items;
    pb_ostream_t sizing = PB_OSTREAM_SIZING;
    for (size_t i = 0; i < list->count; ++i) {
        if (!write_one(&sizing, item + i * width)) {
            return false;
        }
    }
    if (!pb_encode_tag(stream, PB_WT_STRING, LIST_ELEMENTS) ||
        !pb_encode_varint(stream, sizing.bytes_written)) {
        return false;
    }
    for (size_t i = 0; i < list->count; ++i) {
        if (!write_one(stream, item + i * width)) {
            return false;
        }
    }
    return true;
}

static bool write_double_element(pb_ostream_t *stream, const void *item)
{
    return pb_encode_fixed64(stream, item);
}

static bool write_float_element(pb_ostream_t *stream, const void *item)
{
    return pb_encode_fixed32(stream, item);
}

static bool write_int32_element(pb_ostream_t *stream, const void *item)
{
    return pb_encode_varint(stream, (uint64_t)(int64_t) * (const int32_t *)item);
}

static bool write_bool_element(pb_ostream_t *stream, const void *item)
{
    return pb_encode_varint(stream, *(const bool *)item ? 1 : 0);
}

static bool write_doubles(pb_ostream_t *stream, const void *value)
{
    return write_packed(stream, value, sizeof(double), write_double_element);
}

static bool write_floats(pb_ostream_t *stream, const void *value)
{
    return write_packed(stream, value, sizeof(float), write_float_element);
}

static bool write_int32s(pb_ostream_t *stream, const void *value)
{
    return write_packed(stream, value, sizeof(int32_t), write_int32_element);
}

static bool write_bools(pb_ostream_t *stream, const void *value)
{
    return write_packed(stream, value, sizeof(bool), write_bool_element);
}

static bool write_strings(pb_ostream_t *stream, const void *value)
{
    const list_value *list = value;
    const char *const *texts = list->items;
    for (size_t i = 0; i < list->count; ++i) {
        if (texts[i] == NULL || !pb_encode_tag(stream, PB_WT_STRING, LIST_ELEMENTS) ||
            !pb_encode_string(stream, (const pb_byte_t *)texts[i], strlen(texts[i]))) {
            return false;
        }
    }
    return true;
}

static ubii_status publish_list(ubii_node *node, const char *topic, ubii_record_type type,
                                ubii__body_writer write_body, const void *items, size_t count)
{
    if (items == NULL && count > 0) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    list_value list = {items, count};
    return ubii__publish_body(node, topic, (uint32_t)type, write_body, &list);
}

ubii_status ubii_publish_doubles(ubii_node *node, const char *topic, const double *values,
                                 size_t count)
{
    return publish_list(node, topic, UBII_RECORD_DOUBLE_LIST, write_doubles, values, count);
}

ubii_status ubii_publish_floats(ubii_node *node, const char *topic, const float *values,
                                size_t count)
{
    return publish_list(node, topic, UBII_RECORD_FLOAT_LIST, write_floats, values, count);
}

ubii_status ubii_publish_int32s(ubii_node *node, const char *topic, const int32_t *values,
                                size_t count)
{
    return publish_list(node, topic, UBII_RECORD_INT32_LIST, write_int32s, values, count);
}

ubii_status ubii_publish_bools(ubii_node *node, const char *topic, const bool *values, size_t count)
{
    return publish_list(node, topic, UBII_RECORD_BOOL_LIST, write_bools, values, count);
}

ubii_status ubii_publish_strings(ubii_node *node, const char *topic, const char *const *texts,
                                 size_t count)
{
    return publish_list(node, topic, UBII_RECORD_STRING_LIST, write_strings, texts, count);
}

#ifndef UBII_LISTS_H
#define UBII_LISTS_H

/* Records holding lists (DoubleList, StringList, Object2DList, ...): reading their elements and
 * publishing numeric and string lists. Full schema only (UBII_SCHEMA=full, proto/schemas/): a
 * reduced schema has no list members, and including this header fails there, because the schema's
 * list messages (ubii/dataStructure/lists.pb.h, the element types of ubii_list_next_bytes) are not
 * generated. ubii/ubii.h includes it when the schema has it. */

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "ubii/export.h"
#include "ubii/topic.h"
#include "ubii/dataStructure/lists.pb.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The elements of a numeric list member (packed or not), one at a time:
 *     ubii_list_iter it; double d;
 *     if (ubii_record_list(record, UBII_RECORD_DOUBLE_LIST, &it) == UBII_OK)
 *         while (ubii_list_next_double(&it, &d)) ...
 * String lists and lists of messages: ubii_list_next_bytes gives each element's bytes. */
typedef struct ubii_list_iter {
    const uint8_t *bytes; /* the list message */
    size_t size;
    size_t offset;
    const uint8_t *packed; /* the packed run being read, if any */
    size_t packed_left;
    bool malformed;
} ubii_list_iter;
UBII_API ubii_status ubii_record_list(const ubii_record *record, ubii_record_type type,
                                      ubii_list_iter *iter);
UBII_API bool ubii_list_next_double(ubii_list_iter *iter, double *value);
UBII_API bool ubii_list_next_float(ubii_list_iter *iter, float *value);
UBII_API bool ubii_list_next_int32(ubii_list_iter *iter, int32_t *value);
UBII_API bool ubii_list_next_bool(ubii_list_iter *iter, bool *value);
UBII_API bool ubii_list_next_bytes(ubii_list_iter *iter, const uint8_t **bytes, size_t *size);

/* One record holding a list, sent as ubii_publish_double does (ubii/topic.h). */
UBII_API ubii_status ubii_publish_doubles(ubii_node *node, const char *topic, const double *values,
                                          size_t count);
UBII_API ubii_status ubii_publish_floats(ubii_node *node, const char *topic, const float *values,
                                         size_t count);
UBII_API ubii_status ubii_publish_int32s(ubii_node *node, const char *topic, const int32_t *values,
                                         size_t count);
UBII_API ubii_status ubii_publish_bools(ubii_node *node, const char *topic, const bool *values,
                                        size_t count);
UBII_API ubii_status ubii_publish_strings(ubii_node *node, const char *topic,
                                          const char *const *texts, size_t count);

#ifdef __cplusplus
}
#endif

#endif

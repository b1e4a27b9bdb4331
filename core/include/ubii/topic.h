#ifndef UBII_TOPIC_H
#define UBII_TOPIC_H

/* Topics: subscribe (exact topic or regex) with a callback, publish records of any type.
 *
 * Subscriptions are counted locally: the master is asked once per distinct topic or regex, and
 * told to forget it when the last local subscription to it goes. They survive reconnection (the
 * node subscribes everything again after registering anew). A subscription may be made in any
 * state; the master hears of it once the node is READY.
 *
 * Regexes follow JavaScript's RegExp as the master applies it: an unanchored search (use ^...$ to
 * match whole topics). Supported: literals and escapes, ., [...] with ranges and negation,
 * \d \w \s \D \W \S, groups (...) and (?:...), alternation |, quantifiers * + ? {n} {n,} {n,m}
 * (lazy forms match the same topics), anchors ^ $, \b \B. Not supported (subscribing fails with
 * UBII_ERR_UNSUPPORTED): back-references, lookaround, named groups, \p{...} classes, flags. */

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "ubii/export.h"
#include "ubii/node.h"
#include "ubii/status.h"
#include "ubii/dataStructure/color.pb.h"
#include "ubii/dataStructure/image.pb.h"
#include "ubii/dataStructure/pose2d.pb.h"
#include "ubii/dataStructure/pose3d.pb.h"
#include "ubii/dataStructure/quaternion.pb.h"
#include "ubii/dataStructure/vector2.pb.h"
#include "ubii/dataStructure/vector3.pb.h"
#include "ubii/dataStructure/vector4.pb.h"
#include "ubii/topicData/topicDataRecord.pb.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The TopicDataRecord value members, by field number (PROTOCOL.md 3.3). */
typedef enum ubii_record_type {
    UBII_RECORD_NONE = 0,
    UBII_RECORD_DOUBLE = 3,
    UBII_RECORD_BOOL = 4,
    UBII_RECORD_STRING = 5,
    UBII_RECORD_VECTOR2 = 6,
    UBII_RECORD_VECTOR3 = 7,
    UBII_RECORD_VECTOR4 = 8,
    UBII_RECORD_QUATERNION = 9,
    UBII_RECORD_MATRIX3X2 = 10,
    UBII_RECORD_MATRIX4X4 = 11,
    UBII_RECORD_COLOR = 12,
    UBII_RECORD_TOUCH_EVENT = 13,
    UBII_RECORD_KEY_EVENT = 14,
    UBII_RECORD_MOUSE_EVENT = 15,
    UBII_RECORD_MYO_EVENT = 16,
    UBII_RECORD_POSE2D = 17,
    UBII_RECORD_POSE3D = 18,
    UBII_RECORD_OBJECT2D = 19,
    UBII_RECORD_OBJECT3D = 20,
    UBII_RECORD_OBJECT2D_LIST = 21,
    UBII_RECORD_OBJECT3D_LIST = 22,
    UBII_RECORD_INT32 = 23,
    UBII_RECORD_FLOAT = 24,
    UBII_RECORD_INT32_LIST = 25,
    UBII_RECORD_FLOAT_LIST = 26,
    UBII_RECORD_DOUBLE_LIST = 27,
    UBII_RECORD_STRING_LIST = 28,
    UBII_RECORD_BOOL_LIST = 29,
    UBII_RECORD_IMAGE2D = 30,
    UBII_RECORD_IMAGE2D_LIST = 31,
    UBII_RECORD_SESSION = 32,
    UBII_RECORD_TOUCH_EVENT_LIST = 34,
    UBII_RECORD_VECTOR2_LIST = 35,
    UBII_RECORD_VECTOR3_LIST = 36,
    UBII_RECORD_VECTOR4_LIST = 37,
    UBII_RECORD_QUATERNION_LIST = 38, /* holds a single Quaternion (schema quirk) */
    UBII_RECORD_ERROR = 39,
    UBII_RECORD_DEVICE = 40,
    UBII_RECORD_DEVICE_LIST = 41,
    UBII_RECORD_COMPONENT = 42,
    UBII_RECORD_COMPONENT_LIST = 43,
    UBII_RECORD_SESSION_LIST = 44
} ubii_record_type;

/* A received record, lent to the subscription callback: every pointer is valid only during the
 * callback. The value is not decoded until an accessor below asks for it. */
typedef struct ubii_record {
    const char *topic;     /* NUL-terminated */
    const char *client_id; /* "" unless the publisher set it */
    bool has_timestamp;
    int64_t timestamp_millis;
    int64_t timestamp_seconds;
    int32_t timestamp_nanos;
    ubii_record_type type;
    const uint8_t *value; /* length-delimited members: their encoded bytes (a string's text) */
    size_t value_size;
    uint64_t scalar; /* double/float bits, int32 and bool values */
} ubii_record;

typedef uint32_t ubii_subscription;

typedef void (*ubii_record_fn)(ubii_node *node, const ubii_record *record, void *user);

/* Subscribes `fn` to an exact topic / to topics matching a regex. *handle (may be NULL) receives
 * the handle for ubii_unsubscribe. UBII_ERR_FULL when UBII_MAX_SUBSCRIPTIONS are in use;
 * UBII_ERR_INVALID_ARGUMENT for an empty or too long topic; UBII_ERR_UNSUPPORTED for a regex
 * using a feature listed above as unsupported. */
UBII_API ubii_status ubii_subscribe(ubii_node *node, const char *topic, ubii_record_fn fn,
                                    void *user, ubii_subscription *handle);
UBII_API ubii_status ubii_subscribe_regex(ubii_node *node, const char *regex, ubii_record_fn fn,
                                          void *user, ubii_subscription *handle);
UBII_API ubii_status ubii_unsubscribe(ubii_node *node, ubii_subscription handle);

/* Whether `topic` matches `regex` the way the master decides it (unanchored search). Returns
 * UBII_OK (match), UBII_ERR_NOT_FOUND (no match), UBII_ERR_UNSUPPORTED / UBII_ERR_INVALID_ARGUMENT
 * for patterns this dialect cannot run, UBII_ERR_TIMEOUT past UBII_REGEX_STEP_LIMIT. */
UBII_API ubii_status ubii_regex_search(const char *regex, const char *topic);

/* ---- reading a record ------------------------------------------------------------------------ */

UBII_API ubii_status ubii_record_double(const ubii_record *record, double *value);
UBII_API ubii_status ubii_record_float(const ubii_record *record, float *value);
UBII_API ubii_status ubii_record_int32(const ubii_record *record, int32_t *value);
UBII_API ubii_status ubii_record_bool(const ubii_record *record, bool *value);
/* The text is not NUL-terminated. */
UBII_API ubii_status ubii_record_string(const ubii_record *record, const char **text,
                                        size_t *length);

/* Decodes a message-typed member (vector3, pose3D, object2D, ...) into `message`, which must be
 * the nanopb struct `fields` describes. UBII_ERR_WRONG_TYPE if the record holds another member. */
UBII_API ubii_status ubii_record_decode(const ubii_record *record, ubii_record_type type,
                                        const pb_msgdesc_t *fields, void *message);

/* An Image2D without copying its pixels: `data` points into the received message. */
typedef struct ubii_image_view {
    int32_t width;
    int32_t height;
    ubii_dataStructure_Image2D_DataFormat format;
    const uint8_t *data;
    size_t size;
} ubii_image_view;
UBII_API ubii_status ubii_record_image(const ubii_record *record, ubii_image_view *image);

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

/* ---- publishing ----------------------------------------------------------------------------- */
/* Each call sends one record on `topic` at once (UBII_ERR_NOT_CONNECTED unless READY;
 * UBII_ERR_WOULD_BLOCK if the transport's queue is full). With stamp_records the record carries
 * Timestamp.millis = now (epoch ms). */

UBII_API ubii_status ubii_publish_double(ubii_node *node, const char *topic, double value);
UBII_API ubii_status ubii_publish_float(ubii_node *node, const char *topic, float value);
UBII_API ubii_status ubii_publish_int32(ubii_node *node, const char *topic, int32_t value);
UBII_API ubii_status ubii_publish_bool(ubii_node *node, const char *topic, bool value);
UBII_API ubii_status ubii_publish_string(ubii_node *node, const char *topic, const char *text,
                                         size_t length);
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
UBII_API ubii_status ubii_publish_image(ubii_node *node, const char *topic, int32_t width,
                                        int32_t height,
                                        ubii_dataStructure_Image2D_DataFormat format,
                                        const uint8_t *data, size_t size);
/* The common geometric types; the values are copied at once. */
UBII_API ubii_status ubii_publish_vector2(ubii_node *node, const char *topic,
                                          const ubii_dataStructure_Vector2 *value);
UBII_API ubii_status ubii_publish_vector3(ubii_node *node, const char *topic,
                                          const ubii_dataStructure_Vector3 *value);
UBII_API ubii_status ubii_publish_vector4(ubii_node *node, const char *topic,
                                          const ubii_dataStructure_Vector4 *value);
UBII_API ubii_status ubii_publish_quaternion(ubii_node *node, const char *topic,
                                             const ubii_dataStructure_Quaternion *value);
UBII_API ubii_status ubii_publish_color(ubii_node *node, const char *topic,
                                        const ubii_dataStructure_Color *value);
UBII_API ubii_status ubii_publish_pose2d(ubii_node *node, const char *topic,
                                         const ubii_dataStructure_Pose2D *value);
UBII_API ubii_status ubii_publish_pose3d(ubii_node *node, const char *topic,
                                         const ubii_dataStructure_Pose3D *value);
/* Any message-typed member: `message` is the nanopb struct `fields` describes, e.g.
 * ubii_publish_message(node, "/pose", UBII_RECORD_POSE3D, ubii_dataStructure_Pose3D_fields, &pose).
 */
UBII_API ubii_status ubii_publish_message(ubii_node *node, const char *topic, ubii_record_type type,
                                          const pb_msgdesc_t *fields, const void *message);

#ifdef __cplusplus
}
#endif

#endif

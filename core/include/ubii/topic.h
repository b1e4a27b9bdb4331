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
#include "ubii/dataStructure/pose2d.pb.h"
#include "ubii/dataStructure/pose3d.pb.h"
#include "ubii/dataStructure/quaternion.pb.h"
#include "ubii/dataStructure/vector2.pb.h"
#include "ubii/dataStructure/vector3.pb.h"
#include "ubii/dataStructure/vector4.pb.h"
#include "ubii/record_types.h"
#include "ubii/topicData/topicDataRecord.pb.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The TopicDataRecord value members of this build's schema, by field number
 * (docs/PROTOCOL.md §3.3): UBII_RECORD_<MEMBER> for each member, its .proto name in capitals
 * (UBII_RECORD_DOUBLE = 3, UBII_RECORD_POSE3D = 18, UBII_RECORD_OBJECT2D_LIST = 21, ...). The list
 * is generated from the schema (ubii/record_types.h, see proto/README.md), so a type the schema
 * leaves out has no name here and using it does not compile; neither do the functions and headers
 * of left-out types (ubii/lists.h, image.h, devices.h). (Calling an undeclared function is an error
 * in C++ and in C with -pedantic-errors or -Werror; GCC's default C mode only warns.)
 *   full schema (UBII_SCHEMA=full): all 41 members; UBII_RECORD_QUATERNION_LIST holds a single
 *     Quaternion (a quirk of the upstream schema).
 *   topics schema (UBII_SCHEMA=topics): DOUBLE, FLOAT, INT32, BOOL, STRING, VECTOR2, VECTOR3,
 *     VECTOR4, QUATERNION, COLOR, POSE2D, POSE3D, ERROR. A received record of any other member is
 *     not passed on: it is counted (ubii_stats.records_skipped) and reported to on_error with
 *     UBII_ERR_UNSUPPORTED; the other records of the same message are delivered. */
typedef enum ubii_record_type {
    UBII_RECORD_NONE = 0,
#define UBII_RECORD_ENUMERATOR(name, number) UBII_RECORD_##name = number,
    UBII_RECORD_TYPE_LIST(UBII_RECORD_ENUMERATOR)
#undef UBII_RECORD_ENUMERATOR
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

/* The schema's facts about a member, from the generated table (NULL / UBII_RECORD_NONE for a type
 * this build's schema lacks): its .proto name ("vector3", "pose3D", "object2D_list"), and its
 * message format as ProcessingModule inputs and outputs name it ("double", "string",
 * "ubii.dataStructure.Vector3"). For a format two members share (Quaternion: quaternion and the
 * upstream quirk quaternion_list), ubii_record_type_for_format gives the lower field number. */
UBII_API const char *ubii_record_type_name(ubii_record_type type);
UBII_API const char *ubii_record_type_format(ubii_record_type type);
UBII_API ubii_record_type ubii_record_type_for_format(const char *format);

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
/* Whether subscription changes made so far are still on their way to the master: sent with the
 * next poll, or sent and not answered yet. Once it is false, every subscription receives what is
 * published after that (a service call made right after subscribing does not tell: the
 * subscription request goes out with the next poll, possibly after that call). */
UBII_API bool ubii_subscriptions_pending(const ubii_node *node);

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
 * the nanopb struct `fields` describes. UBII_ERR_WRONG_TYPE if the record holds another member;
 * UBII_ERR_INVALID_ARGUMENT for a type that is not a message member of this build's schema. */
UBII_API ubii_status ubii_record_decode(const ubii_record *record, ubii_record_type type,
                                        const pb_msgdesc_t *fields, void *message);

/* Lists (ubii/lists.h) and images (ubii/image.h) have accessors of their own, in the full schema
 * only. */

/* ---- publishing ----------------------------------------------------------------------------- */
/* Each call sends one record on `topic` at once (UBII_ERR_NOT_CONNECTED unless READY;
 * UBII_ERR_WOULD_BLOCK if the transport's queue is full). With stamp_records the record carries
 * Timestamp.millis = now (epoch ms). Lists: ubii/lists.h, images: ubii/image.h (full schema). */

UBII_API ubii_status ubii_publish_double(ubii_node *node, const char *topic, double value);
UBII_API ubii_status ubii_publish_float(ubii_node *node, const char *topic, float value);
UBII_API ubii_status ubii_publish_int32(ubii_node *node, const char *topic, int32_t value);
UBII_API ubii_status ubii_publish_bool(ubii_node *node, const char *topic, bool value);
UBII_API ubii_status ubii_publish_string(ubii_node *node, const char *topic, const char *text,
                                         size_t length);
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
/* Any message-typed member of the schema (else UBII_ERR_INVALID_ARGUMENT): `message` is the nanopb
 * struct `fields` describes, e.g.
 * ubii_publish_message(node, "/pose", UBII_RECORD_POSE3D, ubii_dataStructure_Pose3D_fields, &pose).
 */
UBII_API ubii_status ubii_publish_message(ubii_node *node, const char *topic, ubii_record_type type,
                                          const pb_msgdesc_t *fields, const void *message);

/* A length-delimited member (a message-typed one, or UBII_RECORD_STRING) whose encoded bytes the
 * caller has already, e.g. from another protobuf runtime: `bytes` are the member's payload (a
 * message's fields, without tag and length), copied at once. UBII_ERR_INVALID_ARGUMENT for a
 * scalar or unknown member; the bytes themselves are not checked. */
UBII_API ubii_status ubii_publish_encoded(ubii_node *node, const char *topic, ubii_record_type type,
                                          const uint8_t *bytes, size_t size);

#ifdef __cplusplus
}
#endif

#endif

#ifndef UBII_PUBLISH_H
#define UBII_PUBLISH_H

/* publish.c: one record out, for the typed publish functions of every API part. Internal to the
 * core; not installed. */

#include <pb_encode.h>

#include "ubii/topic.h"

/* Writes a record's value member, tag included. */
typedef bool (*ubii__value_writer)(pb_ostream_t *stream, uint32_t member, const void *value);
/* Writes the body of a message-typed member (without tag and length). */
typedef bool (*ubii__body_writer)(pb_ostream_t *stream, const void *body);
/* Sends one TopicData{record{topic, [timestamp], value}}. */
ubii_status ubii__publish(ubii_node *node, const char *topic, uint32_t member,
                          ubii__value_writer write, const void *value);
/* The same with a message-typed member whose body `write_body` writes (called twice: sizing, then
 * writing). */
ubii_status ubii__publish_body(ubii_node *node, const char *topic, uint32_t member,
                               ubii__body_writer write_body, const void *body);

#endif

#ifndef UBII_RECORD_H
#define UBII_RECORD_H

/* record.c: received TopicData, and what the schema says of record members. Internal to the core;
 * not installed. */

#include "ubii/topic.h"

/* Parses TopicData bytes; hands each record it holds to ubii__dispatch_record. */
void ubii__handle_topic_data(ubii_node *node, const uint8_t *bytes, size_t size);

/* Whether `number` is a TopicDataRecord value member of this build's schema (the generated
 * UBII_RECORD_TYPE_LIST), and the wire type every value member arrives with. */
bool ubii__record_type_known(uint32_t number);
int ubii__record_wire_type(uint32_t number);

#endif

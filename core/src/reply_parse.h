#ifndef UBII_REPLY_PARSE_H
#define UBII_REPLY_PARSE_H

/* service_codec.c: ServiceReply bytes as the ubii_reply callbacks see. Internal to the core; not
 * installed. */

#include "ubii/general/error.pb.h"
#include "ubii/service.h"

/* Splits a ServiceReply into its member; an error member is decoded into *error_storage, which
 * the reply's error texts point into. */
void ubii__parse_reply(const uint8_t *bytes, size_t size, ubii_reply *reply,
                       ubii_general_Error *error_storage);
/* A reply that no master sent: a timeout, a cancellation, a reply the port dropped. */
void ubii__reply_with_status(ubii_reply *reply, ubii_status status);

#endif

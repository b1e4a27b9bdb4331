#ifndef UBII_SERVICE_CODEC_H
#define UBII_SERVICE_CODEC_H

/* Encoding of service requests and decoding of service replies, independent of any transport.
 * Nothing here allocates or blocks; the caller owns every buffer. */

#include <stddef.h>
#include <stdint.h>

#include "ubii/export.h"
#include "ubii/status.h"
#include "ubii/servers/server.pb.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Title and message of a ubii.general.Error reply, cut to fit (always NUL-terminated). */
typedef struct ubii_broker_error {
    char title[128];
    char message[512];
} ubii_broker_error;

/* Writes a ServiceRequest carrying only `topic` (e.g. "/services/server_configuration") into
 * buffer[0..capacity) and sets *length. Fails with UBII_ERR_BUFFER_TOO_SMALL if it does not fit. */
UBII_API ubii_status ubii_encode_topic_request(const char *topic, uint8_t *buffer, size_t capacity,
                                               size_t *length);

/* Decodes a ServiceReply that should carry a ubii.servers.Server. On UBII_ERR_BROKER, `error` (if
 * not NULL) receives the broker's title and message. `server` is written only on UBII_OK. */
UBII_API ubii_status ubii_decode_server_reply(const uint8_t *bytes, size_t length,
                                              ubii_servers_Server *server,
                                              ubii_broker_error *error);

#ifdef __cplusplus
}
#endif

#endif

#ifndef UBII_EMBEDDED_CONFIG_H
#define UBII_EMBEDDED_CONFIG_H

/* Compile-time limits of the embedded port: every buffer of ubii_embedded_port is sized here. Each
 * may be overridden with -D or in the header UBII_CONFIG_FILE names (ubii/config.h), like the
 * core's limits; the library and every file using ubii_embedded_port must see the same values. */

#include "ubii/config.h"

/* Largest message payload either way (a TopicData, a ServiceRequest or ServiceReply). */
#ifndef UBII_EMBEDDED_MAX_MESSAGE
#define UBII_EMBEDDED_MAX_MESSAGE 2048
#endif

/* Longest path (with query) of a URL, including the NUL: "/services/binary", or the WebSocket
 * path with "?clientID=<36-character id>" appended. A longer URL is refused by open. */
#ifndef UBII_EMBEDDED_MAX_PATH
#define UBII_EMBEDDED_MAX_PATH 80
#endif

/* Room next to a message for its framing. ZMTP needs 11 bytes and WebSocket 14; the HTTP request
 * head needs 144 plus the path, so this default lets every protocol carry a message of
 * UBII_EMBEDDED_MAX_MESSAGE. Handshakes use the whole buffer (it holds no message then). */
#ifndef UBII_EMBEDDED_HEADROOM
#define UBII_EMBEDDED_HEADROOM (UBII_EMBEDDED_MAX_PATH + 144)
#endif

#define UBII_EMBEDDED_BUFFER (UBII_EMBEDDED_MAX_MESSAGE + UBII_EMBEDDED_HEADROOM)

/* WebSocket masking-key bytes drawn from the platform at once. */
#ifndef UBII_EMBEDDED_MASK_POOL
#define UBII_EMBEDDED_MASK_POOL 64
#endif
#if UBII_EMBEDDED_MASK_POOL < 4 || UBII_EMBEDDED_MASK_POOL > 252 || UBII_EMBEDDED_MASK_POOL % 4 != 0
#error "UBII_EMBEDDED_MASK_POOL: a multiple of 4 from 4 to 252 (counted in a byte)"
#endif

/* Longest text ubii_embedded_port_last_error() returns, including the NUL. */
#ifndef UBII_EMBEDDED_ERROR_SIZE
#define UBII_EMBEDDED_ERROR_SIZE 96
#endif

#endif

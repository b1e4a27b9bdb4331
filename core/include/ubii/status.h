#ifndef UBII_STATUS_H
#define UBII_STATUS_H

#include "ubii/export.h"

#ifdef __cplusplus
extern "C" {
#endif

/* One status type for every libubii call. UBII_OK is zero, every failure negative. */
typedef enum ubii_status {
    UBII_OK = 0,
    UBII_ERR_INVALID_ARGUMENT = -1, /* a NULL pointer, empty topic or out-of-range value */
    UBII_ERR_BUFFER_TOO_SMALL = -2, /* the caller's buffer cannot hold the encoded message */
    UBII_ERR_ENCODE = -3,           /* nanopb refused to encode (e.g. a string over its max_size) */
    UBII_ERR_DECODE = -4,           /* malformed or oversized protobuf bytes */
    UBII_ERR_UNEXPECTED_REPLY =
        -5,              /* a well-formed reply of another kind than the request asks for */
    UBII_ERR_BROKER = -6 /* the master answered with ubii.general.Error */
} ubii_status;

/* A static English description of `status`; never NULL, also for unknown values. */
UBII_API const char *ubii_strerror(ubii_status status);

#ifdef __cplusplus
}
#endif

#endif

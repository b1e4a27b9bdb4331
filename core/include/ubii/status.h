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
        -5,                      /* a well-formed reply of another kind than the request asks for */
    UBII_ERR_BROKER = -6,        /* the master answered with ubii.general.Error */
    UBII_ERR_TIMEOUT = -7,       /* no answer within the configured time */
    UBII_ERR_NOT_CONNECTED = -8, /* the node is not ready (not registered, or the link is down) */
    UBII_ERR_FULL = -9,          /* a fixed-size table or queue of the node is full */
    UBII_ERR_WOULD_BLOCK = -10,  /* the transport cannot take or give a message right now */
    UBII_ERR_TRANSPORT = -11,    /* the transport failed (connection refused, lost, closed) */
    UBII_ERR_UNSUPPORTED = -12,  /* a URL scheme, regex, option or record type this build lacks */
    UBII_ERR_TOO_LARGE = -13,    /* a message over the transport's or node's size limit */
    UBII_ERR_WRONG_TYPE = -14,   /* a record holds another type than the one asked for */
    UBII_ERR_NOT_FOUND = -15,    /* no such subscription, call or field */
    UBII_ERR_STATE = -16,        /* the call is not allowed in the node's current state */
    UBII_ERR_CANCELLED = -17 /* a pending call dropped because the node stopped or reconnected */
} ubii_status;

/* A static English description of `status`; never NULL, also for unknown values. */
UBII_API const char *ubii_strerror(ubii_status status);

#ifdef __cplusplus
}
#endif

#endif

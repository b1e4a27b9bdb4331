#include "ubii/status.h"

const char *ubii_strerror(ubii_status status)
{
    switch (status) {
    case UBII_OK:
        return "success";
    case UBII_ERR_INVALID_ARGUMENT:
        return "invalid argument";
    case UBII_ERR_BUFFER_TOO_SMALL:
        return "buffer too small for the encoded message";
    case UBII_ERR_ENCODE:
        return "message could not be encoded";
    case UBII_ERR_DECODE:
        return "malformed or oversized message";
    case UBII_ERR_UNEXPECTED_REPLY:
        return "reply of an unexpected kind";
    case UBII_ERR_BROKER:
        return "the master replied with an error";
    }
    return "unknown status";
}

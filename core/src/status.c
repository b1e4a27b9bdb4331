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
    case UBII_ERR_TIMEOUT:
        return "timed out";
    case UBII_ERR_NOT_CONNECTED:
        return "not connected to a master";
    case UBII_ERR_FULL:
        return "table or queue full";
    case UBII_ERR_WOULD_BLOCK:
        return "transport busy, try again";
    case UBII_ERR_TRANSPORT:
        return "transport failure";
    case UBII_ERR_UNSUPPORTED:
        return "not supported";
    case UBII_ERR_TOO_LARGE:
        return "message too large";
    case UBII_ERR_WRONG_TYPE:
        return "record holds another type";
    case UBII_ERR_NOT_FOUND:
        return "not found";
    case UBII_ERR_STATE:
        return "not allowed in the current state";
    case UBII_ERR_CANCELLED:
        return "cancelled";
    }
    return "unknown status";
}

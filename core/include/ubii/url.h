#ifndef UBII_URL_H
#define UBII_URL_H

/* The endpoint URLs a node is given, split as the core and every port read them:
 * scheme://host[:port][/path][?query], the host a name, an IPv4 address or an IPv6 address in
 * brackets. Parsing only: nothing is resolved or copied; the parts point into the URL. */

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "ubii/export.h"
#include "ubii/status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum ubii_url_scheme {
    UBII_URL_OTHER = 0, /* a scheme this library has no transport for; a port may */
    UBII_URL_TCP,       /* ZMQ: host and port, nothing more */
    UBII_URL_WS,
    UBII_URL_WSS,
    UBII_URL_HTTP,
    UBII_URL_HTTPS
} ubii_url_scheme;

typedef struct ubii_url {
    ubii_url_scheme scheme;
    bool tls;         /* wss:// and https:// */
    const char *host; /* host_length bytes, without the brackets of an IPv6 address */
    size_t host_length;
    uint16_t port;    /* as given, else the scheme's (80, 443); 0 for none */
    const char *path; /* from the first '/' or '?' after the authority on; "" for none */
} ubii_url;

/* UBII_OK, or UBII_ERR_INVALID_ARGUMENT for a URL that is not of the form above: no scheme, an
 * empty host, a bracketed host that is no IPv6 address, a space or control character anywhere, a
 * port outside 1..65535, tcp:// without a port or with a path. */
UBII_API ubii_status ubii_url_parse(const char *url, ubii_url *parsed);

#ifdef __cplusplus
}
#endif

#endif

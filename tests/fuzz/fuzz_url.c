/* libFuzzer target: ubii_url_parse, which reads every URL the node and both ports are given. The
 * input is the URL (cut at its first NUL). A parsed URL's parts must lie inside it and agree with
 * what the parser promises: a host of at least one byte, a path that is empty or starts with '/'
 * or '?', a tcp:// URL with a port and nothing after it. */
#include <stdlib.h>
#include <string.h>

#include "ubii/url.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *url = malloc(size + 1);
    if (url == NULL) {
        return 0;
    }
    memcpy(url, data, size);
    url[size] = '\0';
    size_t length = strlen(url);
    ubii_url parsed;
    if (ubii_url_parse(url, &parsed) == UBII_OK) {
        const char *end = url + length;
        if (parsed.host < url || parsed.host_length == 0 ||
            parsed.host + parsed.host_length > end ||
            parsed.path < parsed.host + parsed.host_length || parsed.path > end ||
            (parsed.path[0] != '\0' && parsed.path[0] != '/' && parsed.path[0] != '?') ||
            memchr(parsed.host, '/', parsed.host_length) != NULL ||
            (parsed.scheme == UBII_URL_TCP && (parsed.port == 0 || parsed.path[0] != '\0')) ||
            (parsed.tls && parsed.scheme != UBII_URL_WSS && parsed.scheme != UBII_URL_HTTPS)) {
            abort();
        }
    }
    free(url);
    return 0;
}

/* The one URL reader of the library: the node checks its URLs and derives the topic URL with it,
 * and the ports take their host, port and path from it. */
#include "ubii/url.h"

#include <string.h>

static bool is_scheme_character(char c)
{
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '+' ||
           c == '-' || c == '.';
}

static bool is_ipv6_character(char c)
{
    return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F') || c == ':' ||
           c == '.';
}

/* Control characters and spaces end no part of a URL here: a URL holding one is refused. */
static bool is_printable(const char *text)
{
    for (const unsigned char *c = (const unsigned char *)text; *c != '\0'; ++c) {
        if (*c <= 0x20 || *c == 0x7f) {
            return false;
        }
    }
    return true;
}

static ubii_url_scheme known_scheme(const char *scheme, size_t length, bool *tls)
{
    static const struct {
        const char *name;
        ubii_url_scheme scheme;
        bool tls;
    } schemes[] = {{"tcp", UBII_URL_TCP, false},
                   {"ws", UBII_URL_WS, false},
                   {"wss", UBII_URL_WSS, true},
                   {"http", UBII_URL_HTTP, false},
                   {"https", UBII_URL_HTTPS, true}};
    for (size_t i = 0; i < sizeof schemes / sizeof schemes[0]; ++i) {
        if (strlen(schemes[i].name) == length && strncmp(schemes[i].name, scheme, length) == 0) {
            *tls = schemes[i].tls;
            return schemes[i].scheme;
        }
    }
    *tls = false;
    return UBII_URL_OTHER;
}

static uint16_t default_port(ubii_url_scheme scheme)
{
    switch (scheme) {
    case UBII_URL_WS:
    case UBII_URL_HTTP:
        return 80;
    case UBII_URL_WSS:
    case UBII_URL_HTTPS:
        return 443;
    default:
        return 0;
    }
}

/* Digits up to the path, 1..65535; *end receives where they stop. */
static bool read_port(const char *text, uint16_t *port, const char **end)
{
    uint32_t value = 0;
    const char *at = text;
    while (*at >= '0' && *at <= '9') {
        value = value * 10 + (uint32_t)(*at - '0');
        if (value > 65535) {
            return false;
        }
        ++at;
    }
    if (at == text || value == 0) {
        return false;
    }
    *port = (uint16_t)value;
    *end = at;
    return true;
}

ubii_status ubii_url_parse(const char *url, ubii_url *parsed)
{
    if (url == NULL || parsed == NULL) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    memset(parsed, 0, sizeof *parsed);
    if (!is_printable(url)) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    const char *separator = strstr(url, "://");
    if (separator == NULL || separator == url) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    for (const char *c = url; c < separator; ++c) {
        if (!is_scheme_character(*c)) {
            return UBII_ERR_INVALID_ARGUMENT;
        }
    }
    parsed->scheme = known_scheme(url, (size_t)(separator - url), &parsed->tls);
    const char *rest = separator + 3;
    if (*rest == '[') {
        const char *closing = strchr(rest, ']');
        if (closing == NULL) {
            return UBII_ERR_INVALID_ARGUMENT;
        }
        parsed->host = rest + 1;
        parsed->host_length = (size_t)(closing - parsed->host);
        for (size_t i = 0; i < parsed->host_length; ++i) {
            if (!is_ipv6_character(parsed->host[i])) {
                return UBII_ERR_INVALID_ARGUMENT;
            }
        }
        rest = closing + 1;
        if (*rest != '\0' && *rest != ':' && *rest != '/' && *rest != '?') {
            return UBII_ERR_INVALID_ARGUMENT;
        }
    } else {
        parsed->host = rest;
        parsed->host_length = strcspn(rest, ":/?");
        rest += parsed->host_length;
    }
    if (parsed->host_length == 0) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    parsed->port = default_port(parsed->scheme);
    if (*rest == ':' && !read_port(rest + 1, &parsed->port, &rest)) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    if (*rest != '\0' && *rest != '/' && *rest != '?') {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    parsed->path = rest;
    if (parsed->scheme == UBII_URL_TCP && (parsed->port == 0 || *rest != '\0')) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    return UBII_OK;
}

#ifndef UBII_NODE_EVENTS_H
#define UBII_NODE_EVENTS_H

/* What every part of the core takes from the node it works for: the port's clock and
 * the report to the application's on_error. Internal to the core; not installed. */

#include "ubii/node.h"

static inline uint64_t ubii__now(const ubii_node *node)
{
    return node->port.vtable->monotonic_ms(node->port.context);
}

/* A problem that does not end a call of the application's own. */
static inline void ubii__report(ubii_node *node, ubii_status status, const char *detail)
{
    if (node->config.on_error != NULL) {
        node->config.on_error(node, status, detail, node->config.on_error_user);
    }
}

#endif

#ifndef UBII_EXAMPLE_PORT_H
#define UBII_EXAMPLE_PORT_H

/* The examples run on the port the build has: the Linux port (libzmq, libwebsockets) or the
 * embedded one (plain sockets, static buffers). */

#include <stdbool.h>

#include "ubii/port.h"

#ifdef UBII_EXAMPLE_EMBEDDED
#include "ubii/port_embedded.h"

typedef ubii_embedded_port example_port;

static inline bool example_port_open(example_port *port)
{
    return ubii_embedded_port_init(port, ubii_embedded_posix_platform()) == UBII_OK;
}

static inline ubii_port example_port_get(example_port *port)
{
    return ubii_embedded_port_get(port);
}

static inline void example_port_close(example_port *port)
{
    ubii_embedded_port_close(port);
}
#else
#include "ubii/port_linux.h"

typedef struct example_port {
    ubii_linux_port *linux_port;
} example_port;

static inline bool example_port_open(example_port *port)
{
    ubii_linux_port_options options = {0};
    options.libwebsockets_log_level = 1; /* errors only */
    return ubii_linux_port_create(&port->linux_port, &options) == UBII_OK;
}

static inline ubii_port example_port_get(example_port *port)
{
    return ubii_linux_port_get(port->linux_port);
}

static inline void example_port_close(example_port *port)
{
    ubii_linux_port_destroy(port->linux_port);
}
#endif

#endif

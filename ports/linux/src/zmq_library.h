#ifndef UBII_ZMQ_LIBRARY_H
#define UBII_ZMQ_LIBRARY_H

/* libzmq, loaded when a port first needs it (UBII_LINUX_ZMQ_LIBZMQ) instead of at program start:
 * a node on the in-thread engine never maps libzmq and what it pulls in (libstdc++, Kerberos,
 * libsodium, PGM, NORM: 2.7 MiB of resident memory). zmq.h still gives the types and constants. */

#include <stdbool.h>
#include <stddef.h>

#include <zmq.h>

typedef struct ubii__zmq_library {
    void *handle; /* dlopen's; NULL until loaded */
    void *(*ctx_new)(void);
    int (*ctx_term)(void *context);
    void *(*socket)(void *context, int type);
    int (*close)(void *socket);
    int (*connect)(void *socket, const char *endpoint);
    int (*setsockopt)(void *socket, int option, const void *value, size_t length);
    int (*getsockopt)(void *socket, int option, void *value, size_t *length);
    int (*socket_monitor)(void *socket, const char *endpoint, int events);
    int (*msg_init)(zmq_msg_t *message);
    int (*msg_init_size)(zmq_msg_t *message, size_t size);
    int (*msg_close)(zmq_msg_t *message);
    void *(*msg_data)(zmq_msg_t *message);
    size_t (*msg_size)(const zmq_msg_t *message);
    int (*msg_more)(const zmq_msg_t *message);
    int (*msg_recv)(zmq_msg_t *message, void *socket, int flags);
    int (*msg_send)(zmq_msg_t *message, void *socket, int flags);
    int (*poll)(zmq_pollitem_t *items, int count, long timeout);
    int (*errno_)(void);
} ubii__zmq_library;

/* Loads libzmq and every function above; false, with `error` filled in, if any is missing. */
bool ubii__zmq_library_load(ubii__zmq_library *library, char *error, size_t error_size);
void ubii__zmq_library_unload(ubii__zmq_library *library);

#endif

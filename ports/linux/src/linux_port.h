#ifndef UBII_LINUX_PORT_INTERNAL_H
#define UBII_LINUX_PORT_INTERNAL_H

/* Internal to the Linux port. */

#include <stdint.h>

#include <zmq.h>

#include "ubii/port_linux.h"

typedef enum transport_kind { TRANSPORT_NONE = 0, TRANSPORT_ZMQ = 1 } transport_kind;

typedef struct zmq_channel {
    void *socket;
    void *monitor; /* PAIR socket receiving the socket's connection events */
    zmq_msg_t incoming;
    bool holds_incoming;
    zmq_msg_t outgoing;
    bool holds_outgoing;
} zmq_channel;

typedef struct channel {
    transport_kind kind;
    ubii_channel_state state;
    zmq_channel zmq;
} channel;

struct ubii_linux_port {
    ubii_linux_port_options options;
    void *zmq_context;
    uint32_t monitor_serial;
    channel channels[UBII_CHANNEL_COUNT];
};

/* zmq_channel.c */
ubii_status ubii__zmq_open(ubii_linux_port *port, ubii_channel which, const char *url,
                           const char *client_id);
void ubii__zmq_close(channel *ch);
void ubii__zmq_update_state(channel *ch);
ubii_status ubii__zmq_send_begin(ubii_linux_port *port, channel *ch, size_t size, uint8_t **buffer);
ubii_status ubii__zmq_send_commit(channel *ch);
ubii_status ubii__zmq_receive(ubii_linux_port *port, ubii_channel which, const uint8_t **data,
                              size_t *size);
/* Adds the channel's sockets to `items`; returns how many. */
int ubii__zmq_poll_items(channel *ch, zmq_pollitem_t *items);
int ubii__zmq_fds(channel *ch, ubii_pollfd *fds, int capacity);

#endif

/* ZeroMQ channels: REQ for services, DEALER (routing id = client id) for topic data. A monitor
 * socket reports the connection: OPEN after the ZMTP handshake (only then does the master's ROUTER
 * know the identity), LOST when the connection drops. */
#include <stdio.h>
#include <string.h>

#include "linux_port.h"

static const int monitored_events =
    ZMQ_EVENT_HANDSHAKE_SUCCEEDED | ZMQ_EVENT_DISCONNECTED | ZMQ_EVENT_HANDSHAKE_FAILED_PROTOCOL;

static void release_messages(zmq_channel *z)
{
    if (z->holds_incoming) {
        z->api->msg_close(&z->incoming);
        z->holds_incoming = false;
    }
    if (z->holds_outgoing) {
        z->api->msg_close(&z->outgoing);
        z->holds_outgoing = false;
    }
}

void ubii__zmq_close(channel *ch)
{
    zmq_channel *z = &ch->zmq;
    release_messages(z);
    if (z->socket != NULL) {
        z->api->socket_monitor(z->socket, NULL, 0);
        z->api->close(z->socket);
        z->socket = NULL;
    }
    if (z->monitor != NULL) {
        z->api->close(z->monitor);
        z->monitor = NULL;
    }
}

static bool set_int(const ubii__zmq_library *zmq, void *socket, int option, int value)
{
    return zmq->setsockopt(socket, option, &value, sizeof value) == 0;
}

ubii_status ubii__zmq_open(ubii_linux_port *port, ubii_channel which, const char *url,
                           const char *client_id)
{
    channel *ch = &port->channels[which];
    zmq_channel *z = &ch->zmq;
    memset(z, 0, sizeof *z);
    z->api = &port->zmq_api;
    bool topic = which == UBII_CHANNEL_TOPIC;
    if (topic && (client_id == NULL || client_id[0] == '\0' || strlen(client_id) > 255)) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    z->socket = z->api->socket(port->zmq_context, topic ? ZMQ_DEALER : ZMQ_REQ);
    if (z->socket == NULL) {
        return UBII_ERR_TRANSPORT;
    }
    int64_t max_size = (int64_t)port->options.max_message_size;
    bool configured =
        set_int(z->api, z->socket, ZMQ_LINGER, 0) &&
        z->api->setsockopt(z->socket, ZMQ_MAXMSGSIZE, &max_size, sizeof max_size) == 0 &&
        (!topic ||
         z->api->setsockopt(z->socket, ZMQ_ROUTING_ID, client_id, strlen(client_id)) == 0);
    char endpoint[64];
    snprintf(endpoint, sizeof endpoint, "inproc://ubii-monitor-%p-%u", (void *)port,
             ++port->monitor_serial);
    if (configured && z->api->socket_monitor(z->socket, endpoint, monitored_events) == 0) {
        z->monitor = z->api->socket(port->zmq_context, ZMQ_PAIR);
        configured = z->monitor != NULL && set_int(z->api, z->monitor, ZMQ_LINGER, 0) &&
                     z->api->connect(z->monitor, endpoint) == 0;
    } else {
        configured = false;
    }
    if (!configured || z->api->connect(z->socket, url) != 0) {
        ubii_status status = z->api->errno_() == EINVAL || z->api->errno_() == EPROTONOSUPPORT
                                 ? UBII_ERR_INVALID_ARGUMENT
                                 : UBII_ERR_TRANSPORT;
        ubii__zmq_close(ch);
        return status;
    }
    ch->state = UBII_CHANNEL_CONNECTING;
    return UBII_OK;
}

/* Reads the monitor's events: [uint16 event, uint32 value] then the endpoint. */
void ubii__zmq_update_state(channel *ch)
{
    zmq_channel *z = &ch->zmq;
    if (z->monitor == NULL) {
        return;
    }
    for (;;) {
        zmq_msg_t frame;
        z->api->msg_init(&frame);
        if (z->api->msg_recv(&frame, z->monitor, ZMQ_DONTWAIT) < 0) {
            z->api->msg_close(&frame);
            return;
        }
        uint16_t event = 0;
        if (z->api->msg_size(&frame) >= sizeof event) {
            memcpy(&event, z->api->msg_data(&frame), sizeof event);
        }
        while (z->api->msg_more(&frame)) {
            z->api->msg_close(&frame);
            z->api->msg_init(&frame);
            if (z->api->msg_recv(&frame, z->monitor, ZMQ_DONTWAIT) < 0) {
                break;
            }
        }
        z->api->msg_close(&frame);
        if (event == ZMQ_EVENT_HANDSHAKE_SUCCEEDED && ch->state == UBII_CHANNEL_CONNECTING) {
            ch->state = UBII_CHANNEL_OPEN;
        } else if (event == ZMQ_EVENT_DISCONNECTED ||
                   event == ZMQ_EVENT_HANDSHAKE_FAILED_PROTOCOL) {
            ch->state = UBII_CHANNEL_LOST;
        }
    }
}

ubii_status ubii__zmq_send_begin(ubii_linux_port *port, channel *ch, size_t size, uint8_t **buffer)
{
    zmq_channel *z = &ch->zmq;
    if (size > port->options.max_message_size) {
        return UBII_ERR_TOO_LARGE;
    }
    if (z->holds_outgoing) {
        z->api->msg_close(&z->outgoing);
        z->holds_outgoing = false;
    }
    if (z->api->msg_init_size(&z->outgoing, size) != 0) {
        return UBII_ERR_TRANSPORT;
    }
    z->holds_outgoing = true;
    *buffer = z->api->msg_data(&z->outgoing);
    return UBII_OK;
}

/* The master reads exactly one frame per message on both channels (no delimiter on the DEALER). */
ubii_status ubii__zmq_send_commit(channel *ch)
{
    zmq_channel *z = &ch->zmq;
    if (!z->holds_outgoing) {
        return UBII_ERR_STATE;
    }
    if (z->api->msg_send(&z->outgoing, z->socket, ZMQ_DONTWAIT) < 0) {
        int error = z->api->errno_();
        z->api->msg_close(&z->outgoing);
        z->holds_outgoing = false;
        return error == EAGAIN ? UBII_ERR_WOULD_BLOCK : UBII_ERR_TRANSPORT;
    }
    z->holds_outgoing = false; /* zmq_msg_send took over the message */
    return UBII_OK;
}

static void discard_remaining_parts(const ubii__zmq_library *zmq, void *socket, zmq_msg_t *frame)
{
    while (zmq->msg_more(frame)) {
        zmq_msg_t rest;
        zmq->msg_init(&rest);
        int received = zmq->msg_recv(&rest, socket, ZMQ_DONTWAIT);
        bool more = received >= 0 && zmq->msg_more(&rest);
        zmq->msg_close(&rest);
        if (!more) {
            return;
        }
    }
}

/* REQ delivers the reply alone; the DEALER receives [empty delimiter, payload] from the ROUTER. */
ubii_status ubii__zmq_receive(ubii_linux_port *port, ubii_channel which, const uint8_t **data,
                              size_t *size)
{
    zmq_channel *z = &port->channels[which].zmq;
    if (z->holds_incoming) {
        z->api->msg_close(&z->incoming);
        z->holds_incoming = false;
    }
    for (;;) {
        z->api->msg_init(&z->incoming);
        if (z->api->msg_recv(&z->incoming, z->socket, ZMQ_DONTWAIT) < 0) {
            z->api->msg_close(&z->incoming);
            return UBII_ERR_WOULD_BLOCK;
        }
        if (which == UBII_CHANNEL_TOPIC && z->api->msg_size(&z->incoming) == 0 &&
            z->api->msg_more(&z->incoming)) {
            z->api->msg_close(&z->incoming);
            z->api->msg_init(&z->incoming);
            if (z->api->msg_recv(&z->incoming, z->socket, ZMQ_DONTWAIT) < 0) {
                z->api->msg_close(&z->incoming);
                return UBII_ERR_WOULD_BLOCK;
            }
        }
        if (z->api->msg_more(&z->incoming)) { /* not a shape the master sends: skip it whole */
            discard_remaining_parts(z->api, z->socket, &z->incoming);
            z->api->msg_close(&z->incoming);
            continue;
        }
        z->holds_incoming = true;
        *data = z->api->msg_data(&z->incoming);
        *size = z->api->msg_size(&z->incoming);
        return UBII_OK;
    }
}

int ubii__zmq_poll_items(channel *ch, zmq_pollitem_t *items)
{
    int count = 0;
    if (ch->zmq.socket != NULL) {
        items[count].socket = ch->zmq.socket;
        items[count].events = ZMQ_POLLIN;
        count++;
    }
    if (ch->zmq.monitor != NULL) {
        items[count].socket = ch->zmq.monitor;
        items[count].events = ZMQ_POLLIN;
        count++;
    }
    return count;
}

int ubii__zmq_fds(channel *ch, ubii_pollfd *fds, int capacity)
{
    void *sockets[2] = {ch->zmq.socket, ch->zmq.monitor};
    int count = 0;
    for (int i = 0; i < 2; ++i) {
        if (sockets[i] == NULL) {
            continue;
        }
        int fd = -1;
        size_t length = sizeof fd;
        if (ch->zmq.api->getsockopt(sockets[i], ZMQ_FD, &fd, &length) == 0) {
            if (count < capacity) {
                fds[count].fd = fd;
                fds[count].events = 1; /* POLLIN: ZMQ_FD signals readiness of either direction */
            }
            count++;
        }
    }
    return count;
}

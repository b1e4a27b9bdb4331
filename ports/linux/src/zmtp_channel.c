/* tcp:// in the caller's thread (UBII_LINUX_ZMQ_IN_THREAD): ZMQ's wire protocol (ZMTP 3,
 * ports/common/zmtp_wire.c) over a plain non-blocking socket that the port polls itself.
 *
 * Why not libzmq: its I/O thread wakes for every message that arrives, which costs more kernel time
 * than all the rest of receiving it. Here bytes wait in the socket until the node is polled, so a
 * node polled once per frame takes a frame's worth of messages in a few reads, and its own go out
 * together in one write. The master sees the same REQ or DEALER peer either way.
 * Why not libwebsockets' raw sockets: a node that speaks only tcp:// then never loads
 * libwebsockets and the OpenSSL it brings (lws_library.h).
 *
 * Buffers: what arrives is read into `rx` and handed to the core in place (lent until the next
 * receive); what the core sends is framed in place at the end of `tx`, behind our greeting. */
#define _POSIX_C_SOURCE 200809L /* getaddrinfo */

#include <errno.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <unistd.h>

#include "linux_port.h"
#include "ubii/url.h"
#include "zmtp_wire.h"

enum {
    READ_CHUNK = 64 * 1024,
    /* Read per wait at most: a flood cannot keep one wait reading forever (4 MiB, as the
     * libwebsockets transports take per wait). */
    READ_PER_WAIT = 4 * 1024 * 1024,
    /* Sent but not yet taken by the socket, at most, before send_begin says WOULD_BLOCK. */
    OUTBOX_LIMIT_BYTES = 64 * 1024 * 1024,
    /* An emptied buffer larger than this is given back (after an image, say). */
    KEPT_CAPACITY = 256 * 1024
};

static void close_socket(ubii_linux_port *port, zmtp_channel *z)
{
    if (z->fd >= 0) {
        ubii__lws_release_fd(port, z);
        close(z->fd);
        z->fd = -1;
    }
}

/* Marks the channel LOST with the first reason, and lets go of the socket: a dead socket must not
 * end every wait at once. */
static void lose(ubii_linux_port *port, channel *ch, const char *what, const char *detail)
{
    if (ch->state != UBII_CHANNEL_LOST) {
        ubii__port_error(port, what, detail);
        ch->state = UBII_CHANNEL_LOST;
    }
    close_socket(port, &ch->zmtp);
}

/* Makes room for `more` bytes after `*end`: moves the unread part to the front, or grows the
 * buffer. Without `may_move` (part of it is lent) only the room there is, if any. */
static bool make_room(uint8_t **buffer, size_t *start, size_t *end, size_t *capacity, size_t more,
                      bool may_move)
{
    if (*capacity - *end >= more) {
        return true;
    }
    if (!may_move) {
        return *capacity > *end; /* what room there is */
    }
    if (*start > 0) {
        memmove(*buffer, *buffer + *start, *end - *start);
        *end -= *start;
        *start = 0;
        if (*capacity - *end >= more) {
            return true;
        }
    }
    size_t needed = *end + more;
    size_t grown = *capacity > 0 ? *capacity : READ_CHUNK;
    while (grown < needed) {
        grown *= 2;
    }
    uint8_t *moved = realloc(*buffer, grown);
    if (moved == NULL) {
        return false;
    }
    *buffer = moved;
    *capacity = grown;
    return true;
}

/* An emptied buffer starts again at its front; a large one is given back. */
static void rewind_if_empty(uint8_t **buffer, size_t *start, size_t *end, size_t *capacity)
{
    if (*start != *end) {
        return;
    }
    *start = *end = 0;
    if (*capacity > KEPT_CAPACITY) {
        free(*buffer);
        *buffer = NULL;
        *capacity = 0;
    }
}

/* Starts a non-blocking connect to z->trying or the addresses after it; false if none can
 * start. */
static bool connect_next(ubii_linux_port *port, zmtp_channel *z, int *failure)
{
    for (; z->trying != NULL; z->trying = z->trying->ai_next) {
        close_socket(port, z);
        const struct addrinfo *address = z->trying;
        z->fd = socket(address->ai_family, address->ai_socktype | SOCK_NONBLOCK | SOCK_CLOEXEC,
                       address->ai_protocol);
        if (z->fd < 0) {
            *failure = errno;
            continue;
        }
        int one = 1;
        setsockopt(z->fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one); /* as libzmq does */
        if (connect(z->fd, address->ai_addr, address->ai_addrlen) == 0 || errno == EINPROGRESS) {
            ubii__lws_adopt_fd(port, z, z->fd, NULL);
            return true;
        }
        *failure = errno;
    }
    close_socket(port, z);
    return false;
}

ubii_status ubii__zmtp_open(ubii_linux_port *port, ubii_channel which, const char *url,
                            const char *client_id)
{
    channel *ch = &port->channels[which];
    zmtp_channel *z = &ch->zmtp;
    memset(z, 0, sizeof *z);
    z->fd = -1;
    z->request = which == UBII_CHANNEL_SERVICE;
    ubii_url parsed;
    if (ubii_url_parse(url, &parsed) != UBII_OK || parsed.scheme != UBII_URL_TCP ||
        parsed.host_length >= 256) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    if (!z->request && (client_id == NULL || client_id[0] == '\0')) {
        return UBII_ERR_INVALID_ARGUMENT; /* the master routes topic data by the DEALER's id */
    }
    if (!make_room(&z->tx, &z->tx_start, &z->tx_end, &z->tx_capacity, UBII_ZMTP_HANDSHAKE_MAX,
                   true)) {
        return UBII_ERR_TRANSPORT;
    }
    z->greeting_unsent = ubii__zmtp_handshake(z->tx, UBII_ZMTP_HANDSHAKE_MAX, !z->request,
                                              z->request ? "" : client_id);
    if (z->greeting_unsent == 0) {
        return UBII_ERR_INVALID_ARGUMENT; /* an identity too long for the READY command */
    }
    z->tx_end = z->greeting_unsent;
    char host[256], service[8];
    memcpy(host, parsed.host, parsed.host_length);
    host[parsed.host_length] = '\0';
    snprintf(service, sizeof service, "%u", (unsigned)parsed.port);
    struct addrinfo hints;
    memset(&hints, 0, sizeof hints);
    hints.ai_family = AF_UNSPEC;
    hints.ai_socktype = SOCK_STREAM;
    hints.ai_flags = AI_NUMERICSERV;
    /* Synchronous, as libwebsockets resolves (port_linux.h says so). */
    int resolved = getaddrinfo(host, service, &hints, &z->addresses);
    ch->state = UBII_CHANNEL_CONNECTING;
    if (resolved != 0) {
        z->addresses = NULL;
        lose(port, ch, "ZMQ host could not be resolved", gai_strerror(resolved));
        return UBII_OK; /* as an unreachable host: LOST, and the core retries */
    }
    z->trying = z->addresses;
    int failure = 0;
    if (!connect_next(port, z, &failure)) {
        lose(port, ch, "ZMQ connection failed", strerror(failure));
    }
    return UBII_OK;
}

void ubii__zmtp_close(ubii_linux_port *port, channel *ch)
{
    zmtp_channel *z = &ch->zmtp;
    close_socket(port, z);
    if (z->addresses != NULL) {
        freeaddrinfo(z->addresses);
    }
    free(z->rx);
    free(z->tx);
    memset(z, 0, sizeof *z);
    z->fd = -1;
}

/* Has the non-blocking connect ended? On failure the next address is tried. */
static bool finish_connect(ubii_linux_port *port, channel *ch)
{
    zmtp_channel *z = &ch->zmtp;
    struct pollfd done = {z->fd, POLLOUT, 0};
    if (poll(&done, 1, 0) <= 0) {
        return false;
    }
    int failure = 0;
    socklen_t length = sizeof failure;
    if (getsockopt(z->fd, SOL_SOCKET, SO_ERROR, &failure, &length) != 0) {
        failure = errno;
    }
    if (failure == 0) {
        z->connected = true;
        freeaddrinfo(z->addresses);
        z->addresses = z->trying = NULL;
        return true;
    }
    z->trying = z->trying->ai_next;
    if (!connect_next(port, z, &failure)) {
        lose(port, ch, "ZMQ connection failed", strerror(failure));
    }
    return false;
}

/* Writes what the socket takes now: before the master's READY only our greeting and READY. */
static bool flush(ubii_linux_port *port, channel *ch)
{
    zmtp_channel *z = &ch->zmtp;
    while (z->fd >= 0 && z->connected && z->tx_end > z->tx_start) {
        size_t ready = z->tx_end - z->tx_start;
        if (ch->state != UBII_CHANNEL_OPEN) {
            if (z->greeting_unsent == 0) {
                break;
            }
            ready = z->greeting_unsent;
        }
        ssize_t sent = send(z->fd, z->tx + z->tx_start, ready, MSG_NOSIGNAL);
        if (sent < 0) {
            if (errno == EINTR) {
                continue;
            }
            if (errno == EAGAIN || errno == EWOULDBLOCK) {
                break;
            }
            lose(port, ch, "write to the master failed", strerror(errno));
            return false;
        }
        z->tx_start += (size_t)sent;
        z->greeting_unsent -= z->greeting_unsent < (size_t)sent ? z->greeting_unsent : (size_t)sent;
    }
    if (!z->has_reservation) {
        rewind_if_empty(&z->tx, &z->tx_start, &z->tx_end, &z->tx_capacity);
    }
    return z->fd >= 0;
}

/* Unread bytes held at most: a whole message and what one wait reads behind it. */
static size_t read_limit(const ubii_linux_port *port)
{
    return port->options.max_message_size + 2 * UBII_ZMTP_MAX_HEADER + READ_PER_WAIT;
}

/* Reads what has arrived, READ_PER_WAIT at most. */
static bool read_arrived(ubii_linux_port *port, channel *ch)
{
    zmtp_channel *z = &ch->zmtp;
    for (size_t read_now = 0; read_now < READ_PER_WAIT;) {
        if (z->rx_end - z->rx_start >= read_limit(port)) {
            break; /* unread: the core takes it at its next poll */
        }
        if (!make_room(&z->rx, &z->rx_start, &z->rx_end, &z->rx_capacity, READ_CHUNK,
                       z->lent == 0)) {
            if (z->lent == 0) {
                lose(port, ch, "no memory for received bytes", NULL);
                return false;
            }
            break; /* read on once the core has returned what it was lent */
        }
        ssize_t got = recv(z->fd, z->rx + z->rx_end, z->rx_capacity - z->rx_end, 0);
        if (got > 0) {
            z->rx_end += (size_t)got;
            read_now += (size_t)got;
            continue;
        }
        if (got == 0) {
            lose(port, ch, "ZMQ connection closed by the master", NULL);
            return false;
        }
        if (errno == EINTR) {
            continue;
        }
        if (errno == EAGAIN || errno == EWOULDBLOCK) {
            break;
        }
        lose(port, ch, "ZMQ connection failed", strerror(errno));
        return false;
    }
    return true;
}

/* The unit at rx_start + offset; a broken or oversized one ends the connection. */
static ubii_zmtp_unit unit_at(ubii_linux_port *port, channel *ch, size_t offset,
                              ubii_zmtp_found *found)
{
    zmtp_channel *z = &ch->zmtp;
    size_t at = z->rx_start + offset;
    ubii_zmtp_unit unit = ubii__zmtp_next(&z->step, z->rx + at, z->rx_end - at,
                                          port->options.max_message_size, found);
    switch (unit) {
    case UBII_ZMTP_SKIP:
        if (z->step == UBII_ZMTP_STEP_OPEN && ch->state == UBII_CHANNEL_CONNECTING) {
            ch->state = UBII_CHANNEL_OPEN;
        }
        break;
    case UBII_ZMTP_MISSHAPEN: /* dropped whole, as libzmq's DEALER and REQ do */
        ubii__port_error(port, "a ZMQ message of a shape the master never sends was dropped", NULL);
        break;
    case UBII_ZMTP_TOO_LARGE:
        lose(port, ch, "message over the size limit", NULL);
        break;
    case UBII_ZMTP_ERROR:
        lose(port, ch, found->error, NULL);
        break;
    default:
        break;
    }
    return unit;
}

/* rx_start moves on by `consumed`: so does what has been checked. */
static void consume(zmtp_channel *z, size_t consumed)
{
    z->rx_start += consumed;
    z->checked -= z->checked < consumed ? z->checked : consumed;
}

/* Takes the master's greeting and READY as they arrive: the channel opens with them. */
static void take_handshake(ubii_linux_port *port, channel *ch)
{
    zmtp_channel *z = &ch->zmtp;
    while (ch->state == UBII_CHANNEL_CONNECTING && z->lent == 0) {
        ubii_zmtp_found found;
        if (unit_at(port, ch, 0, &found) != UBII_ZMTP_SKIP) {
            return;
        }
        consume(z, found.consumed);
    }
}

/* Looks through what has arrived for a broken or oversized frame: the channel is LOST as soon as
 * one arrives, not only when the core has taken the messages before it. */
static void check_arrived(ubii_linux_port *port, channel *ch)
{
    zmtp_channel *z = &ch->zmtp;
    if (z->checked < z->lent) {
        z->checked = z->lent;
    }
    while (ch->state == UBII_CHANNEL_OPEN) {
        ubii_zmtp_found found;
        ubii_zmtp_unit unit = unit_at(port, ch, z->checked, &found);
        if (unit != UBII_ZMTP_MESSAGE && unit != UBII_ZMTP_SKIP && unit != UBII_ZMTP_MISSHAPEN) {
            return;
        }
        z->checked += found.consumed;
    }
}

void ubii__zmtp_service(ubii_linux_port *port, ubii_channel which)
{
    channel *ch = &port->channels[which];
    zmtp_channel *z = &ch->zmtp;
    if (z->fd < 0 || (!z->connected && !finish_connect(port, ch))) {
        return;
    }
    if (!flush(port, ch) || !read_arrived(port, ch)) {
        return;
    }
    if (ch->state == UBII_CHANNEL_CONNECTING) {
        take_handshake(port, ch);
        flush(port, ch); /* what waited for the master's READY */
    }
    check_arrived(port, ch);
}

void ubii__zmtp_flush(ubii_linux_port *port, ubii_channel which)
{
    flush(port, &port->channels[which]);
}

short ubii__zmtp_events(const ubii_linux_port *port, const channel *ch)
{
    const zmtp_channel *z = &ch->zmtp;
    if (z->fd < 0) {
        return 0;
    }
    bool writing = !z->connected || (ch->state == UBII_CHANNEL_OPEN && z->tx_end > z->tx_start) ||
                   z->greeting_unsent > 0;
    /* Not while read_arrived would leave the socket alone: the wait would end at once, forever. */
    bool reading =
        z->rx_end - z->rx_start < read_limit(port) && (z->lent == 0 || z->rx_end < z->rx_capacity);
    return (short)((reading ? POLLIN : 0) | (writing ? POLLOUT : 0));
}

/* Gives back what the core was lent. */
static void return_lent(zmtp_channel *z)
{
    consume(z, z->lent);
    z->lent = 0;
    rewind_if_empty(&z->rx, &z->rx_start, &z->rx_end, &z->rx_capacity);
}

ubii_status ubii__zmtp_send_begin(ubii_linux_port *port, channel *ch, size_t size, uint8_t **buffer)
{
    zmtp_channel *z = &ch->zmtp;
    if (size > port->options.max_message_size) {
        return UBII_ERR_TOO_LARGE;
    }
    if (z->request) {
        return_lent(z); /* a reply is done with before the next request (port.h) */
    }
    size_t header = ubii__zmtp_header_size(z->request, size);
    size_t pending = z->tx_end - z->tx_start;
    if (pending > 0 && pending + header + size > OUTBOX_LIMIT_BYTES) {
        return UBII_ERR_WOULD_BLOCK;
    }
    if (!make_room(&z->tx, &z->tx_start, &z->tx_end, &z->tx_capacity, header + size, true)) {
        return UBII_ERR_TRANSPORT;
    }
    z->has_reservation = true;
    z->reserved_size = size;
    *buffer = z->tx + z->tx_end + header;
    return UBII_OK;
}

ubii_status ubii__zmtp_send_commit(channel *ch)
{
    zmtp_channel *z = &ch->zmtp;
    if (!z->has_reservation) {
        return UBII_ERR_STATE;
    }
    z->has_reservation = false;
    ubii__zmtp_write_header(z->tx + z->tx_end, z->request, z->reserved_size);
    z->tx_end += ubii__zmtp_header_size(z->request, z->reserved_size) + z->reserved_size;
    return UBII_OK; /* written at the next wait, with whatever else is queued by then */
}

ubii_status ubii__zmtp_receive(ubii_linux_port *port, channel *ch, const uint8_t **data,
                               size_t *size)
{
    zmtp_channel *z = &ch->zmtp;
    return_lent(z);
    /* Also once LOST: what arrived before the end is still the master's. */
    while (z->step == UBII_ZMTP_STEP_OPEN) {
        ubii_zmtp_found found;
        ubii_zmtp_unit unit = unit_at(port, ch, 0, &found);
        if (unit == UBII_ZMTP_MESSAGE) {
            *data = z->rx + z->rx_start + found.payload;
            *size = (size_t)found.size;
            z->lent = found.consumed;
            return UBII_OK;
        }
        if (unit != UBII_ZMTP_SKIP && unit != UBII_ZMTP_MISSHAPEN) {
            break;
        }
        consume(z, found.consumed);
    }
    return UBII_ERR_WOULD_BLOCK;
}

#define _POSIX_C_SOURCE 200809L /* clock_gettime in strict C99 */
/* The Linux port's vtable: picks the transport by URL scheme and drives the I/O. */
#include <errno.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/eventfd.h>
#include <time.h>
#include <unistd.h>

#include "linux_port.h"
#include "ubii/config.h"

void ubii__port_error(ubii_linux_port *port, const char *what, const char *detail)
{
    snprintf(port->last_error, sizeof port->last_error, "%s%s%s", what, detail ? ": " : "",
             detail ? detail : "");
}

static int poll_fds(void *context, ubii_pollfd *fds, int capacity);

static bool starts_with(const char *text, const char *prefix)
{
    return strncmp(text, prefix, strlen(prefix)) == 0;
}

static bool uses_lws(const channel *ch)
{
    return ch->kind == TRANSPORT_WEBSOCKET || ch->kind == TRANSPORT_HTTP;
}

static void close_channel(void *context, ubii_channel which)
{
    ubii_linux_port *port = context;
    if ((unsigned)which >= UBII_CHANNEL_COUNT) {
        return;
    }
    channel *ch = &port->channels[which];
    if (ch->kind == TRANSPORT_ZMQ) {
        ubii__lws_release_fd(port, ch->zmq.socket);
        ubii__lws_release_fd(port, ch->zmq.monitor);
        ubii__zmq_close(ch);
    } else if (ch->kind == TRANSPORT_ZMTP) {
        ubii__zmtp_close(port, ch);
    } else if (uses_lws(ch)) {
        ubii__lws_close(port, which);
    }
    ch->kind = TRANSPORT_NONE;
    ch->state = UBII_CHANNEL_CLOSED;
}

static ubii_status open_channel(void *context, ubii_channel which, const char *url,
                                const char *client_id)
{
    ubii_linux_port *port = context;
    if ((unsigned)which >= UBII_CHANNEL_COUNT || url == NULL) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    close_channel(port, which);
    /* last_error stays: a channel reopened while the node gives up (a REQ socket is reset when its
     * call is cancelled) must not wipe the reason it gave up for. */
    channel *ch = &port->channels[which];
    if (starts_with(url, "tcp://") && port->options.zmq_engine == UBII_LINUX_ZMQ_LIBZMQ) {
        ubii_status status = ubii__zmq_open(port, which, url, client_id);
        if (status == UBII_OK) {
            ch->kind = TRANSPORT_ZMQ;
            ubii__lws_adopt_zmq(port, ch->zmq.socket);
            ubii__lws_adopt_zmq(port, ch->zmq.monitor);
        }
        return status;
    }
    if (starts_with(url, "tcp://")) {
        ch->kind = TRANSPORT_ZMTP;
        ubii_status status = ubii__zmtp_open(port, which, url, client_id);
        if (status != UBII_OK) {
            close_channel(port, which);
        }
        return status;
    }
    if (starts_with(url, "ws://") || starts_with(url, "wss://") || starts_with(url, "http://") ||
        starts_with(url, "https://")) {
        ubii_status status = ubii__lws_open(port, which, url, client_id);
        if (status != UBII_OK) {
            close_channel(port, which);
        }
        return status;
    }
    return UBII_ERR_UNSUPPORTED;
}

static ubii_channel_state channel_state(void *context, ubii_channel which)
{
    ubii_linux_port *port = context;
    if ((unsigned)which >= UBII_CHANNEL_COUNT) {
        return UBII_CHANNEL_CLOSED;
    }
    channel *ch = &port->channels[which];
    if (ch->kind == TRANSPORT_ZMQ) {
        ubii__zmq_update_state(ch);
    }
    return ch->state;
}

static bool can_send(const channel *ch)
{
    return ch->state == UBII_CHANNEL_OPEN || ch->state == UBII_CHANNEL_CONNECTING;
}

static ubii_status send_begin(void *context, ubii_channel which, size_t size, uint8_t **buffer)
{
    ubii_linux_port *port = context;
    if ((unsigned)which >= UBII_CHANNEL_COUNT || buffer == NULL) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    channel *ch = &port->channels[which];
    if (!can_send(ch)) {
        return UBII_ERR_NOT_CONNECTED;
    }
    if (uses_lws(ch)) {
        return ubii__lws_send_begin(port, which, size, buffer);
    }
    if (ch->kind == TRANSPORT_ZMTP) {
        return ubii__zmtp_send_begin(port, ch, size, buffer);
    }
    return ubii__zmq_send_begin(port, ch, size, buffer);
}

static ubii_status send_commit(void *context, ubii_channel which, unsigned flags)
{
    ubii_linux_port *port = context;
    if ((unsigned)which >= UBII_CHANNEL_COUNT) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    channel *ch = &port->channels[which];
    if (!can_send(ch)) {
        return UBII_ERR_NOT_CONNECTED;
    }
    if (uses_lws(ch)) {
        return ubii__lws_send_commit(port, which, flags);
    }
    /* ZMQ frames have no text/binary distinction */
    if (ch->kind == TRANSPORT_ZMTP) {
        return ubii__zmtp_send_commit(ch);
    }
    return ubii__zmq_send_commit(ch);
}

static ubii_status receive(void *context, ubii_channel which, const uint8_t **data, size_t *size,
                           unsigned *flags)
{
    ubii_linux_port *port = context;
    if ((unsigned)which >= UBII_CHANNEL_COUNT || data == NULL || size == NULL || flags == NULL) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    channel *ch = &port->channels[which];
    *flags = 0;
    if (uses_lws(ch)) {
        return ubii__lws_receive(port, which, data, size, flags);
    }
    if (ch->kind == TRANSPORT_ZMTP) {
        return ubii__zmtp_receive(port, ch, data, size);
    }
    if (ch->kind != TRANSPORT_ZMQ) {
        return UBII_ERR_WOULD_BLOCK;
    }
    return ubii__zmq_receive(port, which, data, size);
}

/* ZMQ's fd signals edges: a message may already wait although the fd is quiet. */
static bool zmq_message_waiting(ubii_linux_port *port)
{
    for (int i = 0; i < UBII_CHANNEL_COUNT; ++i) {
        void *sockets[2] = {port->channels[i].zmq.socket, port->channels[i].zmq.monitor};
        for (int j = 0; port->channels[i].kind == TRANSPORT_ZMQ && j < 2; ++j) {
            int events = 0;
            size_t length = sizeof events;
            if (sockets[j] != NULL &&
                port->zmq_api.getsockopt(sockets[j], ZMQ_EVENTS, &events, &length) == 0 &&
                (events & ZMQ_POLLIN)) {
                return true;
            }
        }
    }
    return false;
}

/* libwebsockets must drive the wait while one of its connections exists (only it knows what
 * they wait for); otherwise poll or zmq_poll alone is cheaper. */
static bool lws_in_use(const ubii_linux_port *port)
{
    for (int i = 0; i < UBII_CHANNEL_COUNT; ++i) {
        if (uses_lws(&port->channels[i])) {
            return true;
        }
    }
    return port->lws_connections > 0;
}

static void drain_wake(ubii_linux_port *port)
{
    uint64_t count;
    if (read(port->wake_fd, &count, sizeof count) < 0) {
        return; /* EAGAIN: nobody woke the port */
    }
}

/* The wait without libzmq and libwebsockets: poll(2) over the port's own pollfds, which are then
 * the in-thread ZMTP connections' (one per channel at most) and the wake fd, last. */
static ubii_status poll_plain(ubii_linux_port *port, int timeout_ms)
{
    enum { MOST = UBII_CHANNEL_COUNT + 1 };
    ubii_pollfd wanted[MOST];
    int count = poll_fds(port, wanted, MOST);
    if (count > MOST) {
        return UBII_ERR_STATE; /* a libzmq or libwebsockets fd: their own waits take those */
    }
    struct pollfd fds[MOST];
    for (int i = 0; i < count; ++i) {
        fds[i].fd = wanted[i].fd;
        fds[i].events = wanted[i].events;
        fds[i].revents = 0;
    }
    if (poll(fds, (nfds_t)count, timeout_ms) < 0 && errno != EINTR) {
        return UBII_ERR_TRANSPORT;
    }
    if (fds[count - 1].revents & POLLIN) {
        drain_wake(port);
    }
    return UBII_OK;
}

static ubii_status wait_for_any(ubii_linux_port *port, int timeout_ms)
{
    if (port->lws != NULL && lws_in_use(port)) {
        /* The wake fd and the others are adopted into lws, which only waits on them. */
        for (int i = 0; i < UBII_CHANNEL_COUNT; ++i) {
            channel *ch = &port->channels[i];
            if (ch->kind == TRANSPORT_ZMTP && (ubii__zmtp_events(port, ch) & POLLOUT)) {
                ubii__lws_want_writable(port, &ch->zmtp);
            }
        }
        ubii__lws_service(port, zmq_message_waiting(port) ? 0 : timeout_ms);
        drain_wake(port);
        return UBII_OK;
    }
    if (port->zmq_api.handle == NULL) {
        return poll_plain(port, timeout_ms);
    }
    zmq_pollitem_t items[2 * UBII_CHANNEL_COUNT + 1];
    int count = 0;
    for (int i = 0; i < UBII_CHANNEL_COUNT; ++i) {
        if (port->channels[i].kind == TRANSPORT_ZMQ) {
            count += ubii__zmq_poll_items(&port->channels[i], items + count);
        }
    }
    zmq_pollitem_t *wake = &items[count++];
    memset(wake, 0, sizeof *wake);
    wake->fd = port->wake_fd;
    wake->events = ZMQ_POLLIN;
    if (port->zmq_api.poll(items, count, timeout_ms) < 0 && port->zmq_api.errno_() != EINTR) {
        return UBII_ERR_TRANSPORT;
    }
    if (wake->revents & ZMQ_POLLIN) {
        drain_wake(port);
    }
    return UBII_OK;
}

static ubii_status wait_for_io(void *context, int timeout_ms)
{
    ubii_linux_port *port = context;
    /* The in-thread ZMTP connections write what was queued since the last wait before it, and do
     * the rest of their I/O after it. */
    for (int i = 0; i < UBII_CHANNEL_COUNT; ++i) {
        if (port->channels[i].kind == TRANSPORT_ZMTP) {
            ubii__zmtp_flush(port, (ubii_channel)i);
        }
    }
    ubii_status status = wait_for_any(port, timeout_ms);
    for (int i = 0; i < UBII_CHANNEL_COUNT; ++i) {
        if (port->channels[i].kind == TRANSPORT_ZMTP) {
            ubii__zmtp_service(port, (ubii_channel)i);
        }
    }
    return status;
}

static int poll_fds(void *context, ubii_pollfd *fds, int capacity)
{
    ubii_linux_port *port = context;
    int count = 0;
    for (int i = 0; i < UBII_CHANNEL_COUNT; ++i) {
        const channel *ch = &port->channels[i];
        if (ch->kind == TRANSPORT_ZMQ) {
            int room = capacity > count ? capacity - count : 0;
            count += ubii__zmq_fds(&port->channels[i], fds != NULL ? fds + count : NULL, room);
        }
        short events = ch->kind == TRANSPORT_ZMTP ? ubii__zmtp_events(port, ch) : 0;
        if (events != 0) {
            if (fds != NULL && count < capacity) {
                fds[count].fd = ch->zmtp.fd;
                fds[count].events = events;
            }
            count++;
        }
    }
    if (port->lws != NULL) {
        int room = capacity > count ? capacity - count : 0;
        count += ubii__lws_fds(port, fds != NULL ? fds + count : NULL, room);
    }
    if (fds != NULL && count < capacity) {
        fds[count].fd = port->wake_fd;
        fds[count].events = POLLIN;
    }
    return count + 1;
}

static uint64_t monotonic_ms(void *context)
{
    (void)context;
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    return (uint64_t)now.tv_sec * 1000u + (uint64_t)now.tv_nsec / 1000000u;
}

static int64_t epoch_ms(void *context)
{
    (void)context;
    struct timespec now;
    clock_gettime(CLOCK_REALTIME, &now);
    return (int64_t)now.tv_sec * 1000 + now.tv_nsec / 1000000;
}

static const ubii_port_vtable linux_vtable = {
    open_channel, close_channel, channel_state, send_begin,   send_commit,
    receive,      wait_for_io,   poll_fds,      monotonic_ms, epoch_ms,
};

ubii_status ubii_linux_port_create(ubii_linux_port **result, const ubii_linux_port_options *options)
{
    if (result == NULL) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    ubii_linux_port *port = calloc(1, sizeof *port);
    if (port == NULL) {
        return UBII_ERR_TRANSPORT;
    }
    if (options != NULL) {
        port->options = *options;
    }
    if (port->options.zmq_engine == UBII_LINUX_ZMQ_DEFAULT) {
        port->options.zmq_engine =
            port->options.zmq_only ? UBII_LINUX_ZMQ_LIBZMQ : UBII_LINUX_ZMQ_IN_THREAD;
    }
    if (port->options.zmq_engine != UBII_LINUX_ZMQ_LIBZMQ &&
        port->options.zmq_engine != UBII_LINUX_ZMQ_IN_THREAD) {
        free(port);
        return UBII_ERR_INVALID_ARGUMENT;
    }
    if (port->options.max_message_size == 0) {
        port->options.max_message_size = UBII_MAX_MESSAGE_SIZE;
    }
    port->wake_fd = eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
    if (port->wake_fd < 0) {
        free(port);
        return UBII_ERR_TRANSPORT;
    }
    if (port->options.zmq_engine == UBII_LINUX_ZMQ_LIBZMQ) {
        if (!ubii__zmq_library_load(&port->zmq_api, port->last_error, sizeof port->last_error)) {
            close(port->wake_fd);
            free(port);
            return UBII_ERR_UNSUPPORTED; /* libzmq is not installed */
        }
        port->zmq_context = port->zmq_api.ctx_new();
        if (port->zmq_context == NULL) {
            ubii__zmq_library_unload(&port->zmq_api);
            close(port->wake_fd);
            free(port);
            return UBII_ERR_TRANSPORT;
        }
    }
    /* TLS: OpenSSL's set-up and certificate store take tens of milliseconds, paid here rather
     * than in a poll, and a bad ca_file is reported here. Otherwise libwebsockets starts with the
     * first ws:// or http:// channel (a quarter of a millisecond), and never in a node that only
     * speaks tcp://. */
    if (port->options.enable_tls && !port->options.zmq_only && !ubii__lws_start(port)) {
        bool missing = port->lws_api.handle == NULL; /* libwebsockets is not installed */
        ubii_linux_port_destroy(port);
        return missing ? UBII_ERR_UNSUPPORTED : UBII_ERR_TRANSPORT;
    }
    *result = port;
    return UBII_OK;
}

ubii_port ubii_linux_port_get(ubii_linux_port *port)
{
    ubii_port handle = {&linux_vtable, port};
    return handle;
}

void ubii_linux_port_destroy(ubii_linux_port *port)
{
    if (port == NULL) {
        return;
    }
    for (int i = 0; i < UBII_CHANNEL_COUNT; ++i) {
        close_channel(port, (ubii_channel)i);
    }
    ubii__lws_destroy(port);
    if (port->zmq_context != NULL) {
        port->zmq_api.ctx_term(port->zmq_context);
    }
    ubii__zmq_library_unload(&port->zmq_api);
    close(port->wake_fd);
    free(port);
}

void ubii_linux_port_wake(ubii_linux_port *port)
{
    if (port == NULL) {
        return;
    }
    /* An eventfd write is async-signal- and thread-safe; a counter already non-zero stays so. */
    uint64_t one = 1;
    if (write(port->wake_fd, &one, sizeof one) < 0) {
        return; /* EAGAIN: the counter is saturated, so a wait ends anyway */
    }
}

const char *ubii_linux_port_last_error(const ubii_linux_port *port)
{
    return port != NULL ? port->last_error : "";
}

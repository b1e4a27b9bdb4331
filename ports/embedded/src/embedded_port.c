/* The embedded port's socket machinery: non-blocking TCP connections, one per channel, with their
 * bytes in the channel's fixed buffers; the protocol drivers frame and parse. Received messages
 * are lent to the core straight from the receive buffer. */
#define _DEFAULT_SOURCE /* getrandom, strncasecmp with glibc in strict C99 */

#include <arpa/inet.h>
#include <errno.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/random.h>
#include <sys/socket.h>
#include <time.h>
#include <unistd.h>

#include "embedded_internal.h"
#include "ubii/url.h"

void ubii__embedded_error(ubii_embedded_port *port, const char *what)
{
    snprintf(port->last_error, sizeof port->last_error, "%s", what);
}

bool ubii__embedded_queue(ubii__embedded_channel *ch, const void *bytes, size_t size)
{
    if (ch->tx_used + size > UBII_EMBEDDED_BUFFER) {
        return false;
    }
    memcpy(ch->tx + ch->tx_used, bytes, size);
    ch->tx_used += size;
    return true;
}

parse_result ubii__embedded_drop(ubii_embedded_port *port, ubii__embedded_channel *ch,
                                 size_t payload, uint64_t size, size_t *consumed)
{
    size_t here = ch->rx_used - payload;
    *consumed = here >= size ? payload + (size_t)size : ch->rx_used;
    ch->discard = here >= size ? 0 : size - here;
    ubii__embedded_error(port, "a message over UBII_EMBEDDED_MAX_MESSAGE was dropped");
    return PARSE_TOO_LARGE;
}

static const protocol_driver *driver_of(const ubii__embedded_channel *ch)
{
    switch (ch->protocol) {
    case PROTOCOL_ZMTP:
        return &ubii__zmtp_driver;
    case PROTOCOL_WEBSOCKET:
        return &ubii__websocket_driver;
    case PROTOCOL_HTTP:
        return &ubii__http_driver;
    default:
        return NULL;
    }
}

static bool shares_buffer(const ubii__embedded_channel *ch)
{
    return ch->rx == ch->tx;
}

/* A channel sharing one buffer reads only once its request is out: the peer answers after it. */
static bool wants_input(const ubii__embedded_channel *ch)
{
    return !shares_buffer(ch) || ch->tx_used == 0;
}

static short poll_events(const ubii__embedded_channel *ch)
{
    bool writing = ch->phase == PHASE_CONNECTING || ch->tx_sent < ch->tx_used;
    return (short)((wants_input(ch) ? POLLIN : 0) | (writing ? POLLOUT : 0));
}

/* The pointers are set again whenever a channel opens, so that they follow the port object even
 * if the application copied it between init and start. */
static void bind_buffers(ubii_embedded_port *port)
{
    ubii__embedded_channel *service = &port->channels[UBII_CHANNEL_SERVICE];
    ubii__embedded_channel *topic = &port->channels[UBII_CHANNEL_TOPIC];
    service->rx = service->tx = port->service_buffer;
    topic->rx = port->topic_rx;
    topic->tx = port->topic_tx;
}

static void reset_connection(ubii__embedded_channel *ch)
{
    if (ch->fd >= 0) {
        close(ch->fd);
    }
    ch->fd = -1;
    ch->phase = PHASE_IDLE;
    ch->step = 0;
    ch->rx_used = 0;
    ch->tx_used = 0;
    ch->tx_sent = 0;
    ch->lent = false;
    ch->header_room = 0;
    ch->discard = 0;
    ch->body_size = 0;
    ch->body_left = 0;
}

static void lose(ubii_embedded_port *port, ubii__embedded_channel *ch, const char *why)
{
    if (why != NULL) {
        ubii__embedded_error(port, why);
    }
    reset_connection(ch);
    ch->state = UBII_CHANNEL_LOST;
}

static ubii_status start_connect(ubii_embedded_port *port, ubii__embedded_channel *ch)
{
    ch->fd = socket(AF_INET, SOCK_STREAM, 0);
    if (ch->fd < 0) {
        ubii__embedded_error(port, "no socket");
        return UBII_ERR_TRANSPORT;
    }
    int one = 1;
    setsockopt(ch->fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    fcntl(ch->fd, F_SETFL, fcntl(ch->fd, F_GETFL) | O_NONBLOCK);
    struct sockaddr_in address;
    memset(&address, 0, sizeof address);
    address.sin_family = AF_INET;
    address.sin_port = htons(ch->port);
    address.sin_addr.s_addr = ch->address;
    if (connect(ch->fd, (struct sockaddr *)&address, sizeof address) != 0 && errno != EINPROGRESS) {
        lose(port, ch, "connection refused");
        return UBII_OK; /* reported through the channel state */
    }
    ch->phase = PHASE_CONNECTING;
    return UBII_OK;
}

/* The address, port and path of a parsed URL into the channel. Returns NULL, or what is wrong. */
static const char *take_endpoint(const ubii_url *url, ubii__embedded_channel *ch)
{
    char ip[16];
    if (url->host_length >= sizeof ip) {
        return "URL host must be an IPv4 address (the embedded port resolves no names)";
    }
    memcpy(ip, url->host, url->host_length);
    ip[url->host_length] = '\0';
    if (inet_pton(AF_INET, ip, &ch->address) != 1) {
        return "URL host must be an IPv4 address (the embedded port resolves no names)";
    }
    ch->port = url->port;
    const char *slash = url->path[0] == '/' ? "" : "/";
    if (strlen(slash) + strlen(url->path) >= sizeof ch->path) {
        return "URL path longer than UBII_EMBEDDED_MAX_PATH allows";
    }
    strcpy(ch->path, slash);
    strcat(ch->path, url->path);
    return NULL;
}

static void close_channel(void *context, ubii_channel which)
{
    ubii_embedded_port *port = context;
    if ((unsigned)which >= UBII_CHANNEL_COUNT) {
        return;
    }
    ubii__embedded_channel *ch = &port->channels[which];
    reset_connection(ch);
    ch->protocol = PROTOCOL_NONE;
    ch->state = UBII_CHANNEL_CLOSED;
}

static ubii_status open_channel(void *context, ubii_channel which, const char *url,
                                const char *client_id)
{
    ubii_embedded_port *port = context;
    if ((unsigned)which >= UBII_CHANNEL_COUNT || url == NULL) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    close_channel(port, which);
    bind_buffers(port);
    ubii__embedded_channel *ch = &port->channels[which];
    bool topic = which == UBII_CHANNEL_TOPIC;
    ubii_url parsed;
    if (ubii_url_parse(url, &parsed) != UBII_OK) {
        ubii__embedded_error(port, "URL must be scheme://IPv4[:port][/path]");
        return UBII_ERR_INVALID_ARGUMENT;
    }
    if (parsed.scheme == UBII_URL_TCP) {
        ch->protocol = PROTOCOL_ZMTP;
        ch->zmq_type = topic ? ZMQ_TYPE_DEALER : ZMQ_TYPE_REQ;
    } else if (parsed.scheme == UBII_URL_WS && topic) {
        ch->protocol = PROTOCOL_WEBSOCKET;
    } else if (parsed.scheme == UBII_URL_HTTP && !topic) {
        ch->protocol = PROTOCOL_HTTP;
    } else {
        ubii__embedded_error(port, "URL scheme not supported by the embedded port");
        return UBII_ERR_UNSUPPORTED;
    }
    const char *url_error = take_endpoint(&parsed, ch);
    if (url_error != NULL) {
        ch->protocol = PROTOCOL_NONE;
        ubii__embedded_error(port, url_error);
        return UBII_ERR_INVALID_ARGUMENT;
    }
    if (topic) {
        if (client_id == NULL || client_id[0] == '\0' || strlen(client_id) >= sizeof ch->identity) {
            ch->protocol = PROTOCOL_NONE;
            ubii__embedded_error(port, "client id missing or too long");
            return UBII_ERR_INVALID_ARGUMENT;
        }
        strcpy(ch->identity, client_id);
        if (ch->protocol == PROTOCOL_WEBSOCKET) {
            size_t used = strlen(ch->path);
            int written = snprintf(ch->path + used, sizeof ch->path - used, "%sclientID=%s",
                                   strchr(ch->path, '?') ? "&" : "?", client_id);
            if (written < 0 || (size_t)written >= sizeof ch->path - used) {
                ch->protocol = PROTOCOL_NONE;
                ubii__embedded_error(port, "URL path with ?clientID= longer than "
                                           "UBII_EMBEDDED_MAX_PATH allows");
                return UBII_ERR_INVALID_ARGUMENT;
            }
        }
    }
    if (ch->protocol == PROTOCOL_HTTP) {
        ch->state = UBII_CHANNEL_OPEN; /* each request makes its own connection */
        return UBII_OK;
    }
    ch->state = UBII_CHANNEL_CONNECTING;
    return start_connect(port, ch);
}

static void flush(ubii_embedded_port *port, ubii__embedded_channel *ch)
{
    while (ch->fd >= 0 && ch->phase != PHASE_CONNECTING && ch->tx_sent < ch->tx_used) {
        ssize_t sent = send(ch->fd, ch->tx + ch->tx_sent, ch->tx_used - ch->tx_sent, MSG_NOSIGNAL);
        if (sent < 0) {
            if (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR) {
                lose(port, ch, "send failed");
            }
            return;
        }
        ch->tx_sent += (size_t)sent;
    }
    if (ch->tx_sent == ch->tx_used && ch->header_room == 0) {
        ch->tx_used = ch->tx_sent = 0;
    }
}

static void drop_front(ubii__embedded_channel *ch, size_t consumed)
{
    memmove(ch->rx, ch->rx + consumed, ch->rx_used - consumed);
    ch->rx_used -= consumed;
}

/* Moves the handshake along; data messages are left for receive(). */
static void advance_handshake(ubii_embedded_port *port, ubii__embedded_channel *ch)
{
    const protocol_driver *driver = driver_of(ch);
    while (ch->fd >= 0 && ch->phase == PHASE_HANDSHAKE) {
        const uint8_t *data;
        size_t size, consumed = 0;
        unsigned flags;
        parse_result result = driver->parse(port, ch, &data, &size, &flags, &consumed);
        if (result == PARSE_ERROR) {
            lose(port, ch, NULL);
            return;
        }
        if (result != PARSE_SKIP) {
            return;
        }
        drop_front(ch, consumed);
    }
}

static void on_connected(ubii_embedded_port *port, ubii__embedded_channel *ch)
{
    int error = 0;
    socklen_t length = sizeof error;
    getsockopt(ch->fd, SOL_SOCKET, SO_ERROR, &error, &length);
    if (error != 0) {
        lose(port, ch, "connection refused");
        return;
    }
    ch->phase = ch->protocol == PROTOCOL_HTTP ? PHASE_OPEN : PHASE_HANDSHAKE;
    if (driver_of(ch)->on_connected(port, ch) != UBII_OK) {
        lose(port, ch, NULL);
    }
}

static void read_input(ubii_embedded_port *port, ubii__embedded_channel *ch)
{
    while (ch->fd >= 0 && wants_input(ch) && ch->rx_used < UBII_EMBEDDED_BUFFER) {
        size_t room = UBII_EMBEDDED_BUFFER - ch->rx_used;
        ssize_t got = recv(ch->fd, ch->rx + ch->rx_used, room, 0);
        if (got > 0) {
            size_t drop = ch->discard < (uint64_t)got ? (size_t)ch->discard : (size_t)got;
            if (drop > 0) { /* the rest of a dropped over-size message */
                memmove(ch->rx + ch->rx_used, ch->rx + ch->rx_used + drop, (size_t)got - drop);
                ch->discard -= drop;
            }
            ch->rx_used += (size_t)got - drop;
            /* A short read took all the socket had: asking again would only say EAGAIN. */
            ch->drained = (size_t)got < room;
            if (ch->drained) {
                return;
            }
            continue;
        }
        ch->drained = true;
        if (got == 0) {
            if (ch->protocol == PROTOCOL_HTTP) { /* the reply may end with the connection */
                close(ch->fd);
                ch->fd = -1;
                return;
            }
            lose(port, ch, "connection closed by the master");
        } else if (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR) {
            lose(port, ch, "receive failed");
        }
        return;
    }
}

/* Reads receive() may do between two waits once the buffered input is used up, so a node polled
 * once per frame takes in more than one buffer's worth per frame, yet a flood cannot keep it
 * inside one poll call. */
enum { REFILLS_PER_WAIT = 8 };

static ubii_status wait_for_io(void *context, int timeout_ms)
{
    ubii_embedded_port *port = context;
    struct pollfd fds[UBII_CHANNEL_COUNT];
    ubii__embedded_channel *owners[UBII_CHANNEL_COUNT];
    nfds_t count = 0;
    for (int i = 0; i < UBII_CHANNEL_COUNT; ++i) {
        ubii__embedded_channel *ch = &port->channels[i];
        ch->refills = REFILLS_PER_WAIT;
        flush(port, ch); /* what was queued since the last wait, in as few sends as it takes */
        if (ch->fd < 0) {
            continue;
        }
        fds[count].fd = ch->fd;
        fds[count].events = poll_events(ch);
        fds[count].revents = 0;
        owners[count++] = ch;
    }
    if (poll(count > 0 ? fds : NULL, count, timeout_ms) < 0 && errno != EINTR) {
        return UBII_ERR_TRANSPORT;
    }
    for (nfds_t i = 0; i < count; ++i) {
        ubii__embedded_channel *ch = owners[i];
        if (ch->phase == PHASE_CONNECTING && fds[i].revents != 0) {
            on_connected(port, ch);
        }
        if (fds[i].revents & (POLLIN | POLLHUP | POLLERR)) {
            read_input(port, ch);
        }
        flush(port, ch);
        advance_handshake(port, ch);
        flush(port, ch);
    }
    return UBII_OK;
}

static ubii_channel_state channel_state(void *context, ubii_channel which)
{
    ubii_embedded_port *port = context;
    return (unsigned)which < UBII_CHANNEL_COUNT ? port->channels[which].state : UBII_CHANNEL_CLOSED;
}

/* The core is done with the message it was lent. */
static void end_loan(ubii__embedded_channel *ch)
{
    if (!ch->lent) {
        return;
    }
    memmove(ch->rx, ch->rx + ch->lent_size, ch->rx_used - ch->lent_size);
    ch->rx_used -= ch->lent_size;
    ch->lent = false;
    if (ch->protocol == PROTOCOL_HTTP) {
        reset_connection(ch); /* one request per connection */
    }
}

/* A REQ peer sends nothing between replies but ZMTP commands; anything else left in a shared
 * buffer is dropped and counted before a request takes the buffer. False while something is only
 * partly there. */
static bool clear_input(ubii_embedded_port *port, ubii__embedded_channel *ch)
{
    if (ch->protocol == PROTOCOL_HTTP) {
        ch->rx_used = 0; /* from a connection that is over: each request has its own */
        return true;
    }
    const protocol_driver *driver = driver_of(ch);
    while (ch->rx_used > 0) {
        const uint8_t *data;
        size_t size, consumed = 0;
        unsigned flags;
        parse_result result = driver->parse(port, ch, &data, &size, &flags, &consumed);
        if (result == PARSE_NEED_MORE) {
            return false;
        }
        if (result == PARSE_ERROR) {
            port->decode_errors++;
            lose(port, ch, NULL);
            return false;
        }
        if (result != PARSE_SKIP) {
            port->decode_errors++; /* a message nobody asked for */
        }
        drop_front(ch, consumed);
    }
    return true;
}

static ubii_status send_begin(void *context, ubii_channel which, size_t size, uint8_t **buffer)
{
    ubii_embedded_port *port = context;
    if ((unsigned)which >= UBII_CHANNEL_COUNT || buffer == NULL) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    ubii__embedded_channel *ch = &port->channels[which];
    if (ch->state != UBII_CHANNEL_OPEN && ch->state != UBII_CHANNEL_CONNECTING) {
        return UBII_ERR_NOT_CONNECTED;
    }
    size_t header = driver_of(ch)->header_size(ch, size);
    if (size > UBII_EMBEDDED_MAX_MESSAGE || header + size > UBII_EMBEDDED_BUFFER) {
        return UBII_ERR_TOO_LARGE;
    }
    if (shares_buffer(ch)) {
        /* The next request: the previous reply has been delivered (port.h). */
        end_loan(ch);
    }
    if (ch->protocol == PROTOCOL_HTTP && ch->fd >= 0) {
        return UBII_ERR_WOULD_BLOCK; /* one request at a time */
    }
    if (ch->protocol != PROTOCOL_HTTP && ch->phase != PHASE_OPEN) {
        return UBII_ERR_WOULD_BLOCK; /* the handshake goes first; the core tries again */
    }
    if (shares_buffer(ch) && !clear_input(port, ch)) {
        return UBII_ERR_WOULD_BLOCK;
    }
    if (ch->tx_used + header + size > UBII_EMBEDDED_BUFFER) {
        flush(port, ch);
        if (ch->tx_used + header + size > UBII_EMBEDDED_BUFFER) {
            return UBII_ERR_WOULD_BLOCK;
        }
    }
    ch->header_room = header;
    ch->reserved_at = ch->tx_used + header;
    ch->reserved = size;
    *buffer = ch->tx + ch->reserved_at;
    return UBII_OK;
}

static ubii_status send_commit(void *context, ubii_channel which, unsigned flags)
{
    ubii_embedded_port *port = context;
    if ((unsigned)which >= UBII_CHANNEL_COUNT) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    ubii__embedded_channel *ch = &port->channels[which];
    if (ch->header_room == 0) {
        return UBII_ERR_STATE;
    }
    driver_of(ch)->frame(port, ch, ch->reserved_at, ch->reserved, flags);
    ch->tx_used = ch->reserved_at + ch->reserved;
    ch->header_room = 0;
    if (ch->protocol == PROTOCOL_HTTP) {
        return start_connect(port, ch);
    }
    /* Not sent yet: messages committed before the next wait go out together, which saves the
     * kernel a send (and the master a wake-up) per message. */
    return UBII_OK;
}

static ubii_status receive(void *context, ubii_channel which, const uint8_t **data, size_t *size,
                           unsigned *flags)
{
    ubii_embedded_port *port = context;
    if ((unsigned)which >= UBII_CHANNEL_COUNT || data == NULL || size == NULL || flags == NULL) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    ubii__embedded_channel *ch = &port->channels[which];
    end_loan(ch);
    if (ch->phase != PHASE_OPEN || ch->protocol == PROTOCOL_NONE) {
        return UBII_ERR_WOULD_BLOCK;
    }
    const protocol_driver *driver = driver_of(ch);
    for (;;) {
        size_t consumed = 0;
        parse_result result = driver->parse(port, ch, data, size, flags, &consumed);
        if (result == PARSE_SKIP) {
            drop_front(ch, consumed);
            flush(port, ch); /* a WebSocket PONG may have been queued */
            continue;
        }
        if (result == PARSE_MESSAGE) {
            ch->lent = true;
            ch->lent_size = consumed;
            return UBII_OK;
        }
        if (result == PARSE_TOO_LARGE) {
            drop_front(ch, consumed);
            port->decode_errors++;
            if (ch->protocol == PROTOCOL_HTTP) {
                reset_connection(ch);
            }
            return UBII_ERR_TOO_LARGE;
        }
        if (result == PARSE_NEED_MORE && ch->protocol != PROTOCOL_HTTP && ch->refills > 0 &&
            !ch->drained) {
            size_t buffered = ch->rx_used;
            ch->refills--;
            read_input(port, ch);
            if (ch->fd >= 0 && ch->rx_used > buffered) {
                continue;
            }
        }
        if (result == PARSE_ERROR) {
            port->decode_errors++;
            lose(port, ch, NULL);
        } else if (ch->protocol == PROTOCOL_HTTP && ch->fd < 0) {
            lose(port, ch, "HTTP connection ended before the reply");
        }
        return UBII_ERR_WOULD_BLOCK;
    }
}

static int poll_fds(void *context, ubii_pollfd *fds, int capacity)
{
    ubii_embedded_port *port = context;
    int count = 0;
    for (int i = 0; i < UBII_CHANNEL_COUNT; ++i) {
        const ubii__embedded_channel *ch = &port->channels[i];
        if (ch->fd < 0) {
            continue;
        }
        if (count < capacity) {
            fds[count].fd = ch->fd;
            fds[count].events = poll_events(ch);
        }
        count++;
    }
    return count;
}

static uint64_t monotonic_ms(void *context)
{
    ubii_embedded_port *port = context;
    return port->platform.monotonic_ms(port->platform.user);
}

static int64_t epoch_ms(void *context)
{
    ubii_embedded_port *port = context;
    return port->platform.epoch_ms(port->platform.user);
}

static const ubii_port_vtable embedded_vtable = {
    open_channel, close_channel, channel_state, send_begin,   send_commit,
    receive,      wait_for_io,   poll_fds,      monotonic_ms, epoch_ms,
};

ubii_status ubii_embedded_port_init(ubii_embedded_port *port, ubii_embedded_platform platform)
{
    if (port == NULL || platform.monotonic_ms == NULL || platform.epoch_ms == NULL ||
        platform.random_bytes == NULL) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    memset(port, 0, sizeof *port);
    port->platform = platform;
    bind_buffers(port);
    for (int i = 0; i < UBII_CHANNEL_COUNT; ++i) {
        port->channels[i].fd = -1;
    }
    return UBII_OK;
}

ubii_port ubii_embedded_port_get(ubii_embedded_port *port)
{
    ubii_port handle = {&embedded_vtable, port};
    return handle;
}

void ubii_embedded_port_close(ubii_embedded_port *port)
{
    if (port != NULL) {
        for (int i = 0; i < UBII_CHANNEL_COUNT; ++i) {
            close_channel(port, (ubii_channel)i);
        }
    }
}

const char *ubii_embedded_port_last_error(const ubii_embedded_port *port)
{
    return port != NULL ? port->last_error : "";
}

/* ---- POSIX platform hooks
 * ------------------------------------------------------------------------ */

static uint64_t posix_monotonic_ms(void *user)
{
    (void)user;
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    return (uint64_t)now.tv_sec * 1000u + (uint64_t)now.tv_nsec / 1000000u;
}

static int64_t posix_epoch_ms(void *user)
{
    (void)user;
    struct timespec now;
    clock_gettime(CLOCK_REALTIME, &now);
    return (int64_t)now.tv_sec * 1000 + now.tv_nsec / 1000000;
}

static void posix_random_bytes(void *user, uint8_t *bytes, size_t count)
{
    (void)user;
    while (count > 0) {
        ssize_t got = getrandom(bytes, count, 0);
        if (got <= 0) {
            return;
        }
        bytes += got;
        count -= (size_t)got;
    }
}

ubii_embedded_platform ubii_embedded_posix_platform(void)
{
    ubii_embedded_platform platform = {posix_monotonic_ms, posix_epoch_ms, posix_random_bytes,
                                       NULL};
    return platform;
}

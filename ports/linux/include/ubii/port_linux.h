#ifndef UBII_PORT_LINUX_H
#define UBII_PORT_LINUX_H

/* The Linux port: ZeroMQ (tcp://) for services and topic data, libwebsockets for WebSocket topic
 * data (ws://, wss://) and binary HTTP services (http://, https://). Unlike the core, this port
 * allocates. libwebsockets and libzmq are loaded at run time, each by the first port that uses it
 * (a node that speaks only tcp:// in its own thread maps neither); where one is not installed,
 * what needs it gives UBII_ERR_UNSUPPORTED and ubii_linux_port_last_error says so. The port starts
 * no thread, unless tcp:// is spoken through libzmq (UBII_LINUX_ZMQ_LIBZMQ, or zmq_only), whose
 * threads then run. Host names in URLs that libzmq does not connect are resolved synchronously
 * when a connection starts; where a frame must never stall, give an IP address.
 *
 *     ubii_linux_port *linux_port;
 *     ubii_linux_port_create(&linux_port, NULL);
 *     ubii_node_init(&node, sizeof node, &config, ubii_linux_port_get(linux_port));
 *     ...
 *     ubii_linux_port_destroy(linux_port);   // after the node is stopped
 */

#include <stdbool.h>
#include <stddef.h>

#include "ubii/export.h"
#include "ubii/port.h"
#include "ubii/status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct ubii_linux_port ubii_linux_port;

/* How tcp:// URLs (ZMQ) are spoken. */
typedef enum ubii_linux_zmq_engine {
    /* UBII_LINUX_ZMQ_IN_THREAD, or UBII_LINUX_ZMQ_LIBZMQ with zmq_only. */
    UBII_LINUX_ZMQ_DEFAULT = 0,
    /* libzmq: a REQ and a DEALER socket, integrated through ZMQ_FD/ZMQ_EVENTS. libzmq's I/O
     * thread wakes for every message that arrives, whether or not the node is being polled: the
     * choice where the polling thread is busy for long stretches and messages should keep coming
     * in meanwhile (examples/cpp/ocr_node keeps only the newest frame). */
    UBII_LINUX_ZMQ_LIBZMQ = 1,
    /* ZMTP 3 written by libubii over a plain socket, in the thread that polls the node: no extra
     * thread, no libwebsockets, and a node polled once per frame takes the frame's messages in a
     * few reads and sends its own in one write (bench/run.sh at 60 Hz: 0.5 against libzmq's 8.9 µs
     * of CPU per message). The master sees the same REQ and DEALER peers. */
    UBII_LINUX_ZMQ_IN_THREAD = 2
} ubii_linux_zmq_engine;

typedef struct ubii_linux_port_options {
    /* Largest message accepted from the master; a larger one drops the connection. 0: the core's
     * UBII_MAX_MESSAGE_SIZE (16 MiB), which also bounds what the node sends. */
    size_t max_message_size;
    /* TLS (wss://, https://) needs this set; without it such URLs give UBII_ERR_UNSUPPORTED. It
     * makes port creation load OpenSSL's certificate store (about 40 ms). libwebsockets 4.1 sets
     * OpenSSL up process-wide: keep to one TLS port per process (a second one, destroyed while
     * the first lives, leaks OpenSSL's store; LeakSanitizer shows it). */
    bool enable_tls;
    /* TLS: accept self-signed certificates, e.g. a master's own. */
    bool allow_self_signed;
    /* If not 0, passed to lws_set_log_level() (process-wide) before libwebsockets starts, e.g.
     * LLL_ERR (1) to keep its notices off stderr. */
    int libwebsockets_log_level;
    /* Only tcp:// (ZMQ) URLs: libwebsockets is never started, ws:// and http:// give
     * UBII_ERR_UNSUPPORTED. Otherwise libwebsockets starts with the first ws:// or http:// channel
     * (a quarter of a millisecond), or in ubii_linux_port_create with enable_tls, so that no
     * ubii_node_poll() pays for OpenSSL's set-up. */
    bool zmq_only;
    ubii_linux_zmq_engine zmq_engine;
    /* TLS: a PEM file of the certificates to trust (a CA's, or a master's self-signed one) instead
     * of the system's store. The master's certificate must then chain to one of them and name the
     * URL's host (its subject's CN or a subjectAltName); allow_self_signed skips both checks. */
    const char *ca_file;
} ubii_linux_port_options;

/* Ends the port's current or next wait at once: the one call that may come from any thread (or a
 * signal handler) while another polls the node, e.g. a worker thread whose result is ready. The
 * wake-up is an eventfd among the port's pollfds, so an external loop wakes too. */
UBII_API void ubii_linux_port_wake(ubii_linux_port *port);

/* A short English description of the port's last transport failure ("" if none yet); it stays
 * until the next failure replaces it. */
UBII_API const char *ubii_linux_port_last_error(const ubii_linux_port *port);

/* Creates a port; `options` may be NULL for the defaults. UBII_ERR_UNSUPPORTED for the libzmq
 * engine without libzmq installed, or enable_tls without libwebsockets; UBII_ERR_TRANSPORT if
 * libzmq or libwebsockets fail to start (e.g. an unreadable ca_file); ubii_linux_port_last_error
 * is unavailable then: nothing is returned. */
UBII_API ubii_status ubii_linux_port_create(ubii_linux_port **port,
                                            const ubii_linux_port_options *options);
/* The port as a node runs on it; valid until ubii_linux_port_destroy. */
UBII_API ubii_port ubii_linux_port_get(ubii_linux_port *port);
/* Closes everything. The node using the port must not be polled afterwards. */
UBII_API void ubii_linux_port_destroy(ubii_linux_port *port);

#ifdef __cplusplus
}
#endif

#endif

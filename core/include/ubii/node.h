#ifndef UBII_NODE_H
#define UBII_NODE_H

/* A Ubi-Interact client node: connects to a master, registers, keeps the topic connection alive
 * (PING/PONG), reconnects when the master goes away, and carries service calls, subscriptions and
 * publications (service.h, topic.h).
 *
 * Single-threaded and poll-driven: nothing happens, and no callback runs, except inside
 * ubii_node_poll() (and ubii_node_stop_wait(), which polls). The node allocates nothing; the
 * application owns the ubii_node (static, stack or heap) and the port it runs on.
 *
 *     ubii_config config;
 *     ubii_config_init(&config);
 *     config.service_url = "tcp://127.0.0.1:8101";
 *     config.topic_url = "tcp://127.0.0.1:8103";
 *     static ubii_node node;
 *     ubii_node_init(&node, sizeof node, &config, port);
 *     ubii_node_start(&node);
 *     while (running) ubii_node_poll(&node, 16);   // or 0 from a game engine's frame tick
 *     ubii_node_stop_wait(&node, 2000);
 */

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "ubii/export.h"
#include "ubii/port.h"
#include "ubii/status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct ubii_node ubii_node;

typedef enum ubii_state {
    UBII_STATE_STOPPED = 0,      /* initialised or stopped; nothing open */
    UBII_STATE_CONNECTING = 1,   /* asking the master for its server configuration */
    UBII_STATE_REGISTERING = 2,  /* registering this client */
    UBII_STATE_OPENING = 3,      /* registered; opening the topic connection */
    UBII_STATE_READY = 4,        /* registered and connected: topics and services work */
    UBII_STATE_RECONNECTING = 5, /* connection failed; deregistering if the master still
                                    answers, then waiting to start over (backoff) */
    UBII_STATE_STOPPING = 6,     /* deregistering and closing */
    UBII_STATE_FAILED = 7        /* gave up (see ubii_config.max_reconnect_attempts) */
} ubii_state;

/* Called (inside poll) on every state change; `reason` says why for RECONNECTING and FAILED. */
typedef void (*ubii_state_fn)(ubii_node *node, ubii_state previous, ubii_state current,
                              ubii_status reason, void *user);

/* Called (inside poll) for trouble that belongs to no call of the application: an error reply to
 * the node's own requests (e.g. a subscription), a TopicData.error from the master, a message
 * that could not be decoded or was too large. `detail` is a short NUL-terminated text. */
typedef void (*ubii_error_fn)(ubii_node *node, ubii_status status, const char *detail, void *user);

typedef struct ubii_config {
    /* Service endpoint: "tcp://HOST:8101" (ZMQ) or "http(s)://HOST:8102/services/binary". */
    const char *service_url;
    /* Topic data endpoint: "tcp://HOST:8103" (ZMQ) or "ws(s)://HOST:8104". NULL: ZMQ on the
     * service URL's host at the port the master reports in its server configuration. */
    const char *topic_url;
    const char *client_name;           /* default "libubii" */
    bool is_dedicated_processing_node; /* default false */
    uint32_t service_timeout_ms;       /* default timeout of a service call: 5000 */
    /* After the master's first PING, this long without another counts as a lost master: 5000.
     * (The npm 0.4.0 master never pings; lost connections are then seen by the transport.)
     * 0 turns the check off. */
    uint32_t ping_timeout_ms;
    uint32_t reconnect_min_ms;       /* first wait before reconnecting: 250 */
    uint32_t reconnect_max_ms;       /* the wait doubles up to this: 8000 */
    uint32_t max_reconnect_attempts; /* 0: never give up; else FAILED after this many in a row */
    bool stamp_records; /* put Timestamp.millis (epoch ms) on published records: true */
    ubii_state_fn on_state;
    void *on_state_user;
    ubii_error_fn on_error;
    void *on_error_user;
} ubii_config;

/* Counters for monitoring; they only grow. */
typedef struct ubii_stats {
    uint64_t records_received;   /* records dispatched to subscriptions */
    uint64_t records_published;  /* records handed to the transport */
    uint64_t duplicates_dropped; /* copies the master sends for overlapping subscriptions */
    uint64_t pings;              /* PINGs answered */
    uint64_t decode_errors;      /* messages from the master that were not valid protobuf */
    uint64_t master_errors;      /* TopicData.error and error replies to the node's own requests */
    uint64_t service_timeouts;
    uint64_t reconnects;
    uint64_t records_skipped; /* records of a type this build's schema leaves out (ubii/topic.h) */
} ubii_stats;

/* sizeof(ubii_node) as this library was built, for callers that cannot evaluate sizeof (e.g. a
 * C# binding allocating unmanaged memory); pass it as ubii_node_init's node_size. */
UBII_API size_t ubii_node_size(void);

/* Fills `config` with the defaults above (URLs NULL). */
UBII_API void ubii_config_init(ubii_config *config);

/* Prepares `node` to run on `port`. `node_size` must be sizeof(ubii_node) as the caller sees it
 * (catches a mismatch of UBII_* limits between the library and the caller:
 * UBII_ERR_INVALID_ARGUMENT). Strings in `config` are copied; `config` need not outlive the call.
 * Does no I/O. */
UBII_API ubii_status ubii_node_init(ubii_node *node, size_t node_size, const ubii_config *config,
                                    ubii_port port);

/* Begins connecting (STOPPED or FAILED -> CONNECTING). Non-blocking: poll() does the work.
 * UBII_ERR_UNSUPPORTED if the port cannot handle a URL's scheme. */
UBII_API ubii_status ubii_node_start(ubii_node *node);

/* Does all due I/O, timers and callbacks, waiting at most timeout_ms for something to happen
 * (0: never waits, for a game engine's frame tick). UBII_ERR_STATE if called from a callback. */
UBII_API ubii_status ubii_node_poll(ubii_node *node, int timeout_ms);

/* Begins stopping: pending calls are cancelled, the client deregistered (bounded by the service
 * timeout), connections closed. Non-blocking; the state reaches STOPPED inside poll(). */
UBII_API ubii_status ubii_node_stop(ubii_node *node);

/* ubii_node_stop(), then polls until STOPPED or timeout_ms have passed (then closes at once).
 * Callbacks may run inside it, as inside poll(). */
UBII_API ubii_status ubii_node_stop_wait(ubii_node *node, int timeout_ms);

UBII_API ubii_state ubii_node_state(const ubii_node *node);
UBII_API const char *ubii_state_name(ubii_state state);

/* The id the master gave this client ("" until registered). Valid until the next state change. */
UBII_API const char *ubii_node_client_id(const ubii_node *node);

UBII_API void ubii_node_stats(const ubii_node *node, ubii_stats *stats);

/* For an external event loop: the fds to watch (returns how many; may exceed capacity), and the
 * longest it may wait before calling ubii_node_poll(node, 0) again (-1: no deadline). */
UBII_API int ubii_node_pollfds(ubii_node *node, ubii_pollfd *fds, int capacity);
UBII_API int ubii_node_next_timeout_ms(ubii_node *node);

/* Milliseconds on the monotonic clock the node's timeouts run on (its port's), so that code
 * scheduling beside the node agrees with it. 0 for NULL. */
UBII_API uint64_t ubii_node_monotonic_ms(const ubii_node *node);

#ifdef __cplusplus
}
#endif

#include "ubii/node_storage.h"

#endif

#ifndef UBII_NODE_STORAGE_H
#define UBII_NODE_STORAGE_H

/* The layout of ubii_node. It is public only so that an application can allocate a node where it
 * likes (static storage, stack, inside its own structs) without libubii allocating; its members are
 * not an API and change between versions. Sizes follow config.h. */

#include "ubii/config.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef void (*ubii__callback)(void);

typedef struct ubii__subscription {
    char pattern[UBII_MAX_TOPIC_SIZE];
    ubii__callback fn;
    void *user;
    uint32_t generation;
    uint8_t kind;      /* ubii__subscription_kind */
    uint8_t active;    /* a local subscriber holds it */
    uint8_t at_master; /* the master has (or is being asked for) this pattern */
    uint8_t in_flight; /* part of the outstanding subscription request */
} ubii__subscription;

typedef struct ubii__call {
    uint32_t offset; /* of the encoded request in the queue's bytes */
    uint32_t size;
    uint32_t timeout_ms;
    ubii__callback fn;
    void *user;
    uint8_t node_step; /* one of the node's own protocol steps: dropped, not answered, on cancel */
} ubii__call;

struct ubii_node {
    size_t struct_size;
    ubii_port port;
    ubii_config config; /* string members point into the copies below */
    char service_url[UBII_MAX_URL_SIZE];
    char topic_url[UBII_MAX_URL_SIZE];
    char client_name[UBII_MAX_NAME_SIZE];
    char client_id[UBII_MAX_CLIENT_ID_SIZE];
    /* Fields of the registration's Client that an optional part of the API adds (a
     * ubii_clients_Client *, which this header does not know): ubii/processing.h. */
    void (*complete_registration)(struct ubii_node *node, void *client);
    const void *offered_modules; /* const ubii_encoded_message * */
    size_t offered_module_count;

    ubii_state state;
    /* State changes made outside poll() (by start) are announced at the next poll(). */
    struct {
        ubii_state previous, current;
        ubii_status reason;
    } deferred_states[4];
    uint32_t deferred_state_count;
    bool in_poll;
    bool stop_requested;
    /* Deregistering after the topic data connection failed, before a retry (or FAILED). */
    bool leaving;
    uint32_t reconnect_attempts;
    uint64_t retry_at_ms;
    uint64_t stop_deadline_ms;
    bool ping_seen;
    uint64_t last_ping_ms;
    uint64_t open_deadline_ms; /* OPENING: the topic connection must be up by then */

    /* Service calls: calls[0] is outstanding once sent. */
    ubii__call calls[UBII_SERVICE_QUEUE_DEPTH];
    uint32_t call_count;
    bool call_sent;
    uint64_t call_deadline_ms;
    uint8_t queue_bytes[UBII_SERVICE_QUEUE_BYTES];
    uint32_t queue_used;

    ubii__subscription subscriptions[UBII_MAX_SUBSCRIPTIONS];
    uint32_t next_generation;
    bool subscriptions_dirty;
    bool subscription_call_pending;

    /* Duplicate suppression for records that match several of this node's patterns. */
    uint64_t last_record_hash;
    uint32_t duplicate_run;

    char record_topic[UBII_MAX_TOPIC_SIZE];
    char record_client_id[UBII_MAX_CLIENT_ID_SIZE];
    ubii_stats stats;
};

#ifdef __cplusplus
}
#endif

#endif

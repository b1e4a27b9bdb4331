#ifndef UBII_NODE_INTERNAL_H
#define UBII_NODE_INTERNAL_H

/* Shared between the core's source files; not installed. */

#include <pb_encode.h>

#include "ubii/node.h"
#include "ubii/service.h"
#include "ubii/topic.h"

enum ubii__subscription_kind { UBII__FREE = 0, UBII__EXACT = 1, UBII__REGEX = 2 };

/* Why a queued call exists: the application's, or one of the node's own protocol steps. */
enum ubii__purpose {
    UBII__CALL_APPLICATION = 0,
    UBII__CALL_SERVER_CONFIGURATION,
    UBII__CALL_REGISTRATION,
    UBII__CALL_SUBSCRIPTION,
    UBII__CALL_RELEASE, /* every subscription dropped before deregistering */
    UBII__CALL_DEREGISTRATION
};

#define UBII__PING "PING"
#define UBII__PONG "PONG"
#define UBII__KEEPALIVE_SIZE 4u

uint64_t ubii__now(ubii_node *node);
void ubii__set_state(ubii_node *node, ubii_state state, ubii_status reason);
void ubii__report(ubii_node *node, ubii_status status, const char *detail);
/* Gives up on the current connection: close everything, then reconnect after a backoff. */
void ubii__connection_lost(ubii_node *node, ubii_status reason);

/* service_queue.c */
ubii_status ubii__enqueue(ubii_node *node, const ubii_services_ServiceRequest *request,
                          uint32_t timeout_ms, uint8_t purpose, ubii__callback fn, void *user);
void ubii__service_step(ubii_node *node);
/* Fails every queued call with `status` (application callbacks see it; node steps are dropped). */
void ubii__cancel_calls(ubii_node *node, ubii_status status);
/* Handles the reply to one of the node's own steps (node.c, subscriptions.c). */
void ubii__on_step_reply(ubii_node *node, uint8_t purpose, const ubii_reply *reply);
void ubii__parse_reply(const uint8_t *bytes, size_t size, ubii_reply *reply,
                       ubii_general_Error *error_storage);

/* subscriptions.c */
void ubii__subscriptions_reset_master(ubii_node *node);
void ubii__subscriptions_sync(ubii_node *node);
void ubii__subscriptions_on_reply(ubii_node *node, const ubii_reply *reply);
/* Queues the request that drops every subscription the master holds (or was asked for) for this
 * node; UBII_OK without a request when it holds none. */
ubii_status ubii__subscriptions_enqueue_release(ubii_node *node);
void ubii__dispatch_record(ubii_node *node, const ubii_record *record, const uint8_t *message,
                           size_t size);

/* record.c */
/* Parses TopicData bytes; calls ubii__dispatch_record for each record it holds. */
void ubii__handle_topic_data(ubii_node *node, const uint8_t *bytes, size_t size);

/* Whether `number` is a TopicDataRecord value member of this build's schema (the generated
 * UBII_RECORD_TYPE_LIST), and the wire type every value member arrives with. */
bool ubii__record_type_known(uint32_t number);
int ubii__record_wire_type(uint32_t number);

/* publish.c */
/* Writes a record's value member, tag included. */
typedef bool (*ubii__value_writer)(pb_ostream_t *stream, uint32_t member, const void *value);
/* Writes the body of a message-typed member (without tag and length). */
typedef bool (*ubii__body_writer)(pb_ostream_t *stream, const void *body);
/* Sends one TopicData{record{topic, [timestamp], value}}. */
ubii_status ubii__publish(ubii_node *node, const char *topic, uint32_t member,
                          ubii__value_writer write, const void *value);
/* The same with a message-typed member whose body `write_body` writes (called twice: sizing, then
 * writing). */
ubii_status ubii__publish_body(ubii_node *node, const char *topic, uint32_t member,
                               ubii__body_writer write_body, const void *body);

/* regex.c: UBII_OK match, UBII_ERR_NOT_FOUND no match, or why it cannot run. */
ubii_status ubii__regex_search(const char *pattern, const char *text, uint32_t step_limit);
/* Checks that the pattern is within the supported dialect (without matching anything). */
ubii_status ubii__regex_validate(const char *pattern);

/* strings */
bool ubii__copy_string(char *destination, size_t capacity, const char *source);

#endif

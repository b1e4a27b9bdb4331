#ifndef UBII_SERVICE_H
#define UBII_SERVICE_H

/* Service calls: a ServiceRequest goes to the master, exactly one reply (or a timeout, or a
 * cancellation) comes back through the callback, inside ubii_node_poll(). Calls are queued and sent
 * one at a time, as the master's REQ/REP channel demands. Requests are encoded when queued, so the
 * caller's request struct need not outlive the call. */

#include <stddef.h>
#include <stdint.h>

#include "ubii/export.h"
#include "ubii/node.h"
#include "ubii/status.h"
#include "ubii/services/serviceReply.pb.h"
#include "ubii/services/serviceRequest.pb.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Service topics the master registers (docs/PROTOCOL.md §2.11). */
#define UBII_SERVICE_SERVER_CONFIGURATION "/services/server_configuration"
#define UBII_SERVICE_SERVICE_LIST "/services/service_list"
#define UBII_SERVICE_TOPIC_LIST "/services/topic_list"
#define UBII_SERVICE_TOPIC_SUBSCRIPTION "/services/topic_subscription"
#define UBII_SERVICE_CLIENT_REGISTRATION "/services/client/registration"
#define UBII_SERVICE_CLIENT_DEREGISTRATION "/services/client/deregistration"
#define UBII_SERVICE_CLIENT_LIST "/services/client/get_list"
#define UBII_SERVICE_DEVICE_REGISTRATION "/services/device/registration"
#define UBII_SERVICE_DEVICE_DEREGISTRATION "/services/device/deregistration"
#define UBII_SERVICE_DEVICE_LIST "/services/device/get_list"
#define UBII_SERVICE_COMPONENT_LIST "/services/component/get_list"

typedef struct ubii_reply {
    /* UBII_OK; UBII_ERR_BROKER (error_title/error_message say why); UBII_ERR_TIMEOUT;
     * UBII_ERR_CANCELLED (the node stopped or reconnected); UBII_ERR_DECODE. */
    ubii_status status;
    /* Which ServiceReply member arrived (ubii_services_ServiceReply_X_tag), 0 if none. */
    uint32_t member;
    /* The member's encoded bytes; valid only during the callback. */
    const uint8_t *bytes;
    size_t size;
    const char *error_title; /* never NULL; "" unless status is UBII_ERR_BROKER */
    const char *error_message;
} ubii_reply;

typedef void (*ubii_reply_fn)(ubii_node *node, const ubii_reply *reply, void *user);

/* Queues `request`. timeout_ms 0 means the node's service_timeout_ms. `fn` may be NULL.
 * UBII_ERR_NOT_CONNECTED unless READY; UBII_ERR_FULL when the queue is full;
 * UBII_ERR_TOO_LARGE if the encoded request exceeds UBII_SERVICE_QUEUE_BYTES. */
UBII_API ubii_status ubii_call(ubii_node *node, const ubii_services_ServiceRequest *request,
                               uint32_t timeout_ms, ubii_reply_fn fn, void *user);

/* A request that carries only a topic, e.g. UBII_SERVICE_TOPIC_LIST. */
UBII_API ubii_status ubii_call_topic(ubii_node *node, const char *topic, uint32_t timeout_ms,
                                     ubii_reply_fn fn, void *user);

/* The same with a ServiceRequest that is already encoded (by another protobuf runtime, e.g. a
 * language binding's): `request` holds its `size` bytes, copied into the queue at once. It must be
 * valid protobuf with a non-empty topic (else UBII_ERR_INVALID_ARGUMENT); the rest is not checked.
 */
UBII_API ubii_status ubii_call_encoded(ubii_node *node, const uint8_t *request, size_t size,
                                       uint32_t timeout_ms, ubii_reply_fn fn, void *user);

/* Device registration: ubii/devices.h (full schema only). */

/* Decodes the reply's member into `message` if it is `expected_member`: UBII_ERR_WRONG_TYPE if
 * another member arrived, the reply's own status if it failed. Callback fields of `message` that
 * the caller bound are called as usual. */
UBII_API ubii_status ubii_reply_decode(const ubii_reply *reply, uint32_t expected_member,
                                       const pb_msgdesc_t *fields, void *message);

/* The occurrences of a repeated message field of the reply's member: with `repeated_field` 1, the
 * elements of a list reply (UBII_SERVICE_SERVICE_LIST's ServiceList, UBII_SERVICE_CLIENT_LIST's
 * ClientList: every list message of the schema repeats its field 1); with
 * ubii_devices_Device_components_tag, a registered device's components. Each is decoded into
 * `element`, a struct of type `fields`, and handed to `fn`, which returns false to stop. pb_decode
 * resets the element's plain fields before each one but keeps its callback fields as they are:
 * initialise `element` first (e.g. `ubii_devices_Component c = ubii_devices_Component_init_zero`),
 * or its callbacks are garbage that decoding calls. Returns the reply's own status if it failed, UBII_ERR_WRONG_TYPE for
 * another member than `expected_member`, UBII_ERR_DECODE for malformed bytes (the occurrences
 * before them were handed on), else UBII_OK. No allocation. */
typedef bool (*ubii_element_fn)(const void *element, void *user);
UBII_API ubii_status ubii_reply_for_each(const ubii_reply *reply, uint32_t expected_member,
                                         uint32_t repeated_field, const pb_msgdesc_t *fields,
                                         void *element, ubii_element_fn fn, void *user);

/* The same for a list reply of strings (UBII_SERVICE_TOPIC_LIST's StringList): each is handed on
 * as bytes and a length, not NUL-terminated. */
typedef bool (*ubii_text_fn)(const char *text, size_t length, void *user);
UBII_API ubii_status ubii_reply_for_each_string(const ubii_reply *reply, uint32_t expected_member,
                                                ubii_text_fn fn, void *user);

#ifdef __cplusplus
}
#endif

#endif

#ifndef UBII_SERVICE_QUEUE_H
#define UBII_SERVICE_QUEUE_H

/* service_queue.c: the application's calls and the node's own protocol steps share one
 * queue; a step's reply goes to its callback like any other, but a cancelled step is dropped
 * unanswered (the node cancels when it tears a connection down, and knows that already). Internal
 * to the core; not installed. */

#include "ubii/service.h"

enum ubii__call_owner { UBII__APPLICATION_CALL = 0, UBII__NODE_STEP = 1 };

ubii_status ubii__enqueue(ubii_node *node, const ubii_services_ServiceRequest *request,
                          uint32_t timeout_ms, enum ubii__call_owner owner, ubii_reply_fn fn,
                          void *user);
/* Sends the head of the queue when it can, and delivers its reply or its timeout. */
void ubii__service_step(ubii_node *node);
/* What becomes of the service channel once the calls are cancelled: a REQ socket with a request
 * in flight must be reset before it carries the next one, unless it is about to close anyway. */
enum ubii__service_channel_next { UBII__SERVICE_CHANNEL_REUSED, UBII__SERVICE_CHANNEL_CLOSES };
/* Fails every queued call with `status` (application callbacks see it; node steps are dropped). */
void ubii__cancel_calls(ubii_node *node, ubii_status status, enum ubii__service_channel_next next);

#endif

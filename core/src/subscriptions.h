#ifndef UBII_SUBSCRIPTIONS_H
#define UBII_SUBSCRIPTIONS_H

/* subscriptions.c: local subscriptions, their requests to the master, dispatch. Internal to the
 * core; not installed. */

#include "ubii/service.h"
#include "ubii/topic.h"

enum ubii__subscription_kind { UBII__FREE = 0, UBII__EXACT = 1, UBII__REGEX = 2 };

/* The connection is gone: the master holds none of this node's patterns any more. */
void ubii__subscriptions_reset_master(ubii_node *node);
/* Queues one request with whatever the master must learn (READY only). */
void ubii__subscriptions_sync(ubii_node *node);
/* Queues the request that drops every subscription the master holds (or was asked for) for this
 * node, its reply to `on_reply`; UBII_OK without a request when it holds none. */
ubii_status ubii__subscriptions_enqueue_release(ubii_node *node, ubii_reply_fn on_reply);
/* Hands one received record to the subscriptions whose pattern matches its topic. */
void ubii__dispatch_record(ubii_node *node, const ubii_record *record, const uint8_t *message,
                           size_t size);

#endif

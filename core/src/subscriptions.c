/* Local subscriptions, counted per distinct (kind, pattern): the master is asked once per pattern.
 *
 * Each slot holds a pattern. `active`: a local subscriber holds it. `at_master`: this slot owns
 * the pattern's subscription at the master (requested or confirmed); at most one slot per pattern
 * does. A slot whose subscriber left but whose pattern the master still has stays (inactive)
 * until the unsubscription is sent and answered. */
#include <string.h>

#include <pb_encode.h>

#include "copy_string.h"
#include "node_events.h"
#include "regex_match.h"
#include "service_queue.h"
#include "subscriptions.h"

enum { HANDLE_INDEX_BITS = 8, GENERATION_MASK = 0xffffff };

static bool same_pattern(const ubii__subscription *a, const ubii__subscription *b)
{
    return a->kind == b->kind && strcmp(a->pattern, b->pattern) == 0;
}

static ubii__subscription *owner_of(ubii_node *node, const ubii__subscription *like)
{
    for (size_t i = 0; i < UBII_MAX_SUBSCRIPTIONS; ++i) {
        ubii__subscription *slot = &node->subscriptions[i];
        if (slot->kind != UBII__FREE && slot->at_master && same_pattern(slot, like)) {
            return slot;
        }
    }
    return NULL;
}

static ubii__subscription *active_twin(ubii_node *node, const ubii__subscription *like)
{
    for (size_t i = 0; i < UBII_MAX_SUBSCRIPTIONS; ++i) {
        ubii__subscription *slot = &node->subscriptions[i];
        if (slot != like && slot->kind != UBII__FREE && slot->active && same_pattern(slot, like)) {
            return slot;
        }
    }
    return NULL;
}

static void free_slot(ubii__subscription *slot)
{
    memset(slot, 0, sizeof *slot);
}

static ubii_status add(ubii_node *node, const char *pattern, uint8_t kind, ubii_record_fn fn,
                       void *user, ubii_subscription *handle)
{
    if (node == NULL || pattern == NULL || pattern[0] == '\0' || fn == NULL ||
        strlen(pattern) >= UBII_MAX_TOPIC_SIZE) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    if (kind == UBII__REGEX) {
        ubii_status status = ubii__regex_validate(pattern);
        if (status != UBII_OK) {
            return status;
        }
    }
    for (size_t i = 0; i < UBII_MAX_SUBSCRIPTIONS; ++i) {
        ubii__subscription *slot = &node->subscriptions[i];
        if (slot->kind != UBII__FREE) {
            continue;
        }
        ubii__copy_string(slot->pattern, sizeof slot->pattern, pattern);
        slot->kind = kind;
        slot->fn = (ubii__callback)fn;
        slot->user = user;
        slot->active = 1;
        slot->generation = node->next_generation;
        node->next_generation = (node->next_generation + 1) & GENERATION_MASK;
        if (node->next_generation == 0) {
            node->next_generation = 1;
        }
        /* A pattern the master still holds for a departed subscriber is taken over. */
        ubii__subscription *owner = owner_of(node, slot);
        if (owner != NULL && !owner->active && !owner->in_flight) {
            free_slot(owner);
            slot->at_master = 1;
        }
        node->subscriptions_dirty = true;
        if (handle != NULL) {
            *handle = slot->generation << HANDLE_INDEX_BITS | (ubii_subscription)(i + 1);
        }
        return UBII_OK;
    }
    return UBII_ERR_FULL;
}

ubii_status ubii_subscribe(ubii_node *node, const char *topic, ubii_record_fn fn, void *user,
                           ubii_subscription *handle)
{
    return add(node, topic, UBII__EXACT, fn, user, handle);
}

ubii_status ubii_subscribe_regex(ubii_node *node, const char *regex, ubii_record_fn fn, void *user,
                                 ubii_subscription *handle)
{
    return add(node, regex, UBII__REGEX, fn, user, handle);
}

ubii_status ubii_unsubscribe(ubii_node *node, ubii_subscription handle)
{
    uint32_t index = (handle & ((1u << HANDLE_INDEX_BITS) - 1)) - 1;
    if (node == NULL || index >= UBII_MAX_SUBSCRIPTIONS) {
        return UBII_ERR_NOT_FOUND;
    }
    ubii__subscription *slot = &node->subscriptions[index];
    if (slot->kind == UBII__FREE || !slot->active ||
        slot->generation != handle >> HANDLE_INDEX_BITS) {
        return UBII_ERR_NOT_FOUND;
    }
    slot->active = 0;
    slot->fn = NULL;
    slot->user = NULL;
    ubii__subscription *twin = active_twin(node, slot);
    if (twin != NULL && slot->at_master && !slot->in_flight) {
        twin->at_master = 1;
        slot->at_master = 0;
    }
    if (!slot->at_master) {
        free_slot(slot);
    }
    node->subscriptions_dirty = true;
    return UBII_OK;
}

void ubii__subscriptions_reset_master(ubii_node *node)
{
    for (size_t i = 0; i < UBII_MAX_SUBSCRIPTIONS; ++i) {
        ubii__subscription *slot = &node->subscriptions[i];
        slot->at_master = 0;
        slot->in_flight = 0;
        if (slot->kind != UBII__FREE && !slot->active) {
            free_slot(slot);
        }
    }
    node->subscription_call_pending = false;
    node->duplicate_run = 0;
}

/* ---- the TopicSubscription request ----------------------------------------------------------- */

typedef struct list_selection {
    ubii_node *node;
    uint8_t kind;
    bool subscribing;
    bool releasing; /* every pattern the master holds, for the unsubscribe lists */
} list_selection;

static bool selected(const list_selection *selection, const ubii__subscription *slot)
{
    if (slot->kind != selection->kind) {
        return false;
    }
    if (selection->releasing) {
        return slot->at_master && !selection->subscribing;
    }
    return slot->in_flight && (bool)slot->active == selection->subscribing;
}

static bool encode_selected(pb_ostream_t *stream, const pb_field_t *field, void *const *arg)
{
    const list_selection *selection = *arg;
    for (size_t i = 0; i < UBII_MAX_SUBSCRIPTIONS; ++i) {
        const ubii__subscription *slot = &selection->node->subscriptions[i];
        if (selected(selection, slot)) {
            if (!pb_encode_tag_for_field(stream, field) ||
                !pb_encode_string(stream, (const pb_byte_t *)slot->pattern,
                                  strlen(slot->pattern))) {
                return false;
            }
        }
    }
    return true;
}

/* Marks what the master must learn; returns whether there is anything. */
static bool select_changes(ubii_node *node)
{
    bool any = false;
    for (size_t i = 0; i < UBII_MAX_SUBSCRIPTIONS; ++i) {
        ubii__subscription *slot = &node->subscriptions[i];
        if (slot->kind == UBII__FREE || slot->in_flight) {
            continue;
        }
        if (slot->active && !slot->at_master && owner_of(node, slot) == NULL) {
            slot->at_master = 1;
            slot->in_flight = 1;
            any = true;
        } else if (!slot->active && slot->at_master && active_twin(node, slot) == NULL) {
            slot->in_flight = 1;
            any = true;
        }
    }
    return any;
}

/* Queues a TopicSubscription request whose four lists are chosen by `releasing`: the marked
 * changes, or the release of everything the master holds. */
static ubii_status enqueue_subscription_request(ubii_node *node, bool releasing,
                                                ubii_reply_fn on_reply)
{
    list_selection lists[4] = {{node, UBII__EXACT, true, releasing},
                               {node, UBII__EXACT, false, releasing},
                               {node, UBII__REGEX, true, releasing},
                               {node, UBII__REGEX, false, releasing}};
    ubii_services_ServiceRequest request;
    memset(&request, 0, sizeof request);
    ubii__copy_string(request.topic, sizeof request.topic, UBII_SERVICE_TOPIC_SUBSCRIPTION);
    request.which_type = ubii_services_ServiceRequest_topic_subscription_tag;
    ubii_services_request_TopicSubscription *subscription = &request.type.topic_subscription;
    ubii__copy_string(subscription->client_id, sizeof subscription->client_id, node->client_id);
    pb_callback_t *fields[4] = {&subscription->subscribe_topics, &subscription->unsubscribe_topics,
                                &subscription->subscribe_topic_regexp,
                                &subscription->unsubscribe_topic_regexp};
    for (size_t i = 0; i < 4; ++i) {
        fields[i]->funcs.encode = encode_selected;
        fields[i]->arg = &lists[i];
    }
    return ubii__enqueue(node, &request, 0, UBII__NODE_STEP, on_reply, NULL);
}

/* Neither master releases a client's subscriptions when it deregisters (docs/PROTOCOL.md §2.8):
 * it would go on forwarding their data to the old id, and the npm 0.4.0 master gets slower with
 * every client that left that way. */
ubii_status ubii__subscriptions_enqueue_release(ubii_node *node, ubii_reply_fn on_reply)
{
    for (size_t i = 0; i < UBII_MAX_SUBSCRIPTIONS; ++i) {
        if (node->subscriptions[i].kind != UBII__FREE && node->subscriptions[i].at_master) {
            return enqueue_subscription_request(node, true, on_reply);
        }
    }
    return UBII_OK;
}

bool ubii_subscriptions_pending(const ubii_node *node)
{
    if (node == NULL) {
        return false;
    }
    if (node->subscriptions_dirty || node->subscription_call_pending) {
        return true;
    }
    for (size_t i = 0; i < UBII_MAX_SUBSCRIPTIONS; ++i) {
        const ubii__subscription *slot = &node->subscriptions[i];
        if (slot->kind != UBII__FREE && slot->active && !slot->at_master) {
            return true;
        }
    }
    return false;
}

static void on_subscription_reply(ubii_node *node, const ubii_reply *reply, void *unused)
{
    (void)unused;
    node->subscription_call_pending = false;
    bool succeeded =
        reply->status == UBII_OK && reply->member == ubii_services_ServiceReply_success_tag;
    for (size_t i = 0; i < UBII_MAX_SUBSCRIPTIONS; ++i) {
        ubii__subscription *slot = &node->subscriptions[i];
        if (!slot->in_flight) {
            continue;
        }
        slot->in_flight = 0;
        if (slot->active) {
            slot->at_master = succeeded;
        } else if (succeeded) {
            free_slot(slot);
        }
    }
    if (!succeeded && reply->status != UBII_ERR_CANCELLED) {
        node->stats.master_errors++;
        ubii__report(node, reply->status == UBII_OK ? UBII_ERR_UNEXPECTED_REPLY : reply->status,
                     reply->error_message[0] ? reply->error_message : "subscription failed");
        return;
    }
    /* Changes made while the request was out are sent now. */
    node->subscriptions_dirty = true;
}

void ubii__subscriptions_sync(ubii_node *node)
{
    if (!node->subscriptions_dirty || node->subscription_call_pending) {
        return;
    }
    node->subscriptions_dirty = false;
    if (!select_changes(node)) {
        return;
    }
    ubii_status status = enqueue_subscription_request(node, false, on_subscription_reply);
    if (status != UBII_OK) {
        /* Undo the marks; a full queue is retried at the next step. */
        for (size_t i = 0; i < UBII_MAX_SUBSCRIPTIONS; ++i) {
            ubii__subscription *slot = &node->subscriptions[i];
            if (slot->in_flight) {
                slot->in_flight = 0;
                if (slot->active) {
                    slot->at_master = 0;
                }
            }
        }
        node->subscriptions_dirty = status == UBII_ERR_FULL;
        if (status != UBII_ERR_FULL) {
            ubii__report(node, status, "subscription request could not be encoded");
        }
        return;
    }
    node->subscription_call_pending = true;
}

/* ---- dispatch -------------------------------------------------------------------------------- */

static bool matches(const ubii__subscription *slot, const char *topic)
{
    if (slot->kind == UBII__EXACT) {
        return strcmp(slot->pattern, topic) == 0;
    }
    return ubii__regex_search(slot->pattern, topic, UBII_REGEX_STEP_LIMIT) == UBII_OK;
}

static uint64_t fnv1a(const uint8_t *bytes, size_t size)
{
    uint64_t hash = 1469598103934665603ull;
    for (size_t i = 0; i < size; ++i) {
        hash = (hash ^ bytes[i]) * 1099511628211ull;
    }
    return hash;
}

/* The master sends a record once per subscription of this client that matches its topic, one copy
 * right after the other. With k such subscriptions, k identical messages in a row are one record.
 */
static bool is_duplicate(ubii_node *node, uint32_t copies, const uint8_t *message, size_t size)
{
    uint64_t hash = fnv1a(message, size);
    bool duplicate =
        copies > 1 && hash == node->last_record_hash && node->duplicate_run + 1 < copies;
    node->duplicate_run = duplicate ? node->duplicate_run + 1 : 0;
    node->last_record_hash = hash;
    return duplicate;
}

void ubii__dispatch_record(ubii_node *node, const ubii_record *record, const uint8_t *message,
                           size_t size)
{
    /* Each pattern is matched once per record: the generation a slot matched with, 0 for none.
     * A callback may unsubscribe and subscribe; a slot taken anew has another generation. */
    uint32_t matched_generation[UBII_MAX_SUBSCRIPTIONS];
    uint32_t copies = 0;
    for (size_t i = 0; i < UBII_MAX_SUBSCRIPTIONS; ++i) {
        const ubii__subscription *slot = &node->subscriptions[i];
        bool relevant = slot->kind != UBII__FREE && (slot->at_master || slot->active);
        matched_generation[i] = relevant && matches(slot, record->topic) ? slot->generation : 0;
        if (matched_generation[i] != 0 && slot->at_master) {
            copies++;
        }
    }
    if (is_duplicate(node, copies, message, size)) {
        node->stats.duplicates_dropped++;
        return;
    }
    node->stats.records_received++;
    for (size_t i = 0; i < UBII_MAX_SUBSCRIPTIONS && node->state == UBII_STATE_READY; ++i) {
        ubii__subscription *slot = &node->subscriptions[i];
        if (slot->kind != UBII__FREE && slot->active && matched_generation[i] != 0 &&
            slot->generation == matched_generation[i]) {
            ((ubii_record_fn)slot->fn)(node, record, slot->user);
        }
    }
}

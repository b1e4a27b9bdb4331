/* pubsub: two nodes in one process, one topic. The publisher sends a counter and a rotating
 * vector; the subscriber prints what arrives.
 *
 *   pubsub [SERVICE_URL [TOPIC_URL [SECONDS]]]   defaults: tcp://127.0.0.1:8101
 * tcp://127.0.0.1:8103 3
 *
 * TOPIC_URL may be ws://127.0.0.1:8104 for WebSocket topic data. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "example_args.h"
#include "ubii/dataStructure/vector3.pb.h"
#include "example_port.h"
#include "ubii/ubii.h"

/* Topics are scoped by the publisher's client id, so that runs side by side do not mix. */
static char counter_topic[128];
static char vector_topic[128];

static double seconds_now(void)
{
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    return (double)now.tv_sec + (double)now.tv_nsec / 1e9;
}

static void on_record(ubii_node *node, const ubii_record *record, void *user)
{
    (void)node;
    int *received = user;
    int32_t count;
    ubii_dataStructure_Vector3 vector = ubii_dataStructure_Vector3_init_zero;
    (*received)++;
    if (ubii_record_int32(record, &count) == UBII_OK) {
        printf("subscriber: %s = %d\n", record->topic, count);
    } else if (ubii_record_decode(record, UBII_RECORD_VECTOR3, ubii_dataStructure_Vector3_fields,
                                  &vector) == UBII_OK) {
        printf("subscriber: %s = (%.3f, %.3f, %.3f)\n", record->topic, vector.x, vector.y,
               vector.z);
    }
}

static void on_error(ubii_node *node, ubii_status status, const char *detail, void *user)
{
    (void)node;
    fprintf(stderr, "%s: %s (%s)\n", (const char *)user, detail, ubii_strerror(status));
}

/* Polls both nodes until `done` says so or `seconds` pass. */
static int pump(ubii_node *a, ubii_node *b, double seconds, int (*done)(ubii_node *, ubii_node *))
{
    double deadline = seconds_now() + seconds;
    while (seconds_now() < deadline) {
        ubii_node_poll(a, 5);
        ubii_node_poll(b, 5);
        if (done != NULL && done(a, b)) {
            return 1;
        }
    }
    return 0;
}

static int both_ready(ubii_node *a, ubii_node *b)
{
    return ubii_node_state(a) == UBII_STATE_READY && ubii_node_state(b) == UBII_STATE_READY;
}

int main(int argc, char **argv)
{
    example_args args = example_parse_args(argc, argv, 3.0);
    static example_port publisher_port, subscriber_port;
    if (!example_port_open(&publisher_port) || !example_port_open(&subscriber_port)) {
        fprintf(stderr, "pubsub: cannot create the transport\n");
        return 1;
    }

    ubii_config config;
    ubii_config_init(&config);
    config.service_url = args.service_url;
    config.topic_url = args.topic_url;
    config.on_error = on_error;

    static ubii_node publisher, subscriber;
    config.client_name = "libubii-example-publisher";
    config.on_error_user = "publisher";
    ubii_node_init(&publisher, sizeof publisher, &config, example_port_get(&publisher_port));
    config.client_name = "libubii-example-subscriber";
    config.on_error_user = "subscriber";
    ubii_node_init(&subscriber, sizeof subscriber, &config, example_port_get(&subscriber_port));

    if (ubii_node_start(&publisher) != UBII_OK || ubii_node_start(&subscriber) != UBII_OK ||
        !pump(&publisher, &subscriber, 10.0, both_ready)) {
        fprintf(stderr, "pubsub: could not connect to %s / %s\n", args.service_url, args.topic_url);
        return 1;
    }
    printf("publisher %s and subscriber %s are connected\n", ubii_node_client_id(&publisher),
           ubii_node_client_id(&subscriber));

    const char *id = ubii_node_client_id(&publisher);
    char vector_regex[160];
    snprintf(counter_topic, sizeof counter_topic, "/%s/example/counter", id);
    snprintf(vector_topic, sizeof vector_topic, "/%s/example/vector", id);
    snprintf(vector_regex, sizeof vector_regex, "^/%s/example/vec", id);
    int received = 0;
    ubii_status status = ubii_subscribe(&subscriber, counter_topic, on_record, &received, NULL);
    if (status == UBII_OK) {
        status = ubii_subscribe_regex(&subscriber, vector_regex, on_record, &received, NULL);
    }
    if (status != UBII_OK) {
        fprintf(stderr, "pubsub: subscribing failed: %s\n", ubii_strerror(status));
        return 1;
    }
    pump(&publisher, &subscriber, 0.3, NULL); /* let the subscriptions reach the master */

    double start = seconds_now();
    int sent = 0;
    while (seconds_now() - start < args.seconds) {
        double phase = (seconds_now() - start) * 2.0;
        ubii_dataStructure_Vector3 vector = {cos(phase), sin(phase), phase};
        status = ubii_publish_int32(&publisher, counter_topic, sent);
        if (status == UBII_OK) {
            status = ubii_publish_vector3(&publisher, vector_topic, &vector);
        }
        if (status != UBII_OK) {
            fprintf(stderr, "pubsub: publishing failed: %s\n", ubii_strerror(status));
            break;
        }
        sent += 2;
        pump(&publisher, &subscriber, 0.25, NULL);
    }
    pump(&publisher, &subscriber, 0.3, NULL);
    printf("sent %d records, received %d\n", sent, received);

    ubii_node_stop_wait(&publisher, 2000);
    ubii_node_stop_wait(&subscriber, 2000);
    example_port_close(&publisher_port);
    example_port_close(&subscriber_port);
    return sent > 0 && received == sent ? 0 : 1;
}

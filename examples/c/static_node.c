/* static_node: a node as small firmware runs one. Node and port are static, nothing is allocated:
 * this program replaces malloc, calloc, realloc and free with versions that abort, so a single
 * allocation anywhere in libubii would end it. It connects, subscribes, publishes a reading and
 * receives it back through the master, then stops. Output goes through write(2), not stdio (which
 * may allocate its buffers).
 *
 *   static_node SERVICE_URL TOPIC_URL    e.g. tcp://127.0.0.1:8101 tcp://127.0.0.1:8103 */
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "example_port.h"
#include "ubii/ubii.h"

static void say(const char *text)
{
    ssize_t written = write(STDOUT_FILENO, text, strlen(text));
    (void)written;
}

/* Allocation traps: reaching one is a failure of the no-heap promise. */
void *malloc(size_t size)
{
    (void)size;
    say("static_node: malloc called\n");
    abort();
}

void *calloc(size_t count, size_t size)
{
    (void)count;
    (void)size;
    say("static_node: calloc called\n");
    abort();
}

void *realloc(void *pointer, size_t size)
{
    (void)pointer;
    (void)size;
    say("static_node: realloc called\n");
    abort();
}

void free(void *pointer)
{
    if (pointer != NULL) {
        say("static_node: free called\n");
        abort();
    }
}

static example_port port;
static ubii_node node;
static int readings;

static void on_reading(ubii_node *n, const ubii_record *record, void *user)
{
    (void)n;
    (void)user;
    double value;
    if (ubii_record_double(record, &value) == UBII_OK && value == 21.5) {
        readings++;
    }
}

static int poll_until_state(ubii_state wanted, int seconds)
{
    time_t deadline = time(NULL) + seconds;
    while (ubii_node_state(&node) != wanted && time(NULL) < deadline) {
        ubii_node_poll(&node, 10);
    }
    return ubii_node_state(&node) == wanted;
}

int main(int argc, char **argv)
{
    if (argc < 3 || !example_port_open(&port)) {
        say("usage: static_node SERVICE_URL TOPIC_URL\n");
        return 2;
    }
    ubii_config config;
    ubii_config_init(&config);
    config.service_url = argv[1];
    config.topic_url = argv[2];
    config.client_name = "libubii-static-node";
    if (ubii_node_init(&node, sizeof node, &config, example_port_get(&port)) != UBII_OK ||
        ubii_node_start(&node) != UBII_OK || !poll_until_state(UBII_STATE_READY, 10)) {
        say("static_node: could not connect\n");
        return 1;
    }
    char topic[96] = "/";
    strcat(topic, ubii_node_client_id(&node));
    strcat(topic, "/temperature");
    ubii_subscribe(&node, topic, on_reading, NULL, NULL);
    time_t deadline = time(NULL) + 10;
    while (readings < 3 && time(NULL) < deadline) {
        ubii_publish_double(&node, topic, 21.5);
        for (int i = 0; i < 10; ++i) {
            ubii_node_poll(&node, 10);
        }
    }
    ubii_node_stop_wait(&node, 2000);
    example_port_close(&port);
    say(readings >= 3 ? "static_node: readings came back, nothing allocated\n"
                      : "static_node: no readings came back\n");
    return readings >= 3 ? 0 : 1;
}

/* idle_node: a node that connects, subscribes to one topic, prints "idle_node: ready" and then
 * only polls (answering PINGs) until SIGTERM or SIGINT: what bench/footprint_idle.sh measures.
 *
 *   idle_node SERVICE_URL TOPIC_URL [libzmq]    libzmq: tcp:// through libzmq, not in-thread
 * Built for either port: on the embedded one (UBII_BENCH_EMBEDDED) the third argument is ignored.
 */
#define _POSIX_C_SOURCE 200809L

#include <signal.h>
#include <stdio.h>
#include <string.h>

#include "ubii/ubii.h"
#ifdef UBII_BENCH_EMBEDDED
#include "ubii/port_embedded.h"
#else
#include "ubii/port_linux.h"
#endif

static volatile sig_atomic_t stopping = 0;

static void on_signal(int signal_number)
{
    (void)signal_number;
    stopping = 1;
}

static void on_record(ubii_node *node, const ubii_record *record, void *user)
{
    (void)node;
    (void)record;
    (void)user;
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: idle_node SERVICE_URL TOPIC_URL [libzmq]\n");
        return 2;
    }
    struct sigaction action;
    memset(&action, 0, sizeof action);
    action.sa_handler = on_signal;
    sigaction(SIGTERM, &action, NULL);
    sigaction(SIGINT, &action, NULL);
#ifdef UBII_BENCH_EMBEDDED
    static ubii_embedded_port embedded_port;
    if (ubii_embedded_port_init(&embedded_port, ubii_embedded_posix_platform()) != UBII_OK) {
        fprintf(stderr, "idle_node: no embedded port\n");
        return 1;
    }
    ubii_port port_handle = ubii_embedded_port_get(&embedded_port);
#else
    ubii_linux_port_options options = {0};
    options.libwebsockets_log_level = 1;
    if (argc > 3 && strcmp(argv[3], "libzmq") == 0) {
        options.zmq_engine = UBII_LINUX_ZMQ_LIBZMQ;
    }
    ubii_linux_port *port = NULL;
    if (ubii_linux_port_create(&port, &options) != UBII_OK) {
        fprintf(stderr, "idle_node: no Linux port\n");
        return 1;
    }
    ubii_port port_handle = ubii_linux_port_get(port);
#endif
    ubii_config config;
    ubii_config_init(&config);
    config.service_url = argv[1];
    config.topic_url = argv[2];
    config.client_name = "libubii-idle";
    static ubii_node node;
    if (ubii_node_init(&node, sizeof node, &config, port_handle) != UBII_OK ||
        ubii_subscribe(&node, "/libubii/idle", on_record, NULL, NULL) != UBII_OK ||
        ubii_node_start(&node) != UBII_OK) {
        fprintf(stderr, "idle_node: invalid arguments\n");
        return 2;
    }
    int said_ready = 0;
    while (!stopping) {
        ubii_node_poll(&node, 100);
        if (!said_ready && ubii_node_state(&node) == UBII_STATE_READY &&
            !ubii_subscriptions_pending(&node)) {
            printf("idle_node: ready\n");
            fflush(stdout);
            said_ready = 1;
        }
    }
    ubii_node_stop_wait(&node, 2000);
#ifdef UBII_BENCH_EMBEDDED
    ubii_embedded_port_close(&embedded_port);
#else
    ubii_linux_port_destroy(port);
#endif
    return 0;
}

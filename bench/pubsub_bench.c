/* pubsub_bench: what one libubii node costs and how fast it goes through a master. The node
 * subscribes to its own topic, then
 *   latency:    ROUNDS sequential round trips (publish, wait for the master's copy), p50/p99;
 *   throughput: MESSAGES published with at most WINDOW unanswered, messages/s received back,
 *               and this process's CPU time (user + system) per message.
 * The throughput phase either reacts to every arrival (poll with a timeout, as an event loop
 * does) or, with FRAME_US > 0, runs as a game engine's tick would: poll(node, 0) once per frame
 * of FRAME_US microseconds, sleeping in between.
 * Prints one line of key=value figures (bench/run.sh puts them beside the Node.js node's).
 *
 *   pubsub_bench SERVICE_URL TOPIC_URL [ROUNDS [MESSAGES [WINDOW [FRAME_US]]]]
 * On the Linux port, UBII_BENCH_ZMQ_ENGINE=libzmq speaks tcp:// through libzmq
 * (UBII_LINUX_ZMQ_LIBZMQ) instead of the default in-thread engine. */
#define _POSIX_C_SOURCE 200809L

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>

#include "ubii/ubii.h"
#ifdef UBII_BENCH_EMBEDDED
#include "ubii/port_embedded.h"
#else
#include "ubii/port_linux.h"
#endif

static const char topic[] = "/libubii/bench/echo";

static double now_seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec / 1e9;
}

/* Process CPU time in seconds: user (the process's own code) and system (the kernel on its
 * behalf: sockets, loopback TCP, thread wake-ups); and how often its threads went to sleep or
 * were preempted (each sleep is a wake-up the kernel pays for). */
static void cpu_seconds(double *user, double *system, long *switches)
{
    struct rusage usage;
    getrusage(RUSAGE_SELF, &usage);
    *user = (double)usage.ru_utime.tv_sec + (double)usage.ru_utime.tv_usec / 1e6;
    *system = (double)usage.ru_stime.tv_sec + (double)usage.ru_stime.tv_usec / 1e6;
    *switches = usage.ru_nvcsw + usage.ru_nivcsw;
}

static long received = 0;

static void on_record(ubii_node *node, const ubii_record *record, void *user)
{
    (void)node;
    (void)record;
    (void)user;
    received++;
}

/* Trouble is reported, never hidden: a run that went wrong says how on stderr. */
static void on_state(ubii_node *node, ubii_state previous, ubii_state current, ubii_status reason,
                     void *user)
{
    (void)node;
    (void)user;
    if (current == UBII_STATE_RECONNECTING || current == UBII_STATE_FAILED) {
        fprintf(stderr, "pubsub_bench: state %d -> %d: %s\n", (int)previous, (int)current,
                ubii_strerror(reason));
    }
}

static void on_error(ubii_node *node, ubii_status status, const char *detail, void *user)
{
    (void)node;
    (void)user;
    fprintf(stderr, "pubsub_bench: %s: %s\n", ubii_strerror(status), detail);
}

static int compare(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static void sleep_until_next_frame(double since, long frame_us)
{
    double frame = (double)frame_us / 1e6;
    double elapsed = now_seconds() - since;
    double wait = frame - fmod(elapsed, frame);
    struct timespec pause = {(time_t)wait, (long)((wait - (double)(time_t)wait) * 1e9)};
    nanosleep(&pause, NULL);
}

static int poll_until(ubii_node *node, long target, double timeout)
{
    double deadline = now_seconds() + timeout;
    while (received < target) {
        if (now_seconds() > deadline) {
            return 0;
        }
        ubii_node_poll(node, 1);
    }
    return 1;
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(
            stderr,
            "usage: pubsub_bench SERVICE_URL TOPIC_URL [ROUNDS [MESSAGES [WINDOW [FRAME_US]]]]\n");
        return 2;
    }
    int rounds = argc > 3 ? atoi(argv[3]) : 2000;
    long messages = argc > 4 ? atol(argv[4]) : 20000;
    long window = argc > 5 ? atol(argv[5]) : 100;
    long frame_us = argc > 6 ? atol(argv[6]) : 0;

#ifdef UBII_BENCH_EMBEDDED
    static ubii_embedded_port embedded_port;
    ubii_embedded_port *port = &embedded_port;
    if (ubii_embedded_port_init(port, ubii_embedded_posix_platform()) != UBII_OK) {
        return 1;
    }
    ubii_port port_handle = ubii_embedded_port_get(port);
#else
    ubii_linux_port_options options = {0};
    options.libwebsockets_log_level = 1;
    const char *engine = getenv("UBII_BENCH_ZMQ_ENGINE");
    if (engine != NULL && strcmp(engine, "libzmq") == 0) {
        /* A ZMQ-only application on libzmq need not start libwebsockets at all. */
        options.zmq_engine = UBII_LINUX_ZMQ_LIBZMQ;
        options.zmq_only = strncmp(argv[1], "tcp://", 6) == 0 && strncmp(argv[2], "tcp://", 6) == 0;
    }
    ubii_linux_port *port;
    if (ubii_linux_port_create(&port, &options) != UBII_OK) {
        return 1;
    }
    ubii_port port_handle = ubii_linux_port_get(port);
#endif
    ubii_config config;
    ubii_config_init(&config);
    config.service_url = argv[1];
    config.topic_url = argv[2];
    config.client_name = "libubii-bench";
    config.stamp_records = false; /* as the Node.js side, which stamps nothing either */
    config.on_state = on_state;
    config.on_error = on_error;
    static ubii_node node;
    ubii_node_init(&node, sizeof node, &config, port_handle);
    ubii_subscribe(&node, topic, on_record, NULL, NULL);
    ubii_node_start(&node);
    double deadline = now_seconds() + 10;
    while (ubii_node_state(&node) != UBII_STATE_READY && now_seconds() < deadline) {
        ubii_node_poll(&node, 10);
    }
    /* Warm up until the subscription is served. */
    while (received == 0 && now_seconds() < deadline) {
        ubii_publish_double(&node, topic, 0.0);
        ubii_node_poll(&node, 10);
    }
    if (received == 0) {
        ubii_stats stats;
        ubii_node_stats(&node, &stats);
        fprintf(stderr,
                "pubsub_bench: no echo from the master (state %d, published %llu, received %llu, "
                "service timeouts %llu, reconnects %llu, master errors %llu)\n",
                (int)ubii_node_state(&node), (unsigned long long)stats.records_published,
                (unsigned long long)stats.records_received,
                (unsigned long long)stats.service_timeouts, (unsigned long long)stats.reconnects,
                (unsigned long long)stats.master_errors);
        return 1;
    }
    poll_until(&node, received + 1000000, 0.2);

    double *rtt = malloc(sizeof(double) * (size_t)rounds);
    for (int i = 0; i < rounds; ++i) {
        long target = received + 1;
        double start = now_seconds();
        ubii_publish_double(&node, topic, (double)i);
        if (!poll_until(&node, target, 5.0)) {
            fprintf(stderr, "pubsub_bench: round %d lost\n", i);
            return 1;
        }
        rtt[i] = (now_seconds() - start) * 1e6;
    }
    qsort(rtt, (size_t)rounds, sizeof rtt[0], compare);

    long base = received;
    double user_start, system_start;
    long switches_start;
    cpu_seconds(&user_start, &system_start, &switches_start);
    double start = now_seconds();
    long sent = 0;
    while (sent < messages) {
        while (sent < messages && sent - (received - base) < window) {
            if (ubii_publish_double(&node, topic, (double)sent) != UBII_OK) {
                break;
            }
            sent++;
        }
        if (frame_us > 0) {
            ubii_node_poll(&node, 0);
            sleep_until_next_frame(start, frame_us);
        } else {
            ubii_node_poll(&node, 1);
        }
    }
    if (!poll_until(&node, base + messages, 30.0)) {
        fprintf(stderr, "pubsub_bench: %ld of %ld came back\n", received - base, messages);
        return 1;
    }
    double elapsed = now_seconds() - start;
    double user_end, system_end;
    long switches_end;
    cpu_seconds(&user_end, &system_end, &switches_end);
    double user = user_end - user_start, system = system_end - system_start;
    printf("rtt_p50_us=%.1f rtt_p99_us=%.1f messages_per_s=%.0f cpu_us_per_message=%.2f "
           "user_us_per_message=%.2f system_us_per_message=%.2f switches_per_message=%.2f\n",
           rtt[rounds / 2], rtt[rounds * 99 / 100], (double)messages / elapsed,
           (user + system) * 1e6 / (double)messages, user * 1e6 / (double)messages,
           system * 1e6 / (double)messages,
           (double)(switches_end - switches_start) / (double)messages);
    free(rtt);
    /* A node the master still believes in would be sent the next run's messages. */
    if (ubii_node_stop_wait(&node, 2000) != UBII_OK) {
        fprintf(stderr, "pubsub_bench: the node did not deregister cleanly\n");
    }
#ifdef UBII_BENCH_EMBEDDED
    ubii_embedded_port_close(port);
#else
    ubii_linux_port_destroy(port);
#endif
    return 0;
}

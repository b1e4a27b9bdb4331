/* soak: one node publishing numbered records at RATE Hz through a master and receiving them back,
 * for SECONDS. Every record carries its sequence number (an int32 on a topic of this run); the
 * receiver counts what is lost, duplicated and out of order. Resident memory and CPU time are read
 * at the start, after WARMUP seconds, and at the end; a line every REPORT seconds shows progress.
 *
 *   soak SERVICE_URL TOPIC_URL [SECONDS [RATE [WARMUP [REPORT]]]]   defaults: 30 s, 1000 Hz, 10 s,
 * 10 s
 *
 * The last line is "soak: sent=... received=... lost=... duplicated=... reordered=...
 * rss_start_kib=
 * ... rss_warm_kib=... rss_end_kib=... cpu_s=..."; exit status 0 only when nothing was lost,
 * duplicated or reordered and the node stayed connected throughout. A record still in flight when
 * the run ends counts as lost only if it has not arrived within a grace second. */
#define _POSIX_C_SOURCE 200809L

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>
#include <unistd.h>

#include "ubii/port_linux.h"
#include "ubii/ubii.h"

enum { GRACE_MS = 1000, CONNECT_TIMEOUT_S = 10 };

typedef struct counts {
    int32_t next_expected; /* the sequence number that should arrive next */
    uint64_t received;
    uint64_t duplicated;
    uint64_t reordered;
    uint64_t gaps; /* numbers skipped over when a later one arrived first */
    uint8_t *seen; /* one byte per sequence number */
    int32_t capacity;
    uint64_t state_changes_after_ready;
} counts;

static double now_seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec / 1e9;
}

static long resident_kib(void)
{
    FILE *status = fopen("/proc/self/status", "r");
    if (status == NULL) {
        return -1;
    }
    char line[256];
    long kib = -1;
    while (fgets(line, sizeof line, status) != NULL) {
        if (sscanf(line, "VmRSS: %ld kB", &kib) == 1) {
            break;
        }
    }
    fclose(status);
    return kib;
}

static double cpu_seconds(void)
{
    struct rusage usage;
    getrusage(RUSAGE_SELF, &usage);
    return (double)usage.ru_utime.tv_sec + (double)usage.ru_utime.tv_usec / 1e6 +
           (double)usage.ru_stime.tv_sec + (double)usage.ru_stime.tv_usec / 1e6;
}

static void on_record(ubii_node *node, const ubii_record *record, void *user)
{
    (void)node;
    counts *c = user;
    int32_t sequence;
    if (ubii_record_int32(record, &sequence) != UBII_OK || sequence < 0 ||
        sequence >= c->capacity) {
        return;
    }
    if (c->seen[sequence]) {
        c->duplicated++;
        return;
    }
    c->seen[sequence] = 1;
    c->received++;
    if (sequence < c->next_expected) {
        c->reordered++; /* an earlier number after a later one */
    } else {
        c->gaps += (uint64_t)(sequence - c->next_expected);
        c->next_expected = sequence + 1;
    }
}

static void on_state(ubii_node *node, ubii_state previous, ubii_state current, ubii_status reason,
                     void *user)
{
    (void)node;
    (void)reason;
    counts *c = user;
    if (previous == UBII_STATE_READY && current != UBII_STATE_READY) {
        c->state_changes_after_ready++;
    }
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: soak SERVICE_URL TOPIC_URL [SECONDS [RATE [WARMUP [REPORT]]]]\n");
        return 2;
    }
    double seconds = argc > 3 ? atof(argv[3]) : 30;
    double rate = argc > 4 ? atof(argv[4]) : 1000;
    double warmup = argc > 5 ? atof(argv[5]) : 10;
    double report = argc > 6 ? atof(argv[6]) : 10;
    if (!(seconds > 0) || !(rate > 0) || rate > 100000 || warmup < 0 || !(report > 0) ||
        seconds * rate >= INT32_MAX) {
        fprintf(stderr, "soak: SECONDS, RATE (<= 100000), WARMUP and REPORT must be positive\n");
        return 2;
    }
    counts c;
    memset(&c, 0, sizeof c);
    c.capacity = (int32_t)(seconds * rate) + 1;
    c.seen = malloc((size_t)c.capacity);
    if (c.seen == NULL) {
        fprintf(stderr, "soak: no memory for %d sequence numbers\n", c.capacity);
        return 2;
    }
    /* Written now, so that its pages are resident before the first reading: left untouched, the
     * table would grow RSS by a page every 4096 records. Volatile, or the compiler turns
     * malloc + memset into calloc, whose fresh pages are not resident. */
    volatile uint8_t *touch = c.seen;
    for (int32_t i = 0; i < c.capacity; ++i) {
        touch[i] = 0;
    }
    ubii_linux_port_options options = {0};
    options.libwebsockets_log_level = 1;
    ubii_linux_port *port = NULL;
    if (ubii_linux_port_create(&port, &options) != UBII_OK) {
        fprintf(stderr, "soak: no Linux port\n");
        return 2;
    }
    ubii_config config;
    ubii_config_init(&config);
    config.service_url = argv[1];
    config.topic_url = argv[2];
    config.client_name = "libubii-soak";
    config.on_state = on_state;
    config.on_state_user = &c;
    static ubii_node node;
    char topic[64];
    snprintf(topic, sizeof topic, "/libubii/soak/%ld", (long)getpid());
    if (ubii_node_init(&node, sizeof node, &config, ubii_linux_port_get(port)) != UBII_OK ||
        ubii_subscribe(&node, topic, on_record, &c, NULL) != UBII_OK ||
        ubii_node_start(&node) != UBII_OK) {
        fprintf(stderr, "soak: invalid arguments\n");
        return 2;
    }
    double deadline = now_seconds() + CONNECT_TIMEOUT_S;
    while ((ubii_node_state(&node) != UBII_STATE_READY || ubii_subscriptions_pending(&node)) &&
           now_seconds() < deadline) {
        ubii_node_poll(&node, 20);
    }
    if (ubii_node_state(&node) != UBII_STATE_READY) {
        fprintf(stderr, "soak: could not connect to %s\n", argv[1]);
        return 1;
    }

    long rss_start = resident_kib(), rss_warm = -1;
    double cpu_start = cpu_seconds(), cpu_warm = 0;
    double start = now_seconds(), next_report = start + report;
    int32_t sent = 0;
    uint64_t publish_failures = 0;
    for (;;) {
        double now = now_seconds();
        double elapsed = now - start;
        if (elapsed >= seconds) {
            break;
        }
        /* As many records as are due by now: a late wake-up catches up instead of drifting. */
        int32_t due = (int32_t)(elapsed * rate) + 1;
        while (sent < due && sent < c.capacity) {
            if (ubii_publish_int32(&node, topic, sent) == UBII_OK) {
                sent++;
            } else {
                publish_failures++;
                break;
            }
        }
        if (rss_warm < 0 && elapsed >= warmup) {
            rss_warm = resident_kib();
            cpu_warm = cpu_seconds();
        }
        if (now >= next_report) {
            printf("soak: %.0f s sent=%d received=%llu rss_kib=%ld cpu_s=%.2f\n", elapsed, sent,
                   (unsigned long long)c.received, resident_kib(), cpu_seconds() - cpu_start);
            fflush(stdout);
            next_report += report;
        }
        /* Until the next record is due, rounded up: rounding down would spin. */
        double wait_ms = ((double)due / rate - elapsed) * 1000.0;
        ubii_node_poll(&node, wait_ms > 0 ? (int)wait_ms + 1 : 0);
    }
    double drain_until = now_seconds() + GRACE_MS / 1000.0;
    while (c.received + c.duplicated < (uint64_t)sent && now_seconds() < drain_until) {
        ubii_node_poll(&node, 10);
    }
    long rss_end = resident_kib();
    double cpu_total = cpu_seconds() - cpu_start;
    if (rss_warm < 0) {
        rss_warm = rss_end;
        cpu_warm = cpu_seconds();
    }
    uint64_t lost = (uint64_t)sent - c.received;
    double growth = rss_warm > 0 ? 100.0 * (double)(rss_end - rss_warm) / (double)rss_warm : 0;
    printf("soak: sent=%d received=%llu lost=%llu duplicated=%llu reordered=%llu "
           "publish_refused=%llu disconnects=%llu rss_start_kib=%ld rss_warm_kib=%ld "
           "rss_end_kib=%ld rss_growth_after_warmup=%.2f%% cpu_s=%.2f cpu_per_record_us=%.1f "
           "cpu_after_warmup_s=%.2f\n",
           sent, (unsigned long long)c.received, (unsigned long long)lost,
           (unsigned long long)c.duplicated, (unsigned long long)c.reordered,
           (unsigned long long)publish_failures, (unsigned long long)c.state_changes_after_ready,
           rss_start, rss_warm, rss_end, growth, cpu_total, sent > 0 ? cpu_total * 1e6 / sent : 0.0,
           cpu_seconds() - cpu_warm);
    bool clean = lost == 0 && c.duplicated == 0 && c.reordered == 0 &&
                 c.state_changes_after_ready == 0; /* before stopping, which leaves READY too */
    ubii_node_stop_wait(&node, 2000);
    ubii_linux_port_destroy(port);
    free(c.seen);
    return clean ? 0 : 1;
}

#ifndef UBII_EXAMPLE_CONNECT_H
#define UBII_EXAMPLE_CONNECT_H

/* For the examples that run a few service calls and end: a node on the given port with the
 * example's URLs and name, started and polled until it is ready or `deadline` passes. */

#include <stdbool.h>
#include <stdio.h>
#include <time.h>

#include "example_args.h"
#include "ubii/ubii.h"

static inline bool example_connect(ubii_node *node, ubii_port port, const example_args *args,
                                   const char *client_name, time_t deadline)
{
    ubii_config config;
    ubii_config_init(&config);
    config.service_url = args->service_url;
    config.topic_url = args->topic_url;
    config.client_name = client_name;
    if (ubii_node_init(node, sizeof *node, &config, port) != UBII_OK ||
        ubii_node_start(node) != UBII_OK) {
        fprintf(stderr, "%s: invalid URLs %s %s\n", client_name, args->service_url,
                args->topic_url);
        return false;
    }
    while (ubii_node_state(node) != UBII_STATE_READY && time(NULL) < deadline) {
        ubii_node_poll(node, 50);
    }
    if (ubii_node_state(node) != UBII_STATE_READY) {
        fprintf(stderr, "%s: could not connect to %s\n", client_name, args->service_url);
        return false;
    }
    return true;
}

#endif

#ifndef UBII_EXAMPLE_ARGS_H
#define UBII_EXAMPLE_ARGS_H

/* Command-line defaults shared by the examples: SERVICE_URL TOPIC_URL [SECONDS]. */

#include <stdio.h>
#include <stdlib.h>

typedef struct example_args {
    const char *service_url;
    const char *topic_url;
    double seconds;
} example_args;

static inline example_args example_parse_args(int argc, char **argv, double default_seconds)
{
    example_args args = {"tcp://127.0.0.1:8101", "tcp://127.0.0.1:8103", default_seconds};
    if (argc > 1) {
        args.service_url = argv[1];
    }
    if (argc > 2) {
        args.topic_url = argv[2];
    }
    if (argc > 3) {
        args.seconds = atof(argv[3]);
    }
    return args;
}

#endif

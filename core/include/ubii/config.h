#ifndef UBII_CONFIG_H
#define UBII_CONFIG_H

/* Compile-time limits of the core. Each has a default and may be overridden with -D, or in a header
 * of your own named by UBII_CONFIG_FILE (e.g. -DUBII_CONFIG_FILE='"my_ubii_config.h"'). They size
 * the fields of ubii_node, so the library and every file using ubii_node must see the same values;
 * ubii_node_init() checks that through the size it is given. */

#ifdef UBII_CONFIG_FILE
#include UBII_CONFIG_FILE
#endif

/* Local subscriptions (topic or regex + callback) a node can hold at once. */
#ifndef UBII_MAX_SUBSCRIPTIONS
#define UBII_MAX_SUBSCRIPTIONS 16
#endif

/* Longest topic or regex, including the terminating NUL. Matches the schema's topic max_size. */
#ifndef UBII_MAX_TOPIC_SIZE
#define UBII_MAX_TOPIC_SIZE 256
#endif

/* Longest service or topic URL, including the NUL. */
#ifndef UBII_MAX_URL_SIZE
#define UBII_MAX_URL_SIZE 256
#endif

/* Longest client name, including the NUL. Matches the schema's Client.name max_size. */
#ifndef UBII_MAX_NAME_SIZE
#define UBII_MAX_NAME_SIZE 128
#endif

/* Longest client id the master assigns, including the NUL. Both masters use UUIDs (36 characters).
 */
#ifndef UBII_MAX_CLIENT_ID_SIZE
#define UBII_MAX_CLIENT_ID_SIZE 48
#endif

/* Bytes for encoded service requests waiting for their turn (one is outstanding at a time). */
#ifndef UBII_SERVICE_QUEUE_BYTES
#define UBII_SERVICE_QUEUE_BYTES 4096
#endif

/* Service requests that can wait at once (including the one outstanding). */
#ifndef UBII_SERVICE_QUEUE_DEPTH
#define UBII_SERVICE_QUEUE_DEPTH 8
#endif

/* Largest message, either way: a record (TopicData) a node publishes above it is refused with
 * UBII_ERR_TOO_LARGE before it reaches the port. It is also the Linux port's default limit for what
 * arrives (ubii_linux_port_options.max_message_size), where a larger message ends the connection;
 * the embedded port has its own, smaller buffers (UBII_EMBEDDED_MAX_MESSAGE) and drops and counts
 * what does not fit. An RGBA8 Image2D of W x H pixels takes 4*W*H bytes plus about 30: 2000 x 2000
 * fits in 16 MiB, 2048 x 2048 (exactly 16 MiB of pixels) does not. */
#ifndef UBII_MAX_MESSAGE_SIZE
#define UBII_MAX_MESSAGE_SIZE (16u * 1024u * 1024u)
#endif

/* Thread steps one regex search may take before it gives up (UBII_ERR_TIMEOUT). The matcher is
 * an automaton (linear in the topic's length), so this only bounds very long topics and patterns.
 */
#ifndef UBII_REGEX_STEP_LIMIT
#define UBII_REGEX_STEP_LIMIT 100000
#endif

/* Instructions and character classes a compiled regex may have (on the stack while matching). */
#ifndef UBII_REGEX_MAX_PROGRAM
#define UBII_REGEX_MAX_PROGRAM 256
#endif
#ifndef UBII_REGEX_MAX_CLASSES
#define UBII_REGEX_MAX_CLASSES 16
#endif

#endif

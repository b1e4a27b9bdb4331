/* A node on the Linux port, built against an installed libubii as a program (main) or as a plugin
 * .so (CONSUMER_PLUGIN: one exported entry point, loaded by consumer_plugin_host.c). Linked with
 * `pkg-config ubii-static`, libubii goes inside either, and a plugin exports only its own entry
 * point. Nothing is connected: the port is created and the node initialised and started. */
#include <stdio.h>

#include "ubii/port_linux.h"
#include "ubii/ubii.h"

static int start_a_node(const char *who)
{
    ubii_linux_port *port = NULL;
    if (ubii_linux_port_create(&port, NULL) != UBII_OK) {
        fprintf(stderr, "%s: no Linux port\n", who);
        return 1;
    }
    ubii_config config;
    ubii_config_init(&config);
    config.service_url = "tcp://127.0.0.1:9";
    config.topic_url = "tcp://127.0.0.1:9";
    static ubii_node node;
    int failed =
        ubii_node_init(&node, sizeof node, &config, ubii_linux_port_get(port)) != UBII_OK ||
        ubii_node_start(&node) != UBII_OK || ubii_node_poll(&node, 0) != UBII_OK;
    ubii_node_stop_wait(&node, 100);
    ubii_linux_port_destroy(port);
    if (failed) {
        fprintf(stderr, "%s: the node did not start\n", who);
        return 1;
    }
    printf("%s: libubii %s started a node on the Linux port\n", who, ubii_version());
    return 0;
}

#ifdef CONSUMER_PLUGIN
__attribute__((visibility("default"))) int consumer_plugin_run(void)
{
    return start_a_node("consumer plugin");
}
#else
int main(void)
{
    return start_a_node("consumer_port");
}
#endif

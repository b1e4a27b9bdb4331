/* services: lists what a master offers: its services, the topics holding data, and its clients.
 *
 *   services [SERVICE_URL [TOPIC_URL]]   defaults: tcp://127.0.0.1:8101 tcp://127.0.0.1:8103 */
#include <stdio.h>
#include <string.h>
#include <time.h>

#include <pb_decode.h>

#include "example_args.h"
#include "ubii/clients/client.pb.h"
#include "ubii/port_linux.h"
#include "ubii/services/service.pb.h"
#include "ubii/ubii.h"

static int pending = 0;

static void print_services(ubii_node *node, const ubii_reply *reply, void *user)
{
    (void)node;
    (void)user;
    pending--;
    if (reply->status != UBII_OK) {
        printf("service list: %s %s\n", ubii_strerror(reply->status), reply->error_message);
        return;
    }
    printf("services:\n");
    ubii_field_iter it;
    const uint8_t *bytes;
    size_t size;
    ubii_field_iter_init(&it, reply->bytes, reply->size, 1);
    while (ubii_field_iter_next(&it, &bytes, &size)) {
        ubii_services_Service service = ubii_services_Service_init_zero;
        pb_istream_t stream = pb_istream_from_buffer(bytes, size);
        if (pb_decode(&stream, ubii_services_Service_fields, &service)) {
            printf("  %-55s %s -> %s\n", service.topic, service.request_message_format,
                   service.response_message_format);
        }
    }
}

static void print_topics(ubii_node *node, const ubii_reply *reply, void *user)
{
    (void)node;
    (void)user;
    pending--;
    if (reply->status != UBII_OK) {
        printf("topic list: %s %s\n", ubii_strerror(reply->status), reply->error_message);
        return;
    }
    printf("topics (services first, then topics holding data):\n");
    ubii_field_iter it;
    const uint8_t *text;
    size_t length;
    ubii_field_iter_init(&it, reply->bytes, reply->size, 1);
    while (ubii_field_iter_next(&it, &text, &length)) {
        printf("  %.*s\n", (int)length, (const char *)text);
    }
}

static void print_clients(ubii_node *node, const ubii_reply *reply, void *user)
{
    (void)user;
    pending--;
    if (reply->status != UBII_OK) {
        printf("client list: %s %s\n", ubii_strerror(reply->status), reply->error_message);
        return;
    }
    printf("clients:\n");
    ubii_field_iter it;
    const uint8_t *bytes;
    size_t size;
    ubii_field_iter_init(&it, reply->bytes, reply->size, 1);
    while (ubii_field_iter_next(&it, &bytes, &size)) {
        ubii_clients_Client client = ubii_clients_Client_init_zero;
        pb_istream_t stream = pb_istream_from_buffer(bytes, size);
        if (pb_decode(&stream, ubii_clients_Client_fields, &client)) {
            printf("  %s  %s%s\n", client.id, client.name,
                   strcmp(client.id, ubii_node_client_id(node)) == 0 ? "  (this example)" : "");
        }
    }
}

int main(int argc, char **argv)
{
    example_args args = example_parse_args(argc, argv, 0);
    ubii_linux_port_options options = {0};
    options.libwebsockets_log_level = 1;
    ubii_linux_port *port = NULL;
    if (ubii_linux_port_create(&port, &options) != UBII_OK) {
        return 1;
    }
    ubii_config config;
    ubii_config_init(&config);
    config.service_url = args.service_url;
    config.topic_url = args.topic_url;
    config.client_name = "libubii-example-services";
    static ubii_node node;
    ubii_node_init(&node, sizeof node, &config, ubii_linux_port_get(port));
    ubii_node_start(&node);

    time_t deadline = time(NULL) + 10;
    while (ubii_node_state(&node) != UBII_STATE_READY && time(NULL) < deadline) {
        ubii_node_poll(&node, 50);
    }
    if (ubii_node_state(&node) != UBII_STATE_READY) {
        fprintf(stderr, "services: could not connect to %s\n", args.service_url);
        return 1;
    }
    ubii_call_topic(&node, UBII_SERVICE_SERVICE_LIST, 0, print_services, NULL);
    ubii_call_topic(&node, UBII_SERVICE_TOPIC_LIST, 0, print_topics, NULL);
    ubii_call_topic(&node, UBII_SERVICE_CLIENT_LIST, 0, print_clients, NULL);
    pending = 3;
    while (pending > 0 && time(NULL) < deadline) {
        ubii_node_poll(&node, 50);
    }
    ubii_node_stop_wait(&node, 2000);
    ubii_linux_port_destroy(port);
    return pending == 0 ? 0 : 1;
}

/* services: lists what a master offers: its services, the topics holding data, and its clients.
 *
 *   services [SERVICE_URL [TOPIC_URL]]   defaults: tcp://127.0.0.1:8101 tcp://127.0.0.1:8103 */
#include <stdbool.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "example_connect.h"
#include "example_port.h"
#include "ubii/clients/client.pb.h"
#include "ubii/services/service.pb.h"
#include "ubii/ubii.h"

static int pending = 0;
static bool client_list_offered = false;

static bool print_service(const void *element, void *user)
{
    (void)user;
    const ubii_services_Service *service = element;
    printf("  %-55s %s -> %s\n", service->topic, service->request_message_format,
           service->response_message_format);
    if (strcmp(service->topic, UBII_SERVICE_CLIENT_LIST) == 0) {
        client_list_offered = true;
    }
    return true;
}

static void print_services(ubii_node *node, const ubii_reply *reply, void *user)
{
    (void)node;
    (void)user;
    pending--;
    printf("services:\n");
    ubii_services_Service service = ubii_services_Service_init_zero;
    ubii_status status =
        ubii_reply_for_each(reply, ubii_services_ServiceReply_service_list_tag, 1,
                            ubii_services_Service_fields, &service, print_service, NULL);
    if (status != UBII_OK) {
        printf("service list: %s %s\n", ubii_strerror(status), reply->error_message);
    }
}

static bool print_text(const char *text, size_t length, void *user)
{
    (void)user;
    printf("  %.*s\n", (int)length, text);
    return true;
}

static void print_topics(ubii_node *node, const ubii_reply *reply, void *user)
{
    (void)node;
    (void)user;
    pending--;
    printf("topics (services first, then topics holding data):\n");
    ubii_status status = ubii_reply_for_each_string(
        reply, ubii_services_ServiceReply_string_list_tag, print_text, NULL);
    if (status != UBII_OK) {
        printf("topic list: %s %s\n", ubii_strerror(status), reply->error_message);
    }
}

static bool print_client(const void *element, void *node)
{
    const ubii_clients_Client *client = element;
    printf("  %s  %s%s\n", client->id, client->name,
           strcmp(client->id, ubii_node_client_id(node)) == 0 ? "  (this example)" : "");
    return true;
}

static void print_clients(ubii_node *node, const ubii_reply *reply, void *user)
{
    (void)user;
    pending--;
    printf("clients:\n");
    ubii_clients_Client client = ubii_clients_Client_init_zero;
    ubii_status status =
        ubii_reply_for_each(reply, ubii_services_ServiceReply_client_list_tag, 1,
                            ubii_clients_Client_fields, &client, print_client, node);
    if (status != UBII_OK) {
        printf("client list: %s %s\n", ubii_strerror(status), reply->error_message);
    }
}

int main(int argc, char **argv)
{
    example_args args = example_parse_args(argc, argv, 0);
    static example_port port;
    if (!example_port_open(&port)) {
        return 1;
    }
    static ubii_node node;
    time_t deadline = time(NULL) + 10;
    if (!example_connect(&node, example_port_get(&port), &args, "libubii-example-services",
                         deadline)) {
        example_port_close(&port);
        return 1;
    }
    ubii_call_topic(&node, UBII_SERVICE_SERVICE_LIST, 0, print_services, NULL);
    ubii_call_topic(&node, UBII_SERVICE_TOPIC_LIST, 0, print_topics, NULL);
    pending = 2;
    while (pending > 0 && time(NULL) < deadline) {
        ubii_node_poll(&node, 50);
    }
    /* The npm 0.4.0 master has no client list service; ask only a master that lists one. */
    if (pending == 0 && client_list_offered) {
        ubii_call_topic(&node, UBII_SERVICE_CLIENT_LIST, 0, print_clients, NULL);
        pending = 1;
        while (pending > 0 && time(NULL) < deadline) {
            ubii_node_poll(&node, 50);
        }
    } else if (pending == 0) {
        printf("clients: this master has no client list service (%s)\n", UBII_SERVICE_CLIENT_LIST);
    }
    ubii_node_stop_wait(&node, 2000);
    example_port_close(&port);
    return pending == 0 ? 0 : 1;
}

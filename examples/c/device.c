/* device: registers a device with two components (a thermometer that publishes its readings and
 * takes a unit), prints what the master made of it, and deregisters it.
 *
 *   device [SERVICE_URL [TOPIC_URL]]   defaults: tcp://127.0.0.1:8101 tcp://127.0.0.1:8103 */
#include <stdbool.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "example_connect.h"
#include "example_port.h"
#include "ubii/ubii.h"

typedef struct registration {
    bool done;
    ubii_status status;
    char device_id[sizeof((ubii_devices_Device *)0)->id];
    int components;
} registration;

static bool print_component(const void *element, void *user)
{
    const ubii_devices_Component *component = element;
    registration *result = user;
    result->components++;
    printf("  component %-32s %-10s %-9s %s\n", component->topic, component->message_format,
           component->io_type == ubii_devices_Component_IOType_PUBLISHER ? "publisher"
                                                                         : "subscriber",
           component->id);
    return true;
}

static void on_registered(ubii_node *node, const ubii_reply *reply, void *user)
{
    (void)node;
    registration *result = user;
    result->done = true;
    ubii_devices_Device device;
    memset(&device, 0, sizeof device);
    result->status = ubii_reply_decode(reply, ubii_services_ServiceReply_device_tag,
                                       ubii_devices_Device_fields, &device);
    if (result->status != UBII_OK) {
        printf("registration: %s %s\n", ubii_strerror(result->status), reply->error_message);
        return;
    }
    snprintf(result->device_id, sizeof result->device_id, "%s", device.id);
    printf("registered device \"%s\" as %s\n", device.name, device.id);
    ubii_devices_Component component = ubii_devices_Component_init_zero;
    result->status = ubii_reply_for_each(
        reply, ubii_services_ServiceReply_device_tag, ubii_devices_Device_components_tag,
        ubii_devices_Component_fields, &component, print_component, result);
    printf("the master holds %d components for it\n", result->components);
}

static void on_deregistered(ubii_node *node, const ubii_reply *reply, void *user)
{
    (void)node;
    registration *result = user;
    result->done = true;
    result->status = reply->status;
    printf("deregistered: %s\n", ubii_strerror(reply->status));
}

static bool poll_until_done(ubii_node *node, const registration *result, time_t deadline)
{
    while (!result->done && time(NULL) < deadline) {
        ubii_node_poll(node, 50);
    }
    return result->done;
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
    if (!example_connect(&node, example_port_get(&port), &args, "libubii-example-device",
                         deadline)) {
        example_port_close(&port);
        return 1;
    }

    ubii_devices_Device device;
    memset(&device, 0, sizeof device);
    snprintf(device.name, sizeof device.name, "libubii example thermometer");
    ubii_devices_Component components[2];
    memset(components, 0, sizeof components);
    snprintf(components[0].topic, sizeof components[0].topic, "/example/thermometer/celsius");
    snprintf(components[0].message_format, sizeof components[0].message_format, "double");
    components[0].io_type = ubii_devices_Component_IOType_PUBLISHER;
    snprintf(components[1].topic, sizeof components[1].topic, "/example/thermometer/unit");
    snprintf(components[1].message_format, sizeof components[1].message_format, "string");
    components[1].io_type = ubii_devices_Component_IOType_SUBSCRIBER;

    registration registered = {0};
    ubii_status status = ubii_register_device_with_components(&node, &device, components, 2, 0,
                                                              on_registered, &registered);
    bool ok = status == UBII_OK && poll_until_done(&node, &registered, deadline) &&
              registered.status == UBII_OK;
    if (ok) {
        registration removed = {0};
        ok = ubii_deregister_device(&node, registered.device_id, 0, on_deregistered, &removed) ==
                 UBII_OK &&
             poll_until_done(&node, &removed, deadline) && removed.status == UBII_OK;
    }
    ubii_node_stop_wait(&node, 2000);
    example_port_close(&port);
    return ok ? 0 : 1;
}

/* libFuzzer target: a ServiceReply from the master, parsed as the node parses it and decoded into
 * the messages the node and applications read from replies. */
#include <string.h>

#include "reply_parse.h"
#include "ubii/devices/component.pb.h"
#include "ubii/devices/device.pb.h"
#include "ubii/servers/server.pb.h"
#include "ubii/service_codec.h"
#include "ubii/wire.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* Reads every byte of what it is handed, so that the sanitizers see a read outside the reply. */
static bool touch_element(const void *element, void *checksum)
{
    const ubii_devices_Component *component = element;
    *(size_t *)checksum += strlen(component->topic) + strlen(component->id);
    return true;
}

static bool touch_text(const char *text, size_t length, void *checksum)
{
    for (size_t i = 0; i < length; ++i) {
        *(size_t *)checksum += (unsigned char)text[i];
    }
    return true;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    ubii_reply reply;
    ubii_general_Error error;
    ubii__parse_reply(data, size, &reply, &error);
    ubii_servers_Server server = ubii_servers_Server_init_zero;
    ubii_reply_decode(&reply, ubii_services_ServiceReply_server_tag, ubii_servers_Server_fields,
                      &server);
    ubii_clients_Client client = ubii_clients_Client_init_zero;
    ubii_reply_decode(&reply, ubii_services_ServiceReply_client_tag, ubii_clients_Client_fields,
                      &client);
    ubii_devices_Device device = ubii_devices_Device_init_zero;
    ubii_reply_decode(&reply, ubii_services_ServiceReply_device_tag, ubii_devices_Device_fields,
                      &device);
    ubii_broker_error broker;
    ubii_decode_server_reply(data, size, &server, &broker);
    ubii_field_iter it;
    const uint8_t *element;
    size_t element_size;
    ubii_field_iter_init(&it, reply.bytes, reply.size, 1);
    while (ubii_field_iter_next(&it, &element, &element_size)) {
    }
    size_t checksum = 0;
    ubii_devices_Component component = ubii_devices_Component_init_zero;
    ubii_reply_for_each(&reply, reply.member, ubii_devices_Device_components_tag,
                        ubii_devices_Component_fields, &component, touch_element, &checksum);
    ubii_reply_for_each(&reply, reply.member, 1, ubii_devices_Component_fields, &component,
                        touch_element, &checksum);
    ubii_reply_for_each_string(&reply, reply.member, touch_text, &checksum);
    return checksum == (size_t)-1; /* keeps the reads from being optimised away */
}

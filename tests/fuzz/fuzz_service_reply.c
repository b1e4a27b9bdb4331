/* libFuzzer target: a ServiceReply from the master, parsed as the node parses it and decoded into
 * the messages the node and applications read from replies. */
#include "node_internal.h"
#include "ubii/devices/device.pb.h"
#include "ubii/servers/server.pb.h"
#include "ubii/service_codec.h"
#include "ubii/wire.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

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
    return 0;
}

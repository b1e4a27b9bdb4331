/* Device registration (ubii/devices.h; full schema only): service calls for this client. */
#include <string.h>

#include <pb_encode.h>

#include "copy_string.h"
#include "ubii/devices.h"

/* A device service request for this client; the caller fills in the rest of the device. */
static void device_request(const char *service, ubii_services_ServiceRequest *request)
{
    memset(request, 0, sizeof *request);
    ubii__copy_string(request->topic, sizeof request->topic, service);
    request->which_type = ubii_services_ServiceRequest_device_tag;
}

static ubii_status call_for_this_client(ubii_node *node, ubii_services_ServiceRequest *request,
                                        uint32_t timeout_ms, ubii_reply_fn fn, void *user)
{
    ubii__copy_string(request->type.device.client_id, sizeof request->type.device.client_id,
                      node->client_id);
    return ubii_call(node, request, timeout_ms, fn, user);
}

ubii_status ubii_register_device(ubii_node *node, const ubii_devices_Device *device,
                                 uint32_t timeout_ms, ubii_reply_fn fn, void *user)
{
    if (node == NULL || device == NULL) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    ubii_services_ServiceRequest request;
    device_request(UBII_SERVICE_DEVICE_REGISTRATION, &request);
    request.type.device = *device;
    return call_for_this_client(node, &request, timeout_ms, fn, user);
}

typedef struct component_array {
    const ubii_devices_Component *components;
    size_t count;
} component_array;

static bool encode_components(pb_ostream_t *stream, const pb_field_t *field, void *const *arg)
{
    const component_array *array = *arg;
    for (size_t i = 0; i < array->count; ++i) {
        if (!pb_encode_tag_for_field(stream, field) ||
            !pb_encode_submessage(stream, ubii_devices_Component_fields, &array->components[i])) {
            return false;
        }
    }
    return true;
}

ubii_status ubii_register_device_with_components(ubii_node *node, const ubii_devices_Device *device,
                                                 const ubii_devices_Component *components,
                                                 size_t component_count, uint32_t timeout_ms,
                                                 ubii_reply_fn fn, void *user)
{
    if (node == NULL || device == NULL || (components == NULL && component_count > 0)) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    ubii_services_ServiceRequest request;
    device_request(UBII_SERVICE_DEVICE_REGISTRATION, &request);
    request.type.device = *device;
    /* ubii_call encodes the request into the queue before it returns: the array on this stack
     * frame outlives its use. */
    component_array array = {components, component_count};
    request.type.device.components.funcs.encode = encode_components;
    request.type.device.components.arg = &array;
    return call_for_this_client(node, &request, timeout_ms, fn, user);
}

ubii_status ubii_deregister_device(ubii_node *node, const char *device_id, uint32_t timeout_ms,
                                   ubii_reply_fn fn, void *user)
{
    if (node == NULL || device_id == NULL) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    ubii_services_ServiceRequest request;
    device_request(UBII_SERVICE_DEVICE_DEREGISTRATION, &request);
    if (!ubii__copy_string(request.type.device.id, sizeof request.type.device.id, device_id)) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    return call_for_this_client(node, &request, timeout_ms, fn, user);
}

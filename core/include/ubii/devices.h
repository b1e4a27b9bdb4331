#ifndef UBII_DEVICES_H
#define UBII_DEVICES_H

/* Registering devices (and their components) for this client. Full schema only (UBII_SCHEMA=full,
 * proto/schemas/): a reduced schema has no Device in its ServiceRequest, and including this header
 * fails there (ubii/devices/device.pb.h is not generated). ubii/ubii.h includes it when the schema
 * has it. */

#include <stddef.h>
#include <stdint.h>

#include "ubii/export.h"
#include "ubii/service.h"
#include "ubii/devices/device.pb.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Registers `device` for this client (its client_id is filled in). The reply's member is
 * ubii_services_ServiceReply_device_tag with the ids the master assigned. */
UBII_API ubii_status ubii_register_device(ubii_node *node, const ubii_devices_Device *device,
                                          uint32_t timeout_ms, ubii_reply_fn fn, void *user);
/* The same with the device's components (Device.components, a nanopb callback field): the
 * `component_count` elements of `components` are encoded into the request at once, so the array
 * need only live during the call. Each component's own callback fields (tags,
 * notify_condition_ids) are encoded as the caller bound them. Whatever `device->components` holds
 * is replaced. */
UBII_API ubii_status ubii_register_device_with_components(
    ubii_node *node, const ubii_devices_Device *device, const ubii_devices_Component *components,
    size_t component_count, uint32_t timeout_ms, ubii_reply_fn fn, void *user);
UBII_API ubii_status ubii_deregister_device(ubii_node *node, const char *device_id,
                                            uint32_t timeout_ms, ubii_reply_fn fn, void *user);

#ifdef __cplusplus
}
#endif

#endif

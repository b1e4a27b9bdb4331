/* Offering processing modules at registration (ubii/processing.h; full schema only). */
#include <pb_encode.h>

#include "ubii/service.h"
#include "ubii/processing.h"

/* Writes each offered spec as one Client.processing_modules element: the bytes are a serialized
 * ProcessingModule already, so they go out as the field's length-delimited payload. */
static bool encode_offered(pb_ostream_t *stream, const pb_field_t *field, void *const *arg)
{
    const ubii_node *node = (const ubii_node *)*arg;
    const ubii_encoded_message *specs = (const ubii_encoded_message *)node->offered_modules;
    for (size_t i = 0; i < node->offered_module_count; ++i) {
        if (!pb_encode_tag_for_field(stream, field) ||
            !pb_encode_string(stream, specs[i].data, specs[i].size)) {
            return false;
        }
    }
    return true;
}

static void add_offered_modules(ubii_node *node, void *client)
{
    ubii_clients_Client *message = (ubii_clients_Client *)client;
    message->processing_modules.funcs.encode = encode_offered;
    message->processing_modules.arg = node;
}

ubii_status ubii_node_offer_processing_modules(ubii_node *node, const ubii_encoded_message *specs,
                                               size_t count)
{
    if (node == NULL || (specs == NULL && count > 0)) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    for (size_t i = 0; i < count; ++i) {
        if (specs[i].data == NULL && specs[i].size > 0) {
            return UBII_ERR_INVALID_ARGUMENT;
        }
    }
    node->offered_modules = specs;
    node->offered_module_count = count;
    node->complete_registration = count > 0 ? add_offered_modules : NULL;
    return UBII_OK;
}

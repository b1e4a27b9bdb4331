#ifndef UBII_PROCESSING_H
#define UBII_PROCESSING_H

/* Offering processing modules: what this client tells the master at registration so that a
 * session can assign modules to it (docs/PROTOCOL.md §5.1). Full schema only (UBII_SCHEMA=full,
 * proto/schemas/): a reduced schema has no ProcessingModule in its Client. ubii/ubii.h includes
 * it when the schema has it. Running the modules a session assigns is the C++ layer's
 * (ubii::Node::serve_sessions); this is the registration part every client needs. */

#include <stddef.h>
#include <stdint.h>

#include "ubii/export.h"
#include "ubii/node.h"
#include "ubii/processing/processingModule.pb.h"

#ifdef __cplusplus
extern "C" {
#endif

/* One serialized ubii.processing.ProcessingModule (its protobuf bytes, from any encoder: nanopb's
 * pb_encode with ubii_processing_ProcessingModule_fields, or a C++ SerializeToString). */
typedef struct ubii_encoded_message {
    const uint8_t *data;
    size_t size;
} ubii_encoded_message;

/* Sends `specs` as Client.processing_modules at every registration from now on, the first and
 * each one after a reconnect (Client.is_dedicated_processing_node comes from ubii_config). The
 * array and the bytes it points to are not copied: they must stay valid and unchanged while the
 * node may register, until the node is stopped or this is called again (count 0 offers none).
 * The registration request must fit UBII_SERVICE_QUEUE_BYTES: a larger one fails the connection
 * attempt with UBII_ERR_TOO_LARGE, reported through on_error. */
UBII_API ubii_status ubii_node_offer_processing_modules(ubii_node *node,
                                                        const ubii_encoded_message *specs,
                                                        size_t count);

#ifdef __cplusplus
}
#endif

#endif

#ifndef UBII_IMAGE_H
#define UBII_IMAGE_H

/* Records holding an Image2D, read and published without copying the pixels. Full schema only
 * (UBII_SCHEMA=full, proto/schemas/): a reduced schema has no image members, and including this
 * header fails there (ubii/dataStructure/image.pb.h is not generated). ubii/ubii.h includes it when
 * the schema has it. */

#include <stddef.h>
#include <stdint.h>

#include "ubii/export.h"
#include "ubii/topic.h"
#include "ubii/dataStructure/image.pb.h"

#ifdef __cplusplus
extern "C" {
#endif

/* An Image2D without copying its pixels: `data` points into the received message. */
typedef struct ubii_image_view {
    int32_t width;
    int32_t height;
    ubii_dataStructure_Image2D_DataFormat format;
    const uint8_t *data;
    size_t size;
} ubii_image_view;
UBII_API ubii_status ubii_record_image(const ubii_record *record, ubii_image_view *image);

/* One record holding an Image2D, sent as ubii_publish_double does (ubii/topic.h). */
UBII_API ubii_status ubii_publish_image(ubii_node *node, const char *topic, int32_t width,
                                        int32_t height,
                                        ubii_dataStructure_Image2D_DataFormat format,
                                        const uint8_t *data, size_t size);

#ifdef __cplusplus
}
#endif

#endif

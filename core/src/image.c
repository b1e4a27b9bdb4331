/* Records holding an Image2D (ubii/image.h; full schema only): the pixels are neither copied when
 * read nor when written. */
#include <string.h>

#include "publish.h"
#include "ubii/image.h"
#include "wire_scan.h"

enum { IMAGE_WIDTH = 1, IMAGE_HEIGHT = 2, IMAGE_FORMAT = 3, IMAGE_DATA = 4 };

/* ---- reading -----------------------------------------------------------------------------------
 */

ubii_status ubii_record_image(const ubii_record *record, ubii_image_view *image)
{
    if (record == NULL || image == NULL) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    if (record->type != UBII_RECORD_IMAGE2D) {
        return UBII_ERR_WRONG_TYPE;
    }
    memset(image, 0, sizeof *image);
    ubii_wire_scan scan;
    ubii_wire_field field;
    bool malformed = false;
    ubii_wire_scan_init(&scan, record->value, record->value_size);
    while (ubii_wire_scan_next(&scan, &field, &malformed)) {
        bool varint = field.wire_type == PB_WT_VARINT;
        if (field.number == IMAGE_WIDTH && varint) {
            image->width = (int32_t)(uint32_t)field.scalar;
        } else if (field.number == IMAGE_HEIGHT && varint) {
            image->height = (int32_t)(uint32_t)field.scalar;
        } else if (field.number == IMAGE_FORMAT && varint) {
            image->format = (ubii_dataStructure_Image2D_DataFormat)field.scalar;
        } else if (field.number == IMAGE_DATA && field.wire_type == PB_WT_STRING) {
            image->data = field.bytes;
            image->size = field.size;
        }
    }
    return malformed ? UBII_ERR_DECODE : UBII_OK;
}

/* ---- publishing ------------------------------------------------------------------------------
 */

typedef struct image_value {
    int32_t width;
    int32_t height;
    ubii_dataStructure_Image2D_DataFormat format;
    const uint8_t *data;
    size_t size;
} image_value;

static bool write_image_body(pb_ostream_t *stream, const void *value)
{
    const image_value *image = value;
    /* proto3: fields at their default value are left out, as every other encoder does. */
    return (image->width == 0 || (pb_encode_tag(stream, PB_WT_VARINT, 1) &&
                                  pb_encode_varint(stream, (uint64_t)(int64_t)image->width))) &&
           (image->height == 0 || (pb_encode_tag(stream, PB_WT_VARINT, 2) &&
                                   pb_encode_varint(stream, (uint64_t)(int64_t)image->height))) &&
           (image->format == 0 || (pb_encode_tag(stream, PB_WT_VARINT, 3) &&
                                   pb_encode_varint(stream, (uint64_t)image->format))) &&
           (image->size == 0 || (pb_encode_tag(stream, PB_WT_STRING, 4) &&
                                 pb_encode_string(stream, image->data, image->size)));
}

ubii_status ubii_publish_image(ubii_node *node, const char *topic, int32_t width, int32_t height,
                               ubii_dataStructure_Image2D_DataFormat format, const uint8_t *data,
                               size_t size)
{
    if ((data == NULL && size > 0) || width < 0 || height < 0) {
        return UBII_ERR_INVALID_ARGUMENT;
    }
    image_value image = {width, height, format, data, size};
    return ubii__publish_body(node, topic, UBII_RECORD_IMAGE2D, write_image_body, &image);
}

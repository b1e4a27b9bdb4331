#ifndef UBII_OCR_OBJECT_RECORDS_HPP
#define UBII_OCR_OBJECT_RECORDS_HPP

// Recognised text as Ubi-Interact Object2DList records. The convention (ocr/README.md):
//   Object2D.id             the recognised text (UTF-8)
//   Object2D.pose.position  top-left corner of the axis-aligned box, in pixels of the input image
//                           (x to the right, y down); pose.orientation is not set
//   Object2D.size           the axis-aligned box's width and height, in pixels
//   Object2D.user_data_json {"confidence":87.5} (Tesseract's 0..100); for EAST boxes also
//                           "rotated_box":{"center":[x,y],"size":[w,h],"angle":degrees}
// The list has one element per TextBox, in the pipeline's order. Strings and the list are nanopb
// callbacks (proto/README.md rule 2), so neither the text length nor the number of boxes is
// limited.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "ubii/ocr/text_box.hpp"
#include "ubii/topic.h"

namespace ubii::ocr
{

// An Object2DList ready to publish:
//     Object2DListMessage message(boxes);
//     ubii_publish_message(node, topic, UBII_RECORD_OBJECT2D_LIST,
//                          ubii_dataStructure_Object2DList_fields, message.get());
// The nanopb struct's callbacks point into this object, which therefore cannot be copied or moved;
// it keeps its own copy of the boxes.
class Object2DListMessage
{
  public:
    explicit Object2DListMessage(std::vector<TextBox> boxes);
    Object2DListMessage(const Object2DListMessage &) = delete;
    Object2DListMessage &operator=(const Object2DListMessage &) = delete;

    const ubii_dataStructure_Object2DList *get() const
    {
        return &message_;
    }
    const std::vector<TextBox> &boxes() const
    {
        return boxes_;
    }
    // The message's protobuf bytes (what a record's object2D_list member holds).
    std::vector<std::uint8_t> encode() const;

  private:
    static bool encode_elements(pb_ostream_t *stream, const pb_field_t *field, void *const *arg);

    std::vector<TextBox> boxes_;
    std::vector<std::string> user_data_json_; // one per box, made once: nanopb encodes twice
    ubii_dataStructure_Object2DList message_;
};

// Reads an encoded Object2DList back into boxes. Text and box come from id, pose and size;
// confidence (and the rotated box) from user_data_json; an element without a confidence there
// gets NaN. Throws InvalidArgument if the bytes are not an Object2DList.
std::vector<TextBox> decode_object2d_list(const std::uint8_t *bytes, std::size_t size);
// The same for a received record; InvalidArgument unless it holds an Object2DList.
std::vector<TextBox> decode_object2d_list(const ubii_record &record);

} // namespace ubii::ocr

#endif

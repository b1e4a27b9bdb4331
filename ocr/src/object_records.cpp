#include "ubii/ocr/object_records.hpp"

#include <cmath>
#include <string>

#include <pb_decode.h>
#include <pb_encode.h>

#include "ubii/dataStructure/object2d.pb.h"
#include "ubii/ocr/error.hpp"
#include "user_data_json.hpp"

namespace ubii::ocr
{
namespace
{

// nanopb is C: no exception may unwind through it, so every callback catches and reports false.

bool encode_text(pb_ostream_t *stream, const pb_field_t *field, void *const *arg)
{
    const auto *text = static_cast<const std::string *>(*arg);
    return pb_encode_tag_for_field(stream, field) &&
           pb_encode_string(stream, reinterpret_cast<const pb_byte_t *>(text->data()),
                            text->size());
}

int to_pixels(double value)
{
    return static_cast<int>(std::lround(value));
}

bool decode_text(pb_istream_t *stream, const pb_field_t *, void **arg)
{
    try {
        auto *text = static_cast<std::string *>(*arg);
        text->resize(stream->bytes_left);
        return pb_read(stream, reinterpret_cast<pb_byte_t *>(text->data()), text->size());
    } catch (...) {
        return false;
    }
}

bool decode_element(pb_istream_t *stream, const pb_field_t *, void **arg)
{
    try {
        auto *boxes = static_cast<std::vector<TextBox> *>(*arg);
        std::string text, json;
        ubii_dataStructure_Object2D object = ubii_dataStructure_Object2D_init_zero;
        object.id.funcs.decode = decode_text;
        object.id.arg = &text;
        object.user_data_json.funcs.decode = decode_text;
        object.user_data_json.arg = &json;
        if (!pb_decode(stream, ubii_dataStructure_Object2D_fields, &object))
            return false;
        TextBox box{std::move(text), 0.0f,
                    cv::Rect(to_pixels(object.pose.position.x), to_pixels(object.pose.position.y),
                             to_pixels(object.size.x), to_pixels(object.size.y)),
                    std::nullopt};
        detail::read_user_data_json(json, box);
        boxes->push_back(std::move(box));
        return true;
    } catch (...) {
        return false;
    }
}

} // namespace

Object2DListMessage::Object2DListMessage(std::vector<TextBox> boxes)
    : boxes_(std::move(boxes)), message_(ubii_dataStructure_Object2DList_init_zero)
{
    user_data_json_.reserve(boxes_.size());
    for (const auto &box : boxes_)
        user_data_json_.push_back(detail::user_data_json(box));
    message_.elements.funcs.encode = encode_elements;
    message_.elements.arg = this;
}

bool Object2DListMessage::encode_elements(pb_ostream_t *stream, const pb_field_t *field,
                                          void *const *arg)
{
    const auto *self = static_cast<const Object2DListMessage *>(*arg);
    for (std::size_t i = 0; i < self->boxes_.size(); ++i) {
        const TextBox &box = self->boxes_[i];
        ubii_dataStructure_Object2D object = ubii_dataStructure_Object2D_init_zero;
        object.id.funcs.encode = encode_text;
        object.id.arg = const_cast<std::string *>(&box.text);
        object.has_pose = true;
        object.pose.has_position = true;
        object.pose.position.x = box.box.x;
        object.pose.position.y = box.box.y;
        object.has_size = true;
        object.size.x = box.box.width;
        object.size.y = box.box.height;
        object.user_data_json.funcs.encode = encode_text;
        object.user_data_json.arg = const_cast<std::string *>(&self->user_data_json_[i]);
        if (!pb_encode_tag_for_field(stream, field) ||
            !pb_encode_submessage(stream, ubii_dataStructure_Object2D_fields, &object))
            return false;
    }
    return true;
}

std::vector<std::uint8_t> Object2DListMessage::encode() const
{
    std::size_t size = 0;
    if (!pb_get_encoded_size(&size, ubii_dataStructure_Object2DList_fields, &message_))
        throw Error("could not size the Object2DList");
    std::vector<std::uint8_t> bytes(size);
    pb_ostream_t stream = pb_ostream_from_buffer(bytes.data(), bytes.size());
    if (!pb_encode(&stream, ubii_dataStructure_Object2DList_fields, &message_))
        throw Error(std::string("could not encode the Object2DList: ") + PB_GET_ERROR(&stream));
    return bytes;
}

std::vector<TextBox> decode_object2d_list(const std::uint8_t *bytes, std::size_t size)
{
    std::vector<TextBox> boxes;
    ubii_dataStructure_Object2DList list = ubii_dataStructure_Object2DList_init_zero;
    list.elements.funcs.decode = decode_element;
    list.elements.arg = &boxes;
    pb_istream_t stream = pb_istream_from_buffer(bytes, size);
    if (!pb_decode(&stream, ubii_dataStructure_Object2DList_fields, &list))
        throw InvalidArgument(std::string("not an Object2DList: ") + PB_GET_ERROR(&stream));
    return boxes;
}

std::vector<TextBox> decode_object2d_list(const ubii_record &record)
{
    if (record.type != UBII_RECORD_OBJECT2D_LIST)
        throw InvalidArgument("record on '" + std::string(record.topic) + "' holds member " +
                              std::to_string(static_cast<int>(record.type)) +
                              ", not an Object2DList");
    return decode_object2d_list(record.value, record.value_size);
}

} // namespace ubii::ocr

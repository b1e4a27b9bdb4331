#include "ubii/record.hpp"

#include <limits>
#include <utility>

#include "ubii/image.h"
#include "ubii/topic.h"

namespace ubii
{

namespace
{

template <class T> T decode_member(const ubii_record &record)
{
    if constexpr (std::is_same_v<T, double>) {
        double value = 0;
        check(ubii_record_double(&record, &value), "a double record");
        return value;
    } else if constexpr (std::is_same_v<T, float>) {
        float value = 0;
        check(ubii_record_float(&record, &value), "a float record");
        return value;
    } else if constexpr (std::is_same_v<T, std::int32_t>) {
        std::int32_t value = 0;
        check(ubii_record_int32(&record, &value), "an int32 record");
        return value;
    } else if constexpr (std::is_same_v<T, bool>) {
        bool value = false;
        check(ubii_record_bool(&record, &value), "a bool record");
        return value;
    } else if constexpr (std::is_same_v<T, std::string>) {
        const char *text = nullptr;
        std::size_t length = 0;
        check(ubii_record_string(&record, &text, &length), "a string record");
        return std::string(text, length);
    } else {
        T message;
        if (record.value_size > static_cast<std::size_t>(std::numeric_limits<int>::max()) ||
            !message.ParseFromArray(record.value, static_cast<int>(record.value_size)))
            throw DecodeError(std::string("the ") + T::descriptor()->full_name() + " on " +
                              record.topic + " is not valid protobuf");
        return message;
    }
}

} // namespace

Value decode_value(const ubii_record &record)
{
    switch (static_cast<RecordType>(record.type)) {
#define UBII_CPP_DECODE_CASE(upper, number, name, format, cpp_type)                                \
    case RecordType::upper:                                                                        \
        return Value(RecordType::upper, decode_member<cpp_type>(record));
        UBII_RECORD_MEMBER_LIST(UBII_CPP_DECODE_CASE)
#undef UBII_CPP_DECODE_CASE
    case RecordType::NONE:
        break;
    }
    return Value();
}

Image2D ImageView::to_image() const
{
    Image2D image;
    image.set_width(width);
    image.set_height(height);
    image.set_data_format(format);
    image.set_data(data, size);
    return image;
}

Record::Record(std::string topic, Value value)
    : type_(value.type()), value_(std::move(value)), topic_storage_(std::move(topic))
{
    point_at_storage();
}

Record::Record(const Record &other)
{
    take(other);
}

Record::Record(Record &&other) noexcept
{
    *this = std::move(other);
}

Record &Record::operator=(const Record &other)
{
    if (this != &other)
        take(other);
    return *this;
}

Record &Record::operator=(Record &&other) noexcept
{
    if (this == &other)
        return *this;
    if (other.lent_ != nullptr) {
        // A lent record's bytes are not ours to keep: copy them. A value that cannot be decoded
        // becomes no value rather than an exception in a noexcept move.
        try {
            take(other);
        } catch (...) {
            topic_storage_.assign(other.topic_);
            client_id_storage_.assign(other.client_id_);
            timestamp_ = other.timestamp_;
            type_ = RecordType::NONE;
            value_ = Value();
            decoded_ = true;
            lent_ = nullptr;
            point_at_storage();
        }
        return *this;
    }
    topic_storage_ = std::move(other.topic_storage_);
    client_id_storage_ = std::move(other.client_id_storage_);
    timestamp_ = other.timestamp_;
    type_ = other.type_;
    value_ = std::move(other.value_);
    decoded_ = true;
    lent_ = nullptr;
    point_at_storage();
    other.point_at_storage();
    return *this;
}

void Record::take(const Record &other)
{
    Value value = other.value(); // decodes a lent record first: may throw, changing nothing
    topic_storage_.assign(other.topic_);
    client_id_storage_.assign(other.client_id_);
    timestamp_ = other.timestamp_;
    type_ = other.type_;
    value_ = std::move(value);
    decoded_ = true;
    lent_ = nullptr;
    point_at_storage();
}

void Record::point_at_storage() noexcept
{
    topic_ = topic_storage_;
    client_id_ = client_id_storage_;
}

Record Record::lend(const ubii_record &record) noexcept
{
    Record lent;
    lent.topic_ = record.topic != nullptr ? record.topic : "";
    lent.client_id_ = record.client_id != nullptr ? record.client_id : "";
    if (record.has_timestamp)
        lent.timestamp_ =
            Timestamp{record.timestamp_seconds, record.timestamp_nanos, record.timestamp_millis};
    lent.type_ = static_cast<RecordType>(record.type);
    lent.lent_ = &record;
    lent.decoded_ = false;
    return lent;
}

const Value &Record::value() const
{
    if (!decoded_) {
        value_ = decode_value(*lent_);
        decoded_ = true;
    }
    return value_;
}

ImageView Record::image() const
{
    if (lent_ != nullptr) {
        ubii_image_view view = {};
        const ubii_status status = ubii_record_image(lent_, &view);
        if (status == UBII_ERR_WRONG_TYPE)
            throw WrongType("the record on " + std::string(topic_) + " holds " +
                            std::string(record_type_name(type_)) + ", not image2D");
        check(status, "an image record");
        return ImageView{view.width, view.height, static_cast<Image2D::DataFormat>(view.format),
                         view.data, view.size};
    }
    const Image2D &image = as<Image2D>();
    return ImageView{image.width(), image.height(), image.data_format(),
                     reinterpret_cast<const std::uint8_t *>(image.data().data()),
                     image.data().size()};
}

void Record::set_topic(std::string topic)
{
    topic_storage_ = std::move(topic);
    topic_ = topic_storage_;
}

void Record::set_value(Value new_value)
{
    if (lent_ != nullptr) { // keep nothing of the message it viewed
        topic_storage_.assign(topic_);
        client_id_storage_.assign(client_id_);
        lent_ = nullptr;
        point_at_storage();
    }
    type_ = new_value.type();
    value_ = std::move(new_value);
    decoded_ = true;
}

void Record::set_client_id(std::string client_id)
{
    client_id_storage_ = std::move(client_id);
    client_id_ = client_id_storage_;
}

} // namespace ubii

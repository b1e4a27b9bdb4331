#ifndef UBII_RECORD_HPP
#define UBII_RECORD_HPP

// ubii::Record: a topic, its value (ubii::Value), and what the publisher stamped on it.
//
// A Record built by the application owns everything. A Record handed to a subscription callback is
// lent: it views the received message (no copy, nothing decoded until asked), and is valid only
// during the callback. Copying or moving a lent Record makes an owning one, so keeping a record is
// simply `ubii::Record kept = record;`. Images can be read without copying the pixels while lent
// (image()).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "ubii/messages.hpp"
#include "ubii/value.hpp"

struct ubii_record;

namespace ubii
{

struct Timestamp {
    std::int64_t seconds = 0;
    std::int32_t nanos = 0;
    std::int64_t millis = 0; // Unix epoch milliseconds, as libubii and the official nodes stamp
};

// What a typed subscription callback gets beside the value; views valid during the callback.
struct RecordInfo {
    std::string_view topic;
    std::string_view client_id; // "" unless the publisher set it
    std::optional<Timestamp> timestamp;
};

// An Image2D's header and pixels without copying them.
struct ImageView {
    std::int32_t width = 0;
    std::int32_t height = 0;
    Image2D::DataFormat format = Image2D::GRAY8;
    const std::uint8_t *data = nullptr;
    std::size_t size = 0;

    // An owning copy.
    Image2D to_image() const;
};

class Record
{
  public:
    Record() = default;
    Record(std::string topic, Value value);
    Record(const Record &other);
    Record(Record &&other) noexcept;
    Record &operator=(const Record &other);
    Record &operator=(Record &&other) noexcept;
    ~Record() = default;

    // Lends a record the C core received (valid while `record` is).
    static Record lend(const ubii_record &record) noexcept;

    std::string_view topic() const noexcept
    {
        return topic_;
    }
    std::string_view client_id() const noexcept
    {
        return client_id_;
    }
    const std::optional<Timestamp> &timestamp() const noexcept
    {
        return timestamp_;
    }
    RecordInfo info() const
    {
        return RecordInfo{topic_, client_id_, timestamp_};
    }
    RecordType type() const noexcept
    {
        return type_;
    }
    // The value, decoded on first use for a lent record: ubii::DecodeError if its bytes are not
    // valid protobuf.
    const Value &value() const;
    // The value as a T: ubii::WrongType if the record holds another type.
    template <class T> const T &as() const
    {
        return value().as<T>();
    }
    // The Image2D without copying its pixels (a lent record: valid during the callback).
    // ubii::WrongType unless the record holds IMAGE2D.
    ImageView image() const;
    // Whether this record views a received message (valid only during the callback).
    bool lent() const noexcept
    {
        return lent_ != nullptr;
    }

    void set_topic(std::string topic);
    void set_value(Value new_value);
    void set_client_id(std::string client_id);

  private:
    void take(const Record &other);
    void point_at_storage() noexcept;

    std::string_view topic_;
    std::string_view client_id_;
    std::optional<Timestamp> timestamp_;
    RecordType type_ = RecordType::NONE;
    const ubii_record *lent_ = nullptr;
    mutable Value value_;
    mutable bool decoded_ = true;
    std::string topic_storage_;
    std::string client_id_storage_;
};

// Decodes a lent C record's value (what Record::value() does for lent records).
Value decode_value(const ubii_record &record);

} // namespace ubii

#endif

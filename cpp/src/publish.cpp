#include "publish.hpp"

#include <cstring>

#include "node_core.hpp"
#include "ubii/image.h"

namespace ubii::detail
{

namespace
{

// A topic as the C API takes it: NUL-terminated; a view that is not is copied into a buffer of
// the node's topic limit.
class TopicText
{
  public:
    explicit TopicText(TopicRef topic)
    {
        const std::string_view view = topic.view();
        ok_ = !view.empty() && view.size() < sizeof copy_;
        if (!ok_)
            return;
        if (topic.terminated()) {
            text_ = view.data();
        } else {
            std::memcpy(copy_, view.data(), view.size());
            copy_[view.size()] = '\0';
            text_ = copy_;
        }
    }
    bool ok() const noexcept
    {
        return ok_;
    }
    const char *c_str() const noexcept
    {
        return text_;
    }

  private:
    bool ok_ = false;
    const char *text_ = "";
    char copy_[UBII_MAX_TOPIC_SIZE];
};

} // namespace

#define UBII_CPP_PUBLISH_SCALAR(method, type, c_function)                                          \
    Status method(NodeCore &core, TopicRef topic, type value) noexcept                             \
    {                                                                                              \
        const TopicText text(topic);                                                               \
        if (!text.ok())                                                                            \
            return Status::invalid_argument;                                                       \
        return to_status(c_function(core.c_node(), text.c_str(), value));                          \
    }
UBII_CPP_PUBLISH_SCALAR(publish_double, double, ubii_publish_double)
UBII_CPP_PUBLISH_SCALAR(publish_float, float, ubii_publish_float)
UBII_CPP_PUBLISH_SCALAR(publish_int32, std::int32_t, ubii_publish_int32)
UBII_CPP_PUBLISH_SCALAR(publish_bool, bool, ubii_publish_bool)
#undef UBII_CPP_PUBLISH_SCALAR

Status publish_string(NodeCore &core, TopicRef topic, std::string_view value) noexcept
{
    const TopicText text(topic);
    if (!text.ok())
        return Status::invalid_argument;
    return to_status(ubii_publish_string(core.c_node(), text.c_str(), value.data(), value.size()));
}

Status publish_image(NodeCore &core, TopicRef topic, const ImageView &image) noexcept
{
    const TopicText text(topic);
    if (!text.ok())
        return Status::invalid_argument;
    return to_status(ubii_publish_image(
        core.c_node(), text.c_str(), image.width, image.height,
        static_cast<ubii_dataStructure_Image2D_DataFormat>(image.format), image.data, image.size));
}

Status publish_message(NodeCore &core, TopicRef topic, RecordType type,
                       const google::protobuf::MessageLite &message) noexcept
{
    if (type == RecordType::IMAGE2D) { // the pixels go to the transport without a copy of ours
        const auto &image = static_cast<const Image2D &>(message);
        return publish_image(core, topic,
                             ImageView{image.width(), image.height(), image.data_format(),
                                       reinterpret_cast<const std::uint8_t *>(image.data().data()),
                                       image.data().size()});
    }
    const TopicText text(topic);
    if (!text.ok())
        return Status::invalid_argument;
    std::string &bytes = core.encode_buffer();
    try {
        if (!message.SerializeToString(&bytes))
            return Status::encode;
    } catch (...) { // allocation
        return Status::encode;
    }
    return to_status(
        ubii_publish_encoded(core.c_node(), text.c_str(), static_cast<ubii_record_type>(type),
                             reinterpret_cast<const std::uint8_t *>(bytes.data()), bytes.size()));
}

Status publish_value(NodeCore &core, TopicRef topic, const Value &value) noexcept
{
    const RecordType type = value.type();
    return value.visit([&](const auto &held) -> Status {
        using T = std::decay_t<decltype(held)>;
        if constexpr (std::is_same_v<T, std::monostate>)
            return Status::invalid_argument;
        else if constexpr (std::is_same_v<T, double>)
            return publish_double(core, topic, held);
        else if constexpr (std::is_same_v<T, float>)
            return publish_float(core, topic, held);
        else if constexpr (std::is_same_v<T, std::int32_t>)
            return publish_int32(core, topic, held);
        else if constexpr (std::is_same_v<T, bool>)
            return publish_bool(core, topic, held);
        else if constexpr (std::is_same_v<T, std::string>)
            return publish_string(core, topic, held);
        else
            return publish_message(core, topic, type, held);
    });
}

} // namespace ubii::detail

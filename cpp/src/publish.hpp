#ifndef UBII_CPP_PUBLISH_HPP
#define UBII_CPP_PUBLISH_HPP

// Publishing through the C core, for ubii::Node and for the outputs of processing modules.

#include <cstdint>
#include <string_view>

#include "ubii/error.hpp"
#include "ubii/node.hpp"
#include "ubii/record.hpp"
#include "ubii/value.hpp"

namespace ubii::detail
{

class NodeCore;

Status publish_double(NodeCore &core, TopicRef topic, double value) noexcept;
Status publish_float(NodeCore &core, TopicRef topic, float value) noexcept;
Status publish_int32(NodeCore &core, TopicRef topic, std::int32_t value) noexcept;
Status publish_bool(NodeCore &core, TopicRef topic, bool value) noexcept;
Status publish_string(NodeCore &core, TopicRef topic, std::string_view value) noexcept;
Status publish_image(NodeCore &core, TopicRef topic, const ImageView &image) noexcept;
Status publish_message(NodeCore &core, TopicRef topic, RecordType type,
                       const google::protobuf::MessageLite &message) noexcept;
Status publish_value(NodeCore &core, TopicRef topic, const Value &value) noexcept;

} // namespace ubii::detail

#endif

#include "ubii/record_type.hpp"

#include "ubii/topic.h"

namespace ubii
{

std::string_view record_type_name(RecordType type) noexcept
{
    const char *name = ubii_record_type_name(static_cast<ubii_record_type>(type));
    return name != nullptr ? name : "";
}

std::string_view message_format(RecordType type) noexcept
{
    const char *format = ubii_record_type_format(static_cast<ubii_record_type>(type));
    return format != nullptr ? format : "";
}

RecordType record_type_for_format(std::string_view format) noexcept
{
    try {
        return static_cast<RecordType>(ubii_record_type_for_format(std::string(format).c_str()));
    } catch (...) { // std::string's allocation
        return RecordType::NONE;
    }
}

} // namespace ubii

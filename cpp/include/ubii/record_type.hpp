#ifndef UBII_RECORD_TYPE_HPP
#define UBII_RECORD_TYPE_HPP

// The TopicDataRecord value members, from the table generated out of the schema
// (UBII_RECORD_MEMBER_LIST in ubii/record_types.h): a member added to the .proto file appears here,
// in ubii::Value and in the record conversions without a line of hand-written code.

#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>

#include "ubii/messages.hpp"
#include "ubii/record_types.h"

namespace ubii
{

// The member a record holds; the values are the field numbers (and the C core's ubii_record_type).
enum class RecordType : int {
    NONE = 0,
#define UBII_CPP_RECORD_ENUMERATOR(upper, number, name, format, cpp_type) upper = number,
    UBII_RECORD_MEMBER_LIST(UBII_CPP_RECORD_ENUMERATOR)
#undef UBII_CPP_RECORD_ENUMERATOR
};

// The member's .proto name ("vector3", "object2D_list"); "" for NONE or an unknown value.
std::string_view record_type_name(RecordType type) noexcept;
// Its message format as processing module specs name it ("double", "ubii.dataStructure.Vector3").
std::string_view message_format(RecordType type) noexcept;
// The member holding `format` (the lower field number where two share one); NONE if none does.
RecordType record_type_for_format(std::string_view format) noexcept;

namespace detail
{
// Every member in field number order, NONE first: the order of ubii::Value's alternatives.
inline constexpr RecordType record_types[] = {RecordType::NONE,
#define UBII_CPP_RECORD_ITEM(upper, number, name, format, cpp_type) RecordType::upper,
                                              UBII_RECORD_MEMBER_LIST(UBII_CPP_RECORD_ITEM)
#undef UBII_CPP_RECORD_ITEM
};
inline constexpr std::size_t record_type_count = sizeof record_types / sizeof record_types[0];

constexpr std::size_t alternative_of(RecordType type)
{
    for (std::size_t i = 0; i < record_type_count; ++i) {
        if (record_types[i] == type)
            return i;
    }
    return record_type_count;
}

template <class T> constexpr RecordType first_member_of()
{
    RecordType result = RecordType::NONE;
#define UBII_CPP_RECORD_MATCH(upper, number, name, format, cpp_type)                               \
    if (result == RecordType::NONE && std::is_same_v<T, cpp_type>)                                 \
        result = RecordType::upper;
    UBII_RECORD_MEMBER_LIST(UBII_CPP_RECORD_MATCH)
#undef UBII_CPP_RECORD_MATCH
    return result;
}
} // namespace detail

// The member a C++ type is published as: Vector3 -> VECTOR3, double -> DOUBLE, std::string ->
// STRING. Where two members share a type (Quaternion: QUATERNION and upstream's QUATERNION_LIST
// quirk), the first; name the other explicitly (Value(RecordType::QUATERNION_LIST, q)). NONE for a
// type no member holds.
template <class T> inline constexpr RecordType record_type_of = detail::first_member_of<T>();

template <class T> inline constexpr bool is_record_value_v = record_type_of<T> != RecordType::NONE;

} // namespace ubii

#endif

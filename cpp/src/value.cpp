#include "ubii/value.hpp"

#include <string>

namespace ubii
{

namespace
{
std::string describe_member(RecordType type)
{
    if (type == RecordType::NONE)
        return "no value";
    return std::string(record_type_name(type)) + " (" + std::string(message_format(type)) + ")";
}
} // namespace

void Value::throw_wrong_type(RecordType wanted) const
{
    throw WrongType(
        "the value holds " + describe_member(type()) + ", not " +
        (wanted == RecordType::NONE ? std::string("the type asked for") : describe_member(wanted)));
}

void Value::throw_mismatch(RecordType member, RecordType given)
{
    throw WrongType(
        "member " + describe_member(member) + " cannot hold " +
        (given == RecordType::NONE ? std::string("the type given") : describe_member(given)));
}

} // namespace ubii

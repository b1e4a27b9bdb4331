#include "record_input.hpp"

#include <cmath>
#include <limits>

#include <google/protobuf/util/json_util.h>
#include <nlohmann/json.hpp>

#include "cli_error.hpp"

namespace ubii::cli
{

namespace
{

using google::protobuf::FieldDescriptor;
using google::protobuf::Message;
using google::protobuf::Reflection;

const google::protobuf::OneofDescriptor &record_members()
{
    return *ubii::TopicDataRecord::descriptor()->FindOneofByName("type");
}

[[noreturn]] void refuse(const std::string &type, const std::string &why)
{
    throw CliError(exit_usage, "not a " + type + ": " + why);
}

void parse_json_message(const std::string &json, Message &message, const std::string &type)
{
    google::protobuf::util::JsonParseOptions options;
    const auto status = google::protobuf::util::JsonStringToMessage(json, &message, options);
    if (!status.ok())
        refuse(type, std::string(status.message()));
}

// Sets one scalar (or adds one element of a repeated one) from a JSON value.
void set_scalar(Message &message, const FieldDescriptor *field, const nlohmann::ordered_json &value,
                const std::string &type)
{
    const Reflection *reflection = message.GetReflection();
    const bool add = field->is_repeated();
    const std::string where = type + "." + field->name();
    switch (field->cpp_type()) {
    case FieldDescriptor::CPPTYPE_DOUBLE:
    case FieldDescriptor::CPPTYPE_FLOAT: {
        if (!value.is_number())
            refuse(type, where + " takes a number, not " + value.dump());
        const double number = value.get<double>();
        if (field->cpp_type() == FieldDescriptor::CPPTYPE_DOUBLE)
            add ? reflection->AddDouble(&message, field, number)
                : reflection->SetDouble(&message, field, number);
        else
            add ? reflection->AddFloat(&message, field, static_cast<float>(number))
                : reflection->SetFloat(&message, field, static_cast<float>(number));
        return;
    }
    case FieldDescriptor::CPPTYPE_INT32: {
        if (!value.is_number_integer() || value.get<long long>() < INT32_MIN ||
            value.get<long long>() > INT32_MAX)
            refuse(type, where + " takes a 32-bit integer, not " + value.dump());
        const auto number = static_cast<std::int32_t>(value.get<long long>());
        add ? reflection->AddInt32(&message, field, number)
            : reflection->SetInt32(&message, field, number);
        return;
    }
    case FieldDescriptor::CPPTYPE_BOOL:
        if (!value.is_boolean())
            refuse(type, where + " takes true or false, not " + value.dump());
        add ? reflection->AddBool(&message, field, value.get<bool>())
            : reflection->SetBool(&message, field, value.get<bool>());
        return;
    case FieldDescriptor::CPPTYPE_STRING:
        if (!value.is_string())
            refuse(type, where + " takes a string, not " + value.dump());
        add ? reflection->AddString(&message, field, value.get<std::string>())
            : reflection->SetString(&message, field, value.get<std::string>());
        return;
    default:
        refuse(type, where + " cannot be given positionally; write the message as JSON");
    }
}

void assign(Message &message, const nlohmann::ordered_json &value, const std::string &type);

void assign_field(Message &message, const FieldDescriptor *field,
                  const nlohmann::ordered_json &value, const std::string &type)
{
    if (field->cpp_type() != FieldDescriptor::CPPTYPE_MESSAGE) {
        set_scalar(message, field, value, type);
        return;
    }
    Message *child = field->is_repeated()
                         ? message.GetReflection()->AddMessage(&message, field)
                         : message.GetReflection()->MutableMessage(&message, field);
    assign(*child, value, type + "." + field->name());
}

// A JSON object is proto3 JSON; an array fills the fields in order, or the one repeated field of a
// list message element by element.
void assign(Message &message, const nlohmann::ordered_json &value, const std::string &type)
{
    if (value.is_object()) {
        parse_json_message(value.dump(), message, type);
        return;
    }
    if (!value.is_array())
        refuse(type, "expected its fields as a list or JSON object, not " + value.dump());
    const auto *descriptor = message.GetDescriptor();
    if (descriptor->field_count() == 1 && descriptor->field(0)->is_repeated()) {
        for (const auto &element : value)
            assign_field(message, descriptor->field(0), element, type);
        return;
    }
    if (value.size() > static_cast<std::size_t>(descriptor->field_count()))
        refuse(type, "it has " + std::to_string(descriptor->field_count()) + " fields, not " +
                         std::to_string(value.size()));
    for (std::size_t i = 0; i < value.size(); ++i)
        assign_field(message, descriptor->field(static_cast<int>(i)), value[i], type);
}

nlohmann::ordered_json parse_json(const std::string &text, const std::string &type,
                                  const char *expected)
{
    nlohmann::ordered_json parsed = nlohmann::ordered_json::parse(text, nullptr, false);
    if (parsed.is_discarded())
        refuse(type, "\"" + text + "\" is not " + expected);
    return parsed;
}

std::string automatic_type(const std::string &value)
{
    if (value == "true" || value == "false")
        return "bool";
    const nlohmann::ordered_json parsed = nlohmann::ordered_json::parse(value, nullptr, false);
    return !parsed.is_discarded() && parsed.is_number() ? "double" : "string";
}

} // namespace

std::vector<std::string> record_type_names()
{
    std::vector<std::string> names{"auto", "json"};
    const auto &members = record_members();
    for (int i = 0; i < members.field_count(); ++i)
        names.push_back(members.field(i)->name());
    return names;
}

ubii::TopicDataRecord parse_record(const std::string &topic, const std::string &requested_type,
                                   const std::string &value)
{
    const std::string type = requested_type == "auto" ? automatic_type(value) : requested_type;
    ubii::TopicDataRecord record;
    if (type == "json") {
        parse_json_message(value, record, "TopicDataRecord");
        if (record.type_case() == ubii::TopicDataRecord::TYPE_NOT_SET)
            refuse("TopicDataRecord", "it sets no value member");
        record.set_topic(topic);
        return record;
    }
    const FieldDescriptor *member = nullptr;
    const auto &members = record_members();
    for (int i = 0; i < members.field_count(); ++i)
        if (members.field(i)->name() == type)
            member = members.field(i);
    if (member == nullptr)
        throw CliError(exit_usage, "no record type \"" + type +
                                       "\" (--type takes auto, json or "
                                       "a TopicDataRecord member)");
    record.set_topic(topic);
    if (member->cpp_type() == FieldDescriptor::CPPTYPE_STRING) {
        record.GetReflection()->SetString(&record, member, value);
        return record;
    }
    if (member->cpp_type() != FieldDescriptor::CPPTYPE_MESSAGE) {
        set_scalar(record, member, parse_json(value, type, "a JSON number or true/false"), type);
        if (member->cpp_type() == FieldDescriptor::CPPTYPE_DOUBLE &&
            !std::isfinite(record.double_()))
            refuse(type, "not finite");
        return record;
    }
    const bool bare_list = !value.empty() && value.front() != '[' && value.front() != '{';
    assign(*record.GetReflection()->MutableMessage(&record, member),
           parse_json(bare_list ? "[" + value + "]" : value, type,
                      "a list of numbers (1,2,3) or a JSON object"),
           type);
    return record;
}

} // namespace ubii::cli

#include "message_output.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <iostream>
#include <sstream>

namespace ubii::cli
{

namespace
{

using google::protobuf::FieldDescriptor;
using google::protobuf::Message;
using google::protobuf::Reflection;

std::string bytes_summary(std::size_t size)
{
    return "<" + std::to_string(size) + " bytes>";
}

// %g keeps 0.1 as 0.1 and 1e-07 short; 17 digits when fewer would not read back the same.
std::string number_text(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.15g", value);
    if (std::stod(text) != value)
        std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

nlohmann::ordered_json scalar_json(const Message &message, const FieldDescriptor *field, int index)
{
    const Reflection *reflection = message.GetReflection();
    const bool repeated = index >= 0;
    switch (field->cpp_type()) {
    case FieldDescriptor::CPPTYPE_INT32:
        return repeated ? reflection->GetRepeatedInt32(message, field, index)
                        : reflection->GetInt32(message, field);
    case FieldDescriptor::CPPTYPE_INT64:
        return repeated ? reflection->GetRepeatedInt64(message, field, index)
                        : reflection->GetInt64(message, field);
    case FieldDescriptor::CPPTYPE_UINT32:
        return repeated ? reflection->GetRepeatedUInt32(message, field, index)
                        : reflection->GetUInt32(message, field);
    case FieldDescriptor::CPPTYPE_UINT64:
        return repeated ? reflection->GetRepeatedUInt64(message, field, index)
                        : reflection->GetUInt64(message, field);
    case FieldDescriptor::CPPTYPE_DOUBLE:
        return repeated ? reflection->GetRepeatedDouble(message, field, index)
                        : reflection->GetDouble(message, field);
    case FieldDescriptor::CPPTYPE_FLOAT:
        return repeated ? reflection->GetRepeatedFloat(message, field, index)
                        : reflection->GetFloat(message, field);
    case FieldDescriptor::CPPTYPE_BOOL:
        return repeated ? reflection->GetRepeatedBool(message, field, index)
                        : reflection->GetBool(message, field);
    case FieldDescriptor::CPPTYPE_ENUM:
        return (repeated ? reflection->GetRepeatedEnum(message, field, index)
                         : reflection->GetEnum(message, field))
            ->name();
    case FieldDescriptor::CPPTYPE_STRING: {
        const std::string value = repeated ? reflection->GetRepeatedString(message, field, index)
                                           : reflection->GetString(message, field);
        if (field->type() == FieldDescriptor::TYPE_BYTES)
            return nlohmann::ordered_json{{"bytes", value.size()}};
        return value;
    }
    case FieldDescriptor::CPPTYPE_MESSAGE:
        return to_json(repeated ? reflection->GetRepeatedMessage(message, field, index)
                                : reflection->GetMessage(message, field));
    }
    return nullptr;
}

std::string scalar_text(const Message &message, const FieldDescriptor *field, int index)
{
    const Reflection *reflection = message.GetReflection();
    const bool repeated = index >= 0;
    switch (field->cpp_type()) {
    case FieldDescriptor::CPPTYPE_DOUBLE:
        return number_text(repeated ? reflection->GetRepeatedDouble(message, field, index)
                                    : reflection->GetDouble(message, field));
    case FieldDescriptor::CPPTYPE_FLOAT:
        return number_text(repeated ? reflection->GetRepeatedFloat(message, field, index)
                                    : reflection->GetFloat(message, field));
    case FieldDescriptor::CPPTYPE_STRING: {
        const std::string value = repeated ? reflection->GetRepeatedString(message, field, index)
                                           : reflection->GetString(message, field);
        return field->type() == FieldDescriptor::TYPE_BYTES ? bytes_summary(value.size()) : value;
    }
    case FieldDescriptor::CPPTYPE_MESSAGE:
        return to_text(repeated ? reflection->GetRepeatedMessage(message, field, index)
                                : reflection->GetMessage(message, field));
    default: {
        const nlohmann::ordered_json value = scalar_json(message, field, index);
        return value.is_string() ? value.get<std::string>() : value.dump();
    }
    }
}

// The fields a message has set, in field-number order (proto3 scalars: those not zero).
std::vector<const FieldDescriptor *> set_fields(const Message &message)
{
    std::vector<const FieldDescriptor *> fields;
    message.GetReflection()->ListFields(message, &fields);
    return fields;
}

const FieldDescriptor *record_member(const ubii::TopicDataRecord &record)
{
    const auto *oneof = record.GetDescriptor()->FindOneofByName("type");
    return record.GetReflection()->GetOneofFieldDescriptor(record, oneof);
}

} // namespace

std::string joined(const std::vector<std::string> &words)
{
    std::string text;
    for (const std::string &word : words)
        text += (text.empty() ? "" : ", ") + word;
    return text;
}

nlohmann::ordered_json to_json(const Message &message)
{
    nlohmann::ordered_json object = nlohmann::ordered_json::object();
    const Reflection *reflection = message.GetReflection();
    for (const FieldDescriptor *field : set_fields(message)) {
        if (field->is_repeated()) {
            nlohmann::ordered_json list = nlohmann::ordered_json::array();
            for (int i = 0; i < reflection->FieldSize(message, field); ++i)
                list.push_back(scalar_json(message, field, i));
            object[field->json_name()] = std::move(list);
        } else {
            object[field->json_name()] = scalar_json(message, field, -1);
        }
    }
    return object;
}

std::string to_text(const Message &message)
{
    std::string text = "{";
    const Reflection *reflection = message.GetReflection();
    for (const FieldDescriptor *field : set_fields(message)) {
        text += (text.size() > 1 ? ", " : "") + field->name() + ": ";
        if (!field->is_repeated()) {
            const bool quoted = field->type() == FieldDescriptor::TYPE_STRING;
            const std::string value = scalar_text(message, field, -1);
            text += quoted ? nlohmann::ordered_json(value).dump() : value;
            continue;
        }
        text += "[";
        for (int i = 0; i < reflection->FieldSize(message, field); ++i)
            text += (i > 0 ? ", " : "") + scalar_text(message, field, i);
        text += "]";
    }
    return text + "}";
}

std::string field_text(const Message &message, const std::string &name)
{
    const FieldDescriptor *field = message.GetDescriptor()->FindFieldByName(name);
    if (field == nullptr)
        return "";
    const Reflection *reflection = message.GetReflection();
    if (!field->is_repeated())
        return field->cpp_type() == FieldDescriptor::CPPTYPE_MESSAGE &&
                       !reflection->HasField(message, field)
                   ? ""
                   : scalar_text(message, field, -1);
    const int size = reflection->FieldSize(message, field);
    if (field->cpp_type() == FieldDescriptor::CPPTYPE_MESSAGE)
        return std::to_string(size);
    std::string text;
    for (int i = 0; i < size; ++i)
        text += (i > 0 ? "," : "") + scalar_text(message, field, i);
    return text;
}

RecordText record_text(const ubii::TopicDataRecord &record)
{
    const FieldDescriptor *member = record_member(record);
    if (member == nullptr)
        return {"none", ""};
    return {member->name(), scalar_text(record, member, -1)};
}

nlohmann::ordered_json record_json(const ubii::TopicDataRecord &record)
{
    nlohmann::ordered_json object{{"topic", record.topic()}};
    const FieldDescriptor *member = record_member(record);
    object["type"] = member != nullptr ? member->name() : "none";
    object["value"] = member != nullptr ? scalar_json(record, member, -1) : nullptr;
    if (!record.client_id().empty())
        object["clientId"] = record.client_id();
    if (record.has_timestamp() && record.timestamp().millis() != 0)
        object["timestampMillis"] = record.timestamp().millis();
    return object;
}

void print_table(const std::vector<const Message *> &rows, const std::vector<std::string> &columns)
{
    std::vector<std::vector<std::string>> cells;
    std::vector<std::string> header;
    for (const std::string &column : columns) {
        std::string title = column;
        std::transform(title.begin(), title.end(), title.begin(), [](unsigned char c) {
            return c == '_' ? ' ' : static_cast<char>(std::toupper(c));
        });
        header.push_back(title);
    }
    cells.push_back(header);
    for (const Message *row : rows) {
        std::vector<std::string> line;
        for (const std::string &column : columns)
            line.push_back(field_text(*row, column));
        cells.push_back(std::move(line));
    }
    std::vector<std::size_t> widths(columns.size(), 0);
    for (const auto &line : cells)
        for (std::size_t i = 0; i < line.size(); ++i)
            widths[i] = std::max(widths[i], line[i].size());
    for (const auto &line : cells) {
        std::string text;
        for (std::size_t i = 0; i < line.size(); ++i) {
            text += line[i];
            if (i + 1 < line.size())
                text += std::string(widths[i] - line[i].size() + 2, ' ');
        }
        std::cout << text << '\n';
    }
}

} // namespace ubii::cli

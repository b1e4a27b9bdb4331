#ifndef UBII_CLI_MESSAGE_OUTPUT_HPP
#define UBII_CLI_MESSAGE_OUTPUT_HPP

// Messages as people and scripts read them: one line of text ("{x: 1, y: 2}"), JSON (field names
// as proto3 JSON writes them), tables. Bytes (image pixels) are summarised as their size, never
// dumped.

#include <string>
#include <vector>

#include <google/protobuf/message.h>
#include <nlohmann/json.hpp>

#include "ubii/ubii.hpp"

namespace ubii::cli
{

// "a, b, c".
std::string joined(const std::vector<std::string> &words);

nlohmann::ordered_json to_json(const google::protobuf::Message &message);
std::string to_text(const google::protobuf::Message &message);

// One field of `message` as a table cell: a scalar as text, a repeated scalar joined with ",", a
// repeated message as its count, a message as text. "" for an unset or unknown field.
std::string field_text(const google::protobuf::Message &message, const std::string &field);

// The set member of a record: its name and value ("double", "42").
struct RecordText {
    std::string type;
    std::string value;
};
RecordText record_text(const ubii::TopicDataRecord &record);
// {"topic", "type", "value", "clientId" (when set), "timestampMillis" (when set)}.
nlohmann::ordered_json record_json(const ubii::TopicDataRecord &record);

// Rows of `columns` fields of each message, under headers in capitals, columns aligned.
void print_table(const std::vector<const google::protobuf::Message *> &rows,
                 const std::vector<std::string> &columns);

} // namespace ubii::cli

#endif

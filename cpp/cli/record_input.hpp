#ifndef UBII_CLI_RECORD_INPUT_HPP
#define UBII_CLI_RECORD_INPUT_HPP

// A record from the command line: `pub TOPIC VALUE --type TYPE`.

#include <string>
#include <vector>

#include "ubii/ubii.hpp"

namespace ubii::cli
{

// The names --type takes: "auto", "json", and every TopicDataRecord member ("double", "vector3",
// "image2D", "double_list", ...).
std::vector<std::string> record_type_names();

// `value` as the member `type` of a record on `topic`:
//   double, float, int32, bool: a JSON number or true/false ("42", "-1.5e3", "true");
//   string: the text as it is;
//   a message: its fields in order as numbers ("1,2,3" or "[1,2,3]"; a list member takes one
//   element per entry, "[[1,2,3],[4,5,6]]"), or proto3 JSON ('{"x": 1, "z": 3}');
//   json: a whole TopicDataRecord in proto3 JSON ('{"vector3": {"x": 1}}');
//   auto: double for a number, bool for true/false, else string.
// CliError(exit_usage) naming the type and what is wrong.
ubii::TopicDataRecord parse_record(const std::string &topic, const std::string &type,
                                   const std::string &value);

} // namespace ubii::cli

#endif

#ifndef UBII_OCR_SRC_USER_DATA_JSON_HPP
#define UBII_OCR_SRC_USER_DATA_JSON_HPP

// The user_data_json of an Object2D made from a TextBox: {"confidence":C} and, for a rotated box,
// "rotated_box":{"center":[x,y],"size":[w,h],"angle":a}. Numbers are written and read with
// std::to_chars / std::from_chars: the shortest form that reads back exactly, with a decimal point
// whatever the process's locale.

#include <string>
#include <string_view>

#include "ubii/ocr/text_box.hpp"

namespace ubii::ocr::detail
{

std::string user_data_json(const TextBox &box);

// Fills box.confidence (NaN when the key is missing) and box.rotated_box from `json`. Reads only
// the keys above; other keys are ignored, so JSON from other producers is accepted.
void read_user_data_json(std::string_view json, TextBox &box);

} // namespace ubii::ocr::detail

#endif

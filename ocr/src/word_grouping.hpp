#ifndef UBII_OCR_SRC_WORD_GROUPING_HPP
#define UBII_OCR_SRC_WORD_GROUPING_HPP

#include <vector>

#include "ubii/ocr/text_box.hpp"

namespace ubii::ocr::detail
{

// Joins characters into words: two characters belong to one word when they share most of a line
// (vertical overlap) and the gap between them is at most `max_gap` times the shorter one's height.
// A word's text is its characters left to right, its confidence their mean, its box their union.
std::vector<TextBox> group_into_words(const std::vector<TextBox> &characters, float max_gap);

} // namespace ubii::ocr::detail

#endif

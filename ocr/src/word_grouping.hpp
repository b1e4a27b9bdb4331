#ifndef UBII_OCR_SRC_WORD_GROUPING_HPP
#define UBII_OCR_SRC_WORD_GROUPING_HPP

#include <cstddef>
#include <vector>

#include "ubii/ocr/text_box.hpp"

namespace ubii::ocr::detail
{

// Joins characters into words: two characters belong to one word when they share most of a line
// (vertical overlap), differ in height by less than a factor of 2 and the gap between them is at
// most `max_gap` times the shorter one's height.
// A word's text is its characters left to right, its confidence their mean, its box their union.
std::vector<TextBox> group_into_words(const std::vector<TextBox> &characters, float max_gap);

// The same rule on bare boxes: the members of each word, as indices into `boxes`, left to right.
std::vector<std::vector<std::size_t>> cluster_words(const std::vector<cv::Rect> &boxes,
                                                    float max_gap);

// Runs (clusters of `boxes`) with a character each that share more than half of the smaller one's
// area are joined: they hold the same letters (e.g. a word and a fragment of it left over from
// MSER's nested regions), which would otherwise be read twice. Judged by the characters, not by
// the runs' bounding boxes: those of neighbouring turned lines overlap although no letter does.
std::vector<std::vector<std::size_t>>
merge_runs_sharing_ink(const std::vector<cv::Rect> &boxes,
                       std::vector<std::vector<std::size_t>> runs);

// Top to bottom, then left to right.
void sort_reading_order(std::vector<TextBox> &words);

} // namespace ubii::ocr::detail

#endif

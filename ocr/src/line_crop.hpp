#ifndef UBII_OCR_SRC_LINE_CROP_HPP
#define UBII_OCR_SRC_LINE_CROP_HPP

// A line of text at an angle, cut out of the frame upright for Tesseract's single-line mode, and
// what Tesseract finds in it put back into the frame: shared by DB (whose detector finds lines)
// and MSER (whose character regions are grouped into them).

#include <array>

#include <opencv2/core/mat.hpp>
#include <opencv2/core/matx.hpp>

#include "ubii/ocr/text_box.hpp"

namespace ubii::ocr::detail
{

// Four corners in the frame's pixels: top-left, top-right, bottom-right, bottom-left as the text
// reads (the line's long side runs from top-left to top-right).
using LineQuad = std::array<cv::Point2f, 4>;

// A rectangle's corners (any order around it) as the text reads, taking the more nearly
// horizontal pair of sides as the line's direction (text turned past 45 degrees is read
// sideways: not supported).
LineQuad as_text_quad(const std::array<cv::Point2f, 4> &corners);

// How far the line's top side turns from the horizontal, in degrees (either way).
float turn_degrees(const LineQuad &quad);

// The line turned upright, padded by `padding` line heights, scaled to a readable height, and the
// transform from the crop's pixels back to the frame's.
struct UprightLine {
    cv::Mat pixels;
    cv::Matx33d to_frame;
};
UprightLine upright_line(const cv::Mat &gray, const LineQuad &quad, float padding);

// A word's box from the crop into the frame (its corners through the inverse transform; the
// rotated box kept). False when nothing of it lies in the frame.
bool place_in_frame(TextBox &word, const cv::Matx33d &to_frame, const cv::Rect &frame);

} // namespace ubii::ocr::detail

#endif

#ifndef UBII_EXAMPLE_OCR_NODE_FRAME_REPORT_HPP
#define UBII_EXAMPLE_OCR_NODE_FRAME_REPORT_HPP

// The line ocr_node prints for each frame, e.g.
//   frame 3 1200x900: 2 boxes, 251.4 ms, 1 dropped: "Hello" 50,40 210x52 96; "world" 280,40 ...
//   frame 4 error: Image2D of 1200x900x3 needs 3240000 bytes, it has 1620000
// Boxes are left,top width x height in the image's pixels, then Tesseract's confidence.

#include <cstdint>
#include <string>
#include <vector>

#include "ubii/ocr/text_box.hpp"

namespace ocr_node
{

std::string frame_line(std::uint64_t frame, int width, int height,
                       const std::vector<ubii::ocr::TextBox> &boxes, double milliseconds,
                       std::uint64_t dropped_so_far);

std::string frame_error_line(std::uint64_t frame, const std::string &error);

} // namespace ocr_node

#endif

#ifndef UBII_EXAMPLE_OCR_NODE_PROCESS_FRAME_HPP
#define UBII_EXAMPLE_OCR_NODE_PROCESS_FRAME_HPP

// One frame: Image2D -> pipeline -> Object2DList on the output topic, and the line to print.

#include <cstdint>
#include <string>

#include "latest_frame.hpp"
#include "ubii/ocr/pipeline.hpp"
#include "ubii/ubii.h"

namespace ocr_node
{

struct FrameResult {
    bool ok = false;  // recognised and published
    std::string line; // what to print: frame_line() or frame_error_line()
};

// Recognises `frame` and publishes its boxes on `output_topic`. Never throws: a frame that cannot
// be used (not an Image2D, wrong byte count, unknown format, a pipeline failure) or cannot be
// published gives an error line and nothing is published for it.
FrameResult process_frame(ubii::ocr::Pipeline &pipeline, ubii_node *node,
                          const std::string &output_topic, const Frame &frame, std::uint64_t number,
                          std::uint64_t dropped_so_far) noexcept;

} // namespace ocr_node

#endif

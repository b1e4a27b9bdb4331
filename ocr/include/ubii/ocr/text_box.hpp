#ifndef UBII_OCR_TEXT_BOX_HPP
#define UBII_OCR_TEXT_BOX_HPP

#include <optional>
#include <string>

#include <opencv2/core/types.hpp>

namespace ubii::ocr
{

// One recognised piece of text, in the pixel coordinates of the frame handed to the pipeline
// (x to the right, y down, origin at the top-left pixel).
struct TextBox {
    std::string text; // UTF-8, no leading or trailing white space, never empty
    float confidence; // Tesseract's confidence, 0..100
    cv::Rect box;     // axis-aligned; for a rotated box its bounding rectangle
    std::optional<cv::RotatedRect> rotated_box; // EAST only: the detector's oriented box
};

} // namespace ubii::ocr

#endif

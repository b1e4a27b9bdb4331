#ifndef UBII_OCR_SRC_GRAYSCALE_HPP
#define UBII_OCR_SRC_GRAYSCALE_HPP

#include <opencv2/core/mat.hpp>

namespace ubii::ocr::detail
{

// Checks a pipeline's input (InvalidImage) and returns it as 8-bit grayscale: Tesseract is both
// faster and far more accurate on cluttered scenes when handed gray rather than colour. A gray
// input is returned as is, without a copy.
cv::Mat to_grayscale(const cv::Mat &image);

// Checks the input the same way and returns it as 3-channel BGR.
cv::Mat to_bgr(const cv::Mat &image);

} // namespace ubii::ocr::detail

#endif

#ifndef UBII_OCR_SRC_DB_DETECTOR_HPP
#define UBII_OCR_SRC_DB_DETECTOR_HPP

// The DB network and its post-processing: OpenCV 4.6's TextDetectionModel_DB wants a 2-D output
// and PP-OCRv4 gives 1x1xHxW, so the probability map is read here (threshold, contours, box score,
// unclip, minimum-area rectangle), for any input size.

#include <array>
#include <vector>

#include <opencv2/core/mat.hpp>
#include <opencv2/dnn/dnn.hpp>

#include "ubii/ocr/db_pipeline.hpp"

namespace ubii::ocr::detail
{

// A detected line as four corners in the frame's pixels: top-left, top-right, bottom-right,
// bottom-left as the text reads (the line's long side runs from top-left to top-right).
using LineQuad = std::array<cv::Point2f, 4>;

class DbDetector
{
  public:
    // ModelError when the model cannot be loaded.
    explicit DbDetector(const DbOptions &options);

    // `bgr`: 8-bit, three channels. Lines in reading order (top to bottom, then left to right).
    std::vector<LineQuad> detect(const cv::Mat &bgr);

    // The network's input size for a frame of `frame` pixels.
    cv::Size input_size(cv::Size frame) const;

  private:
    DbOptions options_;
    cv::dnn::Net net_;
};

} // namespace ubii::ocr::detail

#endif

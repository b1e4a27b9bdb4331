#ifndef UBII_OCR_SRC_DB_DETECTOR_HPP
#define UBII_OCR_SRC_DB_DETECTOR_HPP

// The DB network and its post-processing: OpenCV 4.6's TextDetectionModel_DB wants a 2-D output
// and PP-OCRv4 gives 1x1xHxW, so the probability map is read here (threshold, contours, box score,
// unclip, minimum-area rectangle), for any input size.

#include <array>
#include <list>
#include <string>
#include <utility>
#include <vector>

#include <opencv2/core/mat.hpp>
#include <opencv2/dnn/dnn.hpp>

#include "line_crop.hpp"
#include "ubii/ocr/db_pipeline.hpp"

namespace ubii::ocr::detail
{

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
    // OpenCV 4.6 fixes some of this network's shapes (its Resize layers) at the first input size
    // a Net sees and gets every other size wrong afterwards, even the first again (no boxes at
    // all): one Net per input size, the few most recent kept (a camera gives one size).
    cv::dnn::Net &network_for(cv::Size input);

    DbOptions options_;
    std::string path_;
    std::vector<uchar> model_;
    std::list<std::pair<cv::Size, cv::dnn::Net>> networks_; // most recently used first
    cv::dnn::Net unused_; // loaded by the constructor to check the model, for the first size
};

} // namespace ubii::ocr::detail

#endif

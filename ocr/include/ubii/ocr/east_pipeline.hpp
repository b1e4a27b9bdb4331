#ifndef UBII_OCR_EAST_PIPELINE_HPP
#define UBII_OCR_EAST_PIPELINE_HPP

#include <memory>
#include <string>

#include <opencv2/core/types.hpp>

#include "ubii/ocr/pipeline.hpp"
#include "ubii/ocr/tesseract_options.hpp"

namespace ubii::ocr
{

// EAST: OpenCV's EAST text detector (cv::dnn::TextDetectionModel_EAST) proposes oriented word
// boxes, non-maximum suppression removes overlapping ones, Tesseract reads each box (the thesis's
// TesseractOCR_EAST). Boxes Tesseract finds no text in are dropped.
//
// The model is not part of libubii and nothing is downloaded: give the path of the public
// frozen_east_text_detection.pb (or any network with EAST's two outputs that OpenCV can read).
struct EastOptions {
    EastOptions()
    {
        tesseract.segmentation = Segmentation::single_line;
    }

    std::string model_path; // required
    TesseractOptions tesseract;
    // The frame is resized to this before the forward pass; both multiples of 32.
    cv::Size input_size{320, 320};
    cv::Scalar mean{123.68, 116.78, 103.94}; // subtracted per channel (RGB), as EAST was trained
    bool swap_red_blue = true;               // EAST expects RGB; OpenCV frames are BGR
    float confidence_threshold = 0.5f;       // score-map cells below this propose nothing
    float nms_threshold = 0.5f;              // overlap above which the weaker box is suppressed
    int padding_px = 4;                      // added around each box before it is read
};

class EastPipeline final : public Pipeline
{
  public:
    // ModelError when the model file is missing, unreadable or not a network OpenCV can load;
    // EngineError when Tesseract cannot start; InvalidArgument for bad sizes or thresholds.
    explicit EastPipeline(const EastOptions &options);
    ~EastPipeline() override;

    PipelineKind kind() const override
    {
        return PipelineKind::east;
    }

  private:
    std::vector<TextBox> recognise_frame(const cv::Mat &image) override;

    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace ubii::ocr

#endif

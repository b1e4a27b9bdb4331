#ifndef UBII_OCR_DB_PIPELINE_HPP
#define UBII_OCR_DB_PIPELINE_HPP

#include <memory>
#include <string>

#include "ubii/ocr/pipeline.hpp"
#include "ubii/ocr/tesseract_options.hpp"

namespace ubii::ocr
{

// DB: a pretrained scene-text detector (PaddleOCR's PP-OCRv4 DB network, run by OpenCV's DNN
// module) finds text lines at any angle, each line is cut out upright and Tesseract reads it in
// single-line mode on the one engine the pipeline keeps. Words come back one box each.
//
// The model is not part of libubii: scripts/ocr-models.sh fetches it (pinned, checked) and rewrites
// it for OpenCV 4.6 into the cache, where default_db_model_path() finds it.
struct DbOptions {
    DbOptions()
    {
        tesseract.segmentation = Segmentation::single_line;
    }
    // Empty: default_db_model_path().
    std::string model_path;
    TesseractOptions tesseract;
    // The frame is scaled so that its longer side is this many pixels (each side then rounded to
    // a multiple of 32, the network's stride), keeping its aspect ratio: 1200x900 runs at 640x480.
    // Detection time grows with its square (1200x900 on 2 cores: 480: 60 ms, 640: 95 ms,
    // 960: 200 ms); 640 found every word of the test scenes, 960 no more (ocr/README.md).
    int max_side = 640;
    // A pixel of the network's probability map at or above this is text.
    float binary_threshold = 0.3f;
    // A candidate line is kept when the mean probability inside it reaches this.
    float box_threshold = 0.5f;
    // DB predicts shrunk text kernels; each is grown by area * ratio / perimeter on every side.
    float unclip_ratio = 1.5f;
    // At most this many candidate lines per frame (the largest are not preferred: the first found).
    int max_candidates = 200;
    // Added around each line before it is read, as a fraction of the line's height.
    float padding = 0.1f;
};

// Where scripts/ocr-models.sh puts the model: $UBII_OCR_DB_MODEL if set, else
// <cache>/models/ppocrv4-det/ppocrv4_det_opencv.onnx with <cache> = $UBII_CACHE_DIR, or
// $XDG_CACHE_HOME/libubii, or ~/.cache/libubii. The file need not exist.
std::string default_db_model_path();

class DbPipeline final : public Pipeline
{
  public:
    // ModelError when the model is missing or not a network OpenCV can run (the message says how
    // to fetch it); EngineError when Tesseract cannot start; InvalidArgument for options out of
    // range.
    explicit DbPipeline(const DbOptions &options = {});
    ~DbPipeline() override;

    PipelineKind kind() const override
    {
        return PipelineKind::db;
    }

  private:
    std::vector<TextBox> recognise_frame(const cv::Mat &image) override;

    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace ubii::ocr

#endif

#ifndef UBII_OCR_PURE_PIPELINE_HPP
#define UBII_OCR_PURE_PIPELINE_HPP

#include <memory>

#include "ubii/ocr/pipeline.hpp"
#include "ubii/ocr/tesseract_options.hpp"

namespace ubii::ocr
{

// PURE: Tesseract alone finds the words and reads them (the thesis's TesseractOCR_PURE).
struct PureOptions {
    TesseractOptions tesseract; // automatic segmentation by default; sparse_text suits scenes
};

class PurePipeline final : public Pipeline
{
  public:
    // Throws EngineError when Tesseract cannot start or refuses a variable.
    explicit PurePipeline(const PureOptions &options = {});
    ~PurePipeline() override;

    PipelineKind kind() const override
    {
        return PipelineKind::pure;
    }

  private:
    std::vector<TextBox> recognise_frame(const cv::Mat &image) override;

    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace ubii::ocr

#endif

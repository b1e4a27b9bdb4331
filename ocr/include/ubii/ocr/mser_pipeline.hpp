#ifndef UBII_OCR_MSER_PIPELINE_HPP
#define UBII_OCR_MSER_PIPELINE_HPP

#include <memory>

#include "ubii/ocr/pipeline.hpp"
#include "ubii/ocr/tesseract_options.hpp"

namespace ubii::ocr
{

// MSER: OpenCV's maximally stable extremal regions propose characters, Tesseract reads each one
// in single-character mode, neighbouring characters on a line are joined into words (the thesis's
// TesseractOCR_MSER, with the regions deduplicated first: MSER reports every character many times
// over, as nested regions).
struct MserOptions {
    MserOptions()
    {
        tesseract.segmentation = Segmentation::single_char;
    }

    TesseractOptions tesseract;
    int padding_px = 2; // added around each region before it is read
    // cv::MSER's parameters (its defaults, except a smaller minimum area for small print).
    int delta = 5;
    int min_area = 30;
    int max_area = 14400;
    double max_variation = 0.25;
    double min_diversity = 0.2;
    // Run MSER on the colour image (OpenCV's MSCR variant; slower) instead of grayscale.
    bool use_colour = false;
    // Characters whose horizontal gap is at most this fraction of their height belong to one word.
    float word_gap = 0.3f;
};

class MserPipeline final : public Pipeline
{
  public:
    // Throws EngineError (Tesseract) or InvalidArgument (MSER parameters).
    explicit MserPipeline(const MserOptions &options = {});
    ~MserPipeline() override;

    std::vector<TextBox> recognise(const cv::Mat &image) override;
    PipelineKind kind() const override
    {
        return PipelineKind::mser;
    }

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace ubii::ocr

#endif

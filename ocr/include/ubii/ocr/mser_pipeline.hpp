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
    // White margin around each region's pixels, which are read on their own (drawn black on
    // white, so that neighbouring letters cannot creep in). The thesis cut its crops from the
    // frame with 2 px; with a 2 px white margin Tesseract reads markedly worse than with 6
    // (ocr/README.md).
    int padding_px = 6;
    // cv::MSER's parameters (its defaults, except a smaller minimum area for small print).
    int delta = 5;
    int min_area = 30;
    int max_area = 14400;
    double max_variation = 0.25;
    double min_diversity = 0.2;
    // Run MSER on the colour image (OpenCV's MSCR variant; slower) instead of grayscale.
    bool use_colour = false;
    // Characters whose horizontal gap is at most this fraction of the shorter one's height belong
    // to one word (a space in common fonts is about 0.6 x-heights wide, a letter gap far less).
    float word_gap = 0.4f;
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

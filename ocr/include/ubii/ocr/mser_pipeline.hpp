#ifndef UBII_OCR_MSER_PIPELINE_HPP
#define UBII_OCR_MSER_PIPELINE_HPP

#include <memory>

#include "ubii/ocr/pipeline.hpp"
#include "ubii/ocr/tesseract_options.hpp"

namespace ubii::ocr
{

// MSER: OpenCV's maximally stable extremal regions propose characters; Tesseract reads the text
// those regions make up. MSER reports every character many times over (nested regions), so the
// regions are deduplicated and filtered first, then either read one by one in single-character
// mode (the thesis's TesseractOCR_MSER) or, by default, joined into runs of characters on a line
// that are read once each (ocr/README.md has the measurements behind the default).
struct MserOptions {
    // What Tesseract is asked to read, once per unit. Set `tesseract.segmentation` to match
    // (single_char, single_word, single_line); the default constructor pairs lines with
    // single_line.
    enum class Unit {
        // Every character region on its own, from its region's pixels drawn black on white, then
        // joined into words: the thesis's scheme, no word context, one Tesseract call per
        // character.
        characters,
        // Characters closer than `word_gap` are joined into words, and each word's box is read
        // once from the gray frame.
        words,
        // Characters closer than `line_gap` (letters MSER missed leave gaps) are joined into runs
        // along a line, each read once from the gray frame; Tesseract splits them into words.
        lines,
    };

    MserOptions()
    {
        tesseract.segmentation = Segmentation::single_line;
    }

    Unit recognise_as = Unit::lines;
    TesseractOptions tesseract;
    // Margin around each unit. For characters: white, around the region's pixels, which are read
    // on their own (so that neighbouring letters cannot creep in); the thesis cut its crops from
    // the frame with 2 px, and with a 2 px white margin Tesseract reads markedly worse than with
    // 6 (ocr/README.md). For words and lines: the frame around the box.
    int padding_px = 6;
    // cv::MSER's parameters: its defaults, except a smaller minimum area for small print and a
    // smaller delta, which finds the letters of small, blurred, low-contrast text (whose regions
    // grow fast with the threshold and so look unstable over 5 grey levels).
    int delta = 3;
    int min_area = 30;
    int max_area = 14400;
    double max_variation = 0.25;
    double min_diversity = 0.2;
    // Run MSER on the colour image (OpenCV's MSCR variant; slower) instead of grayscale.
    bool use_colour = false;
    // Characters whose horizontal gap is at most this fraction of the shorter one's height belong
    // to one word (a space in common fonts is about 0.6 x-heights wide, a letter gap far less).
    float word_gap = 0.4f;
    // The same for runs along a line (Unit::lines): wide enough to bridge a letter MSER missed.
    float line_gap = 1.0f;
};

class MserPipeline final : public Pipeline
{
  public:
    // Throws EngineError (Tesseract) or InvalidArgument (MSER parameters).
    explicit MserPipeline(const MserOptions &options = {});
    ~MserPipeline() override;

    PipelineKind kind() const override
    {
        return PipelineKind::mser;
    }

  private:
    std::vector<TextBox> recognise_frame(const cv::Mat &image) override;

    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace ubii::ocr

#endif

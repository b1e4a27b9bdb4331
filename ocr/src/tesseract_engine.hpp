#ifndef UBII_OCR_SRC_TESSERACT_ENGINE_HPP
#define UBII_OCR_SRC_TESSERACT_ENGINE_HPP

// One tesseract::TessBaseAPI, initialised once and reused: the part every pipeline shares. Results
// are read through Tesseract's iterator API, never its text renderers (TSV, hOCR), whose numbers
// follow the process's LC_NUMERIC and turn into decimal commas under many locales.

#include <memory>
#include <optional>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "ubii/ocr/tesseract_options.hpp"
#include "ubii/ocr/text_box.hpp"

namespace tesseract
{
class TessBaseAPI;
}

namespace ubii::ocr::detail
{

class TesseractEngine
{
  public:
    // Throws EngineError when the language cannot be loaded or a variable is refused.
    explicit TesseractEngine(const TesseractOptions &options);
    ~TesseractEngine();
    TesseractEngine(const TesseractEngine &) = delete;
    TesseractEngine &operator=(const TesseractEngine &) = delete;

    // `gray`: 8-bit, one channel. Tesseract copies the pixels; `gray` may go away afterwards.
    void set_image(const cv::Mat &gray);
    // Restricts the next read to `area` of the image last set (clipped to it).
    void set_rectangle(const cv::Rect &area);

    // Every word at or above the minimum confidence, boxes in the image's coordinates.
    std::vector<TextBox> read_words();
    // Everything in the current image or rectangle as one box: the words joined by single spaces,
    // their mean confidence. Nothing when no word is found or the mean is below the minimum.
    std::optional<TextBox> read_as_one(const cv::Rect &box);

    // The single most confident symbol in the current image: in single-character mode the LSTM
    // engine often returns a character together with a look-alike ("c" as "Cc"), of which only
    // one can be right. Nothing when no symbol reaches the minimum confidence.
    std::optional<TextBox> read_best_symbol(const cv::Rect &box);

  private:
    bool recognise();

    std::unique_ptr<tesseract::TessBaseAPI> api_;
    TesseractOptions options_;
};

} // namespace ubii::ocr::detail

#endif

#ifndef UBII_OCR_TESSERACT_OPTIONS_HPP
#define UBII_OCR_TESSERACT_OPTIONS_HPP

#include <map>
#include <string>

namespace ubii::ocr
{

// Tesseract's page segmentation modes that make sense for these pipelines (names follow
// tesseract::PageSegMode; the numbers are Tesseract's --psm values).
enum class Segmentation {
    automatic = 3,    // PSM_AUTO: find blocks, lines and words (documents, clean frames)
    single_block = 6, // PSM_SINGLE_BLOCK
    single_line = 7,  // PSM_SINGLE_LINE
    single_word = 8,  // PSM_SINGLE_WORD
    single_char = 10, // PSM_SINGLE_CHAR
    sparse_text = 11, // PSM_SPARSE_TEXT: as much text as possible, in no particular order (scenes)
};

// Tesseract's engine modes (tesseract::OcrEngineMode). Debian's eng.traineddata holds only the
// LSTM model, so `legacy` and `legacy_and_lstm` fail to initialise with it.
enum class EngineMode {
    legacy = 0,
    lstm_only = 1,
    legacy_and_lstm = 2,
    from_traineddata = 3,
};

struct TesseractOptions {
    std::string language = "eng";
    // Folder holding <language>.traineddata; empty: TESSDATA_PREFIX or Tesseract's built-in path.
    std::string data_path;
    EngineMode engine_mode = EngineMode::lstm_only;
    Segmentation segmentation = Segmentation::automatic;
    // Words below this confidence (0..100) are dropped.
    float min_confidence = 70.0f;
    // Told to Tesseract with every image. Without it Tesseract estimates the resolution and prints
    // "Estimating resolution as N" to stderr for every frame.
    int source_resolution_dpi = 300;
    // Any Tesseract variable, e.g. {"tessedit_char_whitelist", "0123456789"}. An unknown name
    // makes the pipeline's constructor throw EngineError.
    std::map<std::string, std::string> variables;
};

} // namespace ubii::ocr

#endif

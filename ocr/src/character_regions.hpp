#ifndef UBII_OCR_SRC_CHARACTER_REGIONS_HPP
#define UBII_OCR_SRC_CHARACTER_REGIONS_HPP

#include <cstddef>
#include <vector>

#include <opencv2/core/types.hpp>

namespace ubii::ocr::detail
{

// Turns MSER's region boxes into one box per character candidate. MSER reports each character
// many times over (nested regions at neighbouring thresholds: ~2,900 regions for 27 words), plus
// regions spanning whole words or panels and the holes inside letters. Reading each with
// Tesseract would take seconds, so:
//   1. near-identical boxes collapse into one;
//   2. boxes shaped unlike a character (too flat, too thin, too small) go;
//   3. boxes holding two side-by-side candidates are words or lines, not characters, and go;
//   4. boxes inside another candidate (holes, inner strokes) go;
//   5. a dot just above a stem joins it (i, j).
struct CharacterCandidate {
    cv::Rect box;
    std::vector<std::size_t> regions; // indices of the MSER regions that make it up
};
std::vector<CharacterCandidate> character_candidates(const std::vector<cv::Rect> &regions);

} // namespace ubii::ocr::detail

#endif

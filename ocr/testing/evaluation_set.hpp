#ifndef UBII_OCR_TESTING_EVALUATION_SET_HPP
#define UBII_OCR_TESTING_EVALUATION_SET_HPP

// The evaluation set: scenes the pipelines were never tuned on, to measure them honestly. The
// tuning scenes (scenes.hpp: baseline, sign, webcam) are the ones parameters were chosen on; these
// come from another generator with another seed, other words, other fonts and sizes, and nothing
// in ocr/src may be tuned on them (ocr/README.md, "Test data").
//
// Six kinds, six images each, 36 in all, each made from its own seed (kUbiiEvaluationSeed + its
// index), so one image can be made alone:
//   document  a page of 5-7 lines, serif, sans or mono, slightly turned (up to 2 degrees)
//   sign      2-3 lines of large bold text on a coloured panel, turned up to 10 degrees and seen
//             in perspective, in clutter, blurred, with noise
//   label     a few words of mixed sizes on a pastel panel, turned up to 5 degrees
//   photo     2-4 lines on a textured, coloured background with clutter, blurred, with noise
//   tilted    3-5 lines on a light ground, turned 6-10 degrees either way, in perspective
//   lowres    640x480: small text (18-26 px) in low contrast, blurred, noisy, JPEG quality 35

#include <string>
#include <vector>

#include "scenes.hpp"

namespace ubii::ocr::testdata
{

inline constexpr unsigned kUbiiEvaluationSeed = 0x5EED2026u;

struct EvaluationScene {
    std::string kind;
    Scene scene; // scene.name: "NN-kind"
};

const std::vector<std::string> &evaluation_kinds();
// Image `index` (0..35) alone.
EvaluationScene evaluation_scene(int index);
int evaluation_set_size();
std::vector<EvaluationScene> evaluation_set();

// Writes NN-kind.png and NN-kind.txt (one line per word: left top width height text) to `dir`.
void write_evaluation_set(const std::string &dir);

} // namespace ubii::ocr::testdata

#endif

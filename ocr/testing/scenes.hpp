#ifndef UBII_OCR_TESTING_SCENES_HPP
#define UBII_OCR_TESTING_SCENES_HPP

// Synthetic scenes with known text, made at run time (no photographs can be downloaded), for the
// OCR tests and the benchmark. Generation is seeded: every call returns the same pixels.
//
//   baseline  1200x900, dark DejaVu Sans text on white (a scanned page at its best)
//   sign      1200x900, dark text on a yellow panel, perspective-warped into a cluttered scene,
//             blurred, with sensor noise
//   webcam    640x480, small low-contrast text in a cluttered scene, blurred, JPEG quality 30
//
// Text is rasterised by OpenCV's FreeType module with DejaVu Sans (fonts-dejavu-core): a real
// hinted, anti-aliased TrueType font gives Tesseract the shapes it was trained on, where OpenCV's
// Hershey stroke fonts are not a fair test.

#include <string>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "ubii/ocr/text_box.hpp"

namespace ubii::ocr::testdata
{

struct GroundTruthWord {
    std::string text;
    cv::Rect box; // tight box of the word's ink, in the scene's pixels
};

struct Scene {
    std::string name;
    cv::Mat image; // BGR
    std::vector<GroundTruthWord> words;
};

Scene baseline_scene();
Scene sign_scene();
Scene webcam_scene();
std::vector<Scene> all_scenes();

// The input size at which the generated EAST test network sees this scene's text at the scale it
// was built for (capitals about 20 px high), in multiples of 32. The public EAST model copes with
// many scales; the hand-set test network with only a few.
cv::Size east_test_input_size(const Scene &scene);

// Word-level precision and recall. A recognised word counts as correct when, after keeping only
// letters and digits and ignoring case, it equals a not yet matched ground-truth word and the two
// boxes overlap by at least half of the smaller one.
struct WordScore {
    int correct = 0;
    int recognised = 0; // recognised words that are not empty after normalisation
    int expected = 0;
    double precision() const
    {
        return recognised == 0 ? 0.0 : double(correct) / recognised;
    }
    double recall() const
    {
        return expected == 0 ? 0.0 : double(correct) / expected;
    }
    std::vector<std::string> missed;   // ground truth not found
    std::vector<std::string> spurious; // recognised words that match nothing
};

WordScore score_words(const std::vector<TextBox> &recognised,
                      const std::vector<GroundTruthWord> &truth);
std::string describe(const WordScore &score);

} // namespace ubii::ocr::testdata

#endif

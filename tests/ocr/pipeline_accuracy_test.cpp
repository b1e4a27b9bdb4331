// Word-level precision and recall of every pipeline on every synthetic scene, against thresholds
// set below what was measured (the measured values are in the table's comments and in
// ocr/README.md). A drop below a threshold is a regression worth a look, not noise: the scenes
// and the recognition are deterministic.
#include <gtest/gtest.h>

#include "ocr_test_support.hpp"

namespace
{

using namespace ubii::ocr;

struct Expectation {
    PipelineKind kind;
    const char *scene;
    double min_precision;
    double min_recall;
};

// Measured (Tesseract 5.3.0, OpenCV 4.6.0, Debian 12): precision / recall.
const Expectation expectations[] = {
    {PipelineKind::pure, "baseline", 0.95, 0.95}, // 1.00 / 1.00
    {PipelineKind::pure, "sign", 0.65, 0.65},     // 0.83 / 0.83 (sparse text; "12" read as "1?")
    {PipelineKind::pure, "webcam", 0.75, 0.90},   // 0.91 / 1.00 (sparse text)
    // MSER joins its character regions into runs along a line and reads each run once, with the
    // context of its words (the thesis's single-character reads scored 0.66 / 0.66, 0.08 / 0.17
    // and 0.11 / 0.20 here).
    {PipelineKind::mser, "baseline", 0.90, 0.90}, // 1.00 / 1.00
    {PipelineKind::mser, "sign", 0.60, 0.80},     // 0.75 / 1.00: clutter read as "4" twice
    {PipelineKind::mser, "webcam", 0.75, 0.90},   // 0.91 / 1.00: clutter read as "C"
    {PipelineKind::east, "baseline", 0.65, 0.85}, // 0.80 / 0.95 (generated test network)
    {PipelineKind::east, "sign", 0.40, 0.50},     // 0.57 / 0.67
    {PipelineKind::east, "webcam", 0.25, 0.60},   // 0.38 / 0.80
    // The pretrained PP-OCRv4 detector, each line read in single-line mode.
    {PipelineKind::db, "baseline", 0.90, 0.90}, // 1.00 / 1.00 (0.98 / 0.98 at input size 960)
    {PipelineKind::db, "sign", 0.80, 0.95},     // 1.00 / 1.00
    {PipelineKind::db, "webcam", 0.80, 0.95},   // 1.00 / 1.00
};

class PipelineAccuracy : public ::testing::TestWithParam<Expectation>
{
};

TEST_P(PipelineAccuracy, FindsTheSceneWordsAtTheStatedPrecisionAndRecall)
{
    const Expectation &expected = GetParam();
    const auto &scene = test::scene(expected.scene);
    const auto pipeline = make_pipeline(test::options_for(expected.kind, scene));
    const auto words = pipeline->recognise(scene.image);
    const auto score = testdata::score_words(words, scene.words);
    RecordProperty("precision", std::to_string(score.precision()));
    RecordProperty("recall", std::to_string(score.recall()));
    std::cout << to_string(expected.kind) << " on " << expected.scene << ": "
              << testdata::describe(score) << "\n";
    EXPECT_GE(score.precision(), expected.min_precision);
    EXPECT_GE(score.recall(), expected.min_recall);
    for (const auto &word : words) {
        EXPECT_FALSE(word.text.empty());
        EXPECT_GE(word.confidence, 70.0f) << word.text; // the default minimum confidence
        EXPECT_EQ(word.box & cv::Rect(0, 0, scene.image.cols, scene.image.rows), word.box)
            << word.text;
        // Lines read at an angle keep it: EAST and DB always, MSER for its turned runs.
        if (expected.kind == PipelineKind::pure) {
            EXPECT_FALSE(word.rotated_box.has_value()) << word.text;
        }
        if (expected.kind == PipelineKind::east || expected.kind == PipelineKind::db) {
            EXPECT_TRUE(word.rotated_box.has_value()) << word.text;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(EveryPipelineOnEveryScene, PipelineAccuracy,
                         ::testing::ValuesIn(expectations),
                         [](const ::testing::TestParamInfo<Expectation> &param_info) {
                             return std::string(to_string(param_info.param.kind)) + "_" +
                                    param_info.param.scene;
                         });

} // namespace

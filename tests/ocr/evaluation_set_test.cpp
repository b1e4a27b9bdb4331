// The evaluation set (ocr/testing/evaluation_set.hpp) as a fixture of its own: its shape, that it
// is deterministic and apart from the tuning scenes, and accuracy on it a margin below what
// bench/ocr/run.sh eval measured (in the comments), for the pipelines whose claims rest on it.
#include <map>
#include <set>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include "evaluation_set.hpp"
#include "ocr_test_support.hpp"

namespace
{

using namespace ubii::ocr;
namespace data = ubii::ocr::testdata;

const std::vector<data::EvaluationScene> &evaluation()
{
    static const std::vector<data::EvaluationScene> set = data::evaluation_set();
    return set;
}

data::WordScore score_kind(Pipeline &pipeline, const std::string &kind)
{
    data::WordScore sum;
    for (const auto &entry : evaluation()) {
        if (!kind.empty() && entry.kind != kind)
            continue;
        const auto score =
            data::score_words(pipeline.recognise(entry.scene.image), entry.scene.words);
        sum.correct += score.correct;
        sum.recognised += score.recognised;
        sum.expected += score.expected;
    }
    return sum;
}

TEST(EvaluationSet, HoldsAtLeastThirtyImagesOfSixKindsWithTheirWordsInside)
{
    ASSERT_GE(evaluation().size(), 30u);
    std::map<std::string, int> per_kind;
    std::set<std::string> names;
    for (const auto &entry : evaluation()) {
        ++per_kind[entry.kind];
        EXPECT_TRUE(names.insert(entry.scene.name).second) << entry.scene.name;
        ASSERT_FALSE(entry.scene.words.empty()) << entry.scene.name;
        const cv::Rect image({}, entry.scene.image.size());
        for (const auto &word : entry.scene.words) {
            EXPECT_FALSE(word.box.empty()) << entry.scene.name << " " << word.text;
            EXPECT_EQ(word.box & image, word.box) << entry.scene.name << " " << word.text;
        }
    }
    EXPECT_EQ(per_kind.size(), data::evaluation_kinds().size());
    for (const auto &[kind, count] : per_kind)
        EXPECT_GE(count, 5) << kind;
}

TEST(EvaluationSet, IsTheSameEveryTimeAndNoTuningScene)
{
    for (const int index : {0, 13, 35}) {
        const auto again = data::evaluation_scene(index);
        const auto &first = evaluation()[static_cast<std::size_t>(index)];
        EXPECT_EQ(cv::norm(again.scene.image, first.scene.image, cv::NORM_INF), 0.0) << index;
        EXPECT_EQ(again.scene.words.size(), first.scene.words.size());
    }
    for (const auto &tuning : testdata::all_scenes()) {
        for (const auto &entry : evaluation()) {
            if (entry.scene.image.size() == tuning.image.size()) {
                EXPECT_GT(cv::norm(entry.scene.image, tuning.image, cv::NORM_L1), 0.0);
            }
        }
    }
}

// The pretrained detector's claim: nearly every word of scenes it was never shown.
TEST(EvaluationAccuracy, DbReadsNearlyEveryWordOfTheSet)
{
    auto pipeline = make_pipeline(test::options_for(PipelineKind::db, testdata::sign_scene()));
    const auto score = score_kind(*pipeline, "");
    std::cout << "db on the evaluation set: " << data::describe(score) << "\n";
    EXPECT_GE(score.recall(), 0.95);    // 0.99
    EXPECT_GE(score.precision(), 0.95); // 1.00
}

// MSER's lines follow the text's angle: turned lines are read upright (0.39 before, like PURE).
TEST(EvaluationAccuracy, MserReadsTurnedLines)
{
    auto pipeline = make_pipeline(default_options(PipelineKind::mser));
    const auto score = score_kind(*pipeline, "tilted");
    std::cout << "mser on tilted: " << data::describe(score) << "\n";
    EXPECT_GE(score.recall(), 0.9);    // 0.99
    EXPECT_GE(score.precision(), 0.9); // 0.99
}

TEST(EvaluationAccuracy, PureReadsDocuments)
{
    auto options = default_options(PipelineKind::pure);
    tesseract_options(options).segmentation = Segmentation::sparse_text;
    auto pipeline = make_pipeline(options);
    const auto score = score_kind(*pipeline, "document");
    EXPECT_GE(score.recall(), 0.95);    // 0.99
    EXPECT_GE(score.precision(), 0.95); // 1.00
}

// OpenCV 4.6 got every input size after the first wrong (no boxes at all): frames of another
// shape, and back, must read as they read alone.
TEST(EvaluationAccuracy, DbReadsFramesOfChangingSizes)
{
    const auto &label = evaluation()[12].scene; // 900x700
    const auto &photo = evaluation()[18].scene; // 1200x900
    ASSERT_NE(label.image.size(), photo.image.size());
    auto pipeline = make_pipeline(test::options_for(PipelineKind::db, photo));
    const auto label_alone = data::score_words(pipeline->recognise(label.image), label.words);
    const auto photo_next = data::score_words(pipeline->recognise(photo.image), photo.words);
    const auto label_again = data::score_words(pipeline->recognise(label.image), label.words);
    EXPECT_GE(label_alone.recall(), 0.9) << data::describe(label_alone);
    EXPECT_GE(photo_next.recall(), 0.9) << data::describe(photo_next);
    EXPECT_EQ(label_again.correct, label_alone.correct) << data::describe(label_again);
}

} // namespace

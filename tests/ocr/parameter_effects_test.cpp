// What the pipelines' parameters change, measured on the synthetic scenes.
#include <algorithm>
#include <cctype>

#include <gtest/gtest.h>

#include "ocr_test_support.hpp"

namespace
{

using namespace ubii::ocr;

std::vector<TextBox> read_with(PipelineOptions options, const testdata::Scene &scene)
{
    return make_pipeline(options)->recognise(scene.image);
}

bool only_digits(const std::string &text)
{
    return std::all_of(text.begin(), text.end(),
                       [](unsigned char c) { return std::isdigit(c) != 0; });
}

// Sparse text looks for text everywhere, without layout analysis: on the cluttered webcam frame
// it reports more candidate words than automatic segmentation (measured with no minimum
// confidence: 19 against 11), and still finds the words on the sheet (both find all 10 at the
// default minimum confidence).
TEST(SegmentationOnWebcam, SparseTextReportsMoreCandidatesAndKeepsTheWords)
{
    const auto &webcam = test::scene("webcam");
    PureOptions automatic, sparse;
    automatic.tesseract.segmentation = Segmentation::automatic;
    sparse.tesseract.segmentation = Segmentation::sparse_text;

    const auto automatic_words = read_with(automatic, webcam);
    const auto sparse_words = read_with(sparse, webcam);
    const auto automatic_score = testdata::score_words(automatic_words, webcam.words);
    const auto sparse_score = testdata::score_words(sparse_words, webcam.words);
    std::cout << "automatic: " << testdata::describe(automatic_score)
              << "\nsparse: " << testdata::describe(sparse_score) << "\n";
    EXPECT_GE(automatic_score.recall(), 0.9);
    EXPECT_GE(sparse_score.recall(), 0.9);

    automatic.tesseract.min_confidence = sparse.tesseract.min_confidence = 0.0f;
    const auto all_automatic = read_with(automatic, webcam);
    const auto all_sparse = read_with(sparse, webcam);
    std::cout << "candidates: automatic " << all_automatic.size() << ", sparse "
              << all_sparse.size() << "\n";
    EXPECT_GT(all_sparse.size(), all_automatic.size());
}

// The minimum confidence is a filter: raising it only ever removes words.
TEST(MinimumConfidence, RaisingItRemovesWordsAndKeepsTheRest)
{
    const auto &webcam = test::scene("webcam");
    PureOptions lenient, strict;
    lenient.tesseract.segmentation = strict.tesseract.segmentation = Segmentation::sparse_text;
    lenient.tesseract.min_confidence = 0.0f;
    strict.tesseract.min_confidence = 90.0f;
    const auto all = read_with(lenient, webcam);
    const auto confident = read_with(strict, webcam);
    ASSERT_LT(confident.size(), all.size());
    for (const auto &word : confident) {
        EXPECT_GE(word.confidence, 90.0f);
        EXPECT_TRUE(std::any_of(all.begin(), all.end(), [&](const TextBox &candidate) {
            return candidate.text == word.text && candidate.box == word.box;
        })) << word.text;
    }
}

// A digits-only whitelist makes MSER's reads digits only: letters are no longer reported as
// letters, and the numbers on the page are still found (read in runs along a line, the default;
// the pipeline adds the space to the whitelist so that a run still splits into words).
TEST(MserWhitelist, DigitsOnlyWhitelistYieldsOnlyDigitsAndFindsTheNumbers)
{
    const auto &baseline = test::scene("baseline");
    MserOptions plain, digits;
    digits.tesseract.variables["tessedit_char_whitelist"] = "0123456789";

    const auto plain_words = read_with(plain, baseline);
    ASSERT_TRUE(std::any_of(plain_words.begin(), plain_words.end(),
                            [](const TextBox &word) { return !only_digits(word.text); }));

    const auto digit_words = read_with(digits, baseline);
    ASSERT_FALSE(digit_words.empty());
    for (const auto &word : digit_words)
        EXPECT_TRUE(only_digits(word.text)) << word.text;
    int numbers_found = 0;
    for (const char *number : {"42", "2024", "314"})
        numbers_found += std::any_of(digit_words.begin(), digit_words.end(),
                                     [&](const TextBox &word) { return word.text == number; });
    EXPECT_GE(numbers_found, 2);
}

// What MSER's regions are read as: runs along a line (the default) give Tesseract word context and
// read the baseline page almost perfectly (measured 1.00 / 1.00); the thesis's single-character
// reads, still available, lose letters such as u, d, l to look-alikes (measured 0.59 / 0.59).
TEST(MserUnit, ReadingRunsAlongALineBeatsReadingSingleCharacters)
{
    const auto &baseline = test::scene("baseline");
    MserOptions lines, characters;
    characters.recognise_as = MserOptions::Unit::characters;
    characters.tesseract.segmentation = Segmentation::single_char;
    const auto line_score = testdata::score_words(read_with(lines, baseline), baseline.words);
    const auto character_score =
        testdata::score_words(read_with(characters, baseline), baseline.words);
    std::cout << "lines: " << testdata::describe(line_score)
              << "\ncharacters: " << testdata::describe(character_score) << "\n";
    EXPECT_GE(character_score.recall(), 0.4); // single-character mode still reads words
    EXPECT_GE(line_score.recall(), 0.95);
    EXPECT_GT(line_score.precision(), character_score.precision());
    EXPECT_GT(line_score.recall(), character_score.recall());
}

// EAST's non-maximum suppression: a lower threshold suppresses boxes at smaller overlaps, so fewer
// boxes reach Tesseract. The boxes are not visible from outside the pipeline; with no minimum
// confidence each box Tesseract reads is one reported word, so the words stand for the boxes.
TEST(EastSuppression, LowerNmsThresholdReportsFewerWords)
{
    const auto &baseline = test::scene("baseline");
    auto loose = std::get<EastOptions>(test::options_for(PipelineKind::east, baseline));
    auto tight = loose;
    loose.nms_threshold = 0.9f;
    tight.nms_threshold = 0.1f;
    loose.tesseract.min_confidence = tight.tesseract.min_confidence = 0.0f;
    const auto loose_words = read_with(loose, baseline);
    const auto tight_words = read_with(tight, baseline);
    std::cout << "words (boxes with text): NMS 0.9 " << loose_words.size() << ", NMS 0.1 "
              << tight_words.size() << "\n";
    EXPECT_LT(tight_words.size(), loose_words.size());
}

} // namespace

// `ubii-node ocr FILE...`: image files read by the OCR plugin's modules, no master.
#include <chrono>
#include <cstdio>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "cli_process.hpp"
#include "ocr_test_support.hpp"

namespace
{

using namespace std::chrono_literals;
using ::testing::HasSubstr;
namespace ocr = ubii::ocr;

ubii_cli_test::Outcome ubii_node(const std::vector<std::string> &arguments)
{
    ubii_cli_test::Process process(UBII_NODE_CLI, arguments,
                                   {"UBII_OCR_DB_MODEL=" UBII_OCR_DB_MODEL});
    return process.finish(60s);
}

// The scene as a PNG file of this test's own (ctest runs the cases in parallel), removed
// afterwards.
class SceneFile
{
  public:
    explicit SceneFile(const std::string &name)
        : scene_(ocr::test::scene(name)),
          path_(::testing::TempDir() + "ocr_cli_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name() + "_" + name +
                ".png")
    {
        cv::imwrite(path_, scene_.image);
    }
    ~SceneFile()
    {
        std::remove(path_.c_str());
    }
    const std::string &path() const
    {
        return path_;
    }
    const ocr::testdata::Scene &scene() const
    {
        return scene_;
    }

  private:
    const ocr::testdata::Scene &scene_;
    std::string path_;
};

// The words of one --json line, as text boxes to score.
std::vector<ocr::TextBox> words_of(const nlohmann::json &line)
{
    std::vector<ocr::TextBox> words;
    for (const auto &word : line.at("words")) {
        const auto &box = word.at("box");
        words.push_back(
            {word.at("text").get<std::string>(), word.at("confidence").get<float>(),
             cv::Rect(box[0].get<int>(), box[1].get<int>(), box[2].get<int>(), box[3].get<int>()),
             std::nullopt});
    }
    return words;
}

TEST(OcrCommand, ReadsEachFileAndPrintsOneJsonLinePerFile)
{
    const SceneFile sign("sign"), webcam("webcam");
    for (const std::string pipeline : {"pure", "db"}) {
        const auto outcome =
            ubii_node({"ocr", "--pipeline", pipeline, "--json", sign.path(), webcam.path()});
        ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
        std::istringstream lines(outcome.out);
        std::string line;
        for (const SceneFile *file : {&sign, &webcam}) {
            ASSERT_TRUE(std::getline(lines, line)) << outcome.out;
            const auto json = nlohmann::json::parse(line);
            EXPECT_EQ(json.at("file"), file->path());
            EXPECT_GT(json.at("ms").get<double>(), 0.0);
            const auto score = ocr::testdata::score_words(words_of(json), file->scene().words);
            EXPECT_GE(score.recall(), 0.8) << pipeline << " " << ocr::testdata::describe(score);
        }
    }
}

TEST(OcrCommand, PrintsWordsWithBoxesAndConfidencesAsText)
{
    const SceneFile sign("sign");
    const auto outcome = ubii_node({"ocr", "--pipeline", "db", sign.path()});
    ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
    EXPECT_THAT(outcome.out, ::testing::MatchesRegex("(.|\n)*: 6 words, [0-9]+ ms\n(.|\n)*"));
    EXPECT_THAT(outcome.out,
                ::testing::ContainsRegex("\"ENTRY\" +[0-9]+,[0-9]+ +[0-9]+x[0-9]+ +[0-9]+"));
}

TEST(OcrCommand, MistakesAreRefusedWithTheCliExitCodes)
{
    const SceneFile sign("sign");
    auto outcome = ubii_node({"ocr", "/nonexistent/scene.png"});
    EXPECT_EQ(outcome.exit_code, 2);
    EXPECT_THAT(outcome.err, HasSubstr("/nonexistent/scene.png: no such file"));

    outcome = ubii_node({"ocr", "--arg", "min_confidence=200", sign.path()});
    EXPECT_EQ(outcome.exit_code, 2);
    EXPECT_THAT(outcome.err, HasSubstr("minimum confidence must lie in 0..100"));

    outcome = ubii_node({"ocr", "--pipeline", "tesseract", sign.path()});
    EXPECT_EQ(outcome.exit_code, 2);

    outcome = ubii_node({"ocr", "--pipeline", "east", sign.path()});
    EXPECT_EQ(outcome.exit_code, 5);
    EXPECT_THAT(outcome.err, HasSubstr("EAST needs a model file"));

    outcome =
        ubii_node({"ocr", "--pipeline", "db", "--arg", "model=/nonexistent/db.onnx", sign.path()});
    EXPECT_EQ(outcome.exit_code, 5);
    EXPECT_THAT(outcome.err, HasSubstr("scripts/ocr-models.sh"));
}

} // namespace

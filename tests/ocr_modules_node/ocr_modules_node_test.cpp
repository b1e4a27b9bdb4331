// The OCR modules served by `ubii-node run` against the real master: the official Node.js client
// node publishes a generated scene as an Image2D (nodejs_publish_image.js), TesseractOCR_PURE from
// the OCR plugin (run --wire: the npm master assigns no sessions) recognises it and publishes an
// Object2DList, which a C node here receives and checks against the scene's ground truth; a frame
// it cannot read comes back as an error record.
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>

#include "child_process.h"
#include "scenes.hpp"
#include "test_node.h"
#include "ubii/ocr/image_records.hpp"
#include "ubii/ocr/object_records.hpp"

using ubii_test::ChildProcess;
using ubii_test::TestNode;

namespace
{

using namespace std::chrono_literals;
namespace scenes = ubii::ocr::testdata; // the scene generator (ocr/testing/scenes.hpp)

// The baseline scene as RGB8 pixels in a file of its own, for the Node.js publisher.
struct SceneFile {
    scenes::Scene scene = scenes::baseline_scene();
    ubii::ocr::Image2DData image = ubii::ocr::mat_to_image(scene.image);
    std::string directory;
    std::string pixels;

    SceneFile()
    {
        std::string pattern =
            std::string(std::getenv("TMPDIR") != nullptr ? std::getenv("TMPDIR") : "/tmp") +
            "/ocr_modules_node_test.XXXXXX";
        if (mkdtemp(pattern.data()) == nullptr) {
            throw std::runtime_error("mkdtemp failed");
        }
        directory = pattern;
        pixels = directory + "/baseline.rgb";
        std::ofstream(pixels, std::ios::binary)
            .write(reinterpret_cast<const char *>(image.data.data()),
                   static_cast<std::streamsize>(image.data.size()));
    }
    ~SceneFile()
    {
        std::remove(pixels.c_str());
        std::remove((directory + "/good").c_str());
        rmdir(directory.c_str());
    }
    SceneFile(const SceneFile &) = delete;
    SceneFile &operator=(const SceneFile &) = delete;
};

const SceneFile &scene_file()
{
    static const SceneFile file;
    return file;
}

constexpr const char *module = "TesseractOCR_PURE";

std::vector<std::string> run_command(const std::string &topic_url,
                                     const std::vector<std::string> &wires)
{
    std::vector<std::string> command = {UBII_NODE_CLI, "--service-url", ubii_test::service_url(),
                                        "--topic-url", topic_url,       "--connect-timeout",
                                        "10",          "run",           module};
    for (const std::string &wire : wires) {
        command.push_back("--wire");
        command.push_back(std::string(module) + ":" + wire);
    }
    return command;
}

std::vector<std::string> publisher_command(const std::string &topic, int burst,
                                           const std::string &good_after_file = "")
{
    const auto &file = scene_file();
    std::vector<std::string> command = {"node",
                                        UBII_NODEJS_PUBLISH_IMAGE,
                                        UBII_NODEJS_CLIENT,
                                        ubii_test::service_url(),
                                        ubii_test::topic_zmq_url(),
                                        topic,
                                        file.pixels,
                                        std::to_string(file.image.width),
                                        std::to_string(file.image.height),
                                        std::to_string(static_cast<int>(file.image.format)),
                                        std::to_string(burst)};
    if (!good_after_file.empty()) {
        command.push_back(good_after_file);
    }
    return command;
}

// Index of the first line of `child` from `from` on that matches, -1 if none yet.
int find_line(ChildProcess &child, const std::regex &pattern, size_t from = 0)
{
    auto &lines = child.lines();
    for (size_t i = from; i < lines.size(); ++i) {
        if (std::regex_search(lines[i], pattern)) {
            return static_cast<int>(i);
        }
    }
    return -1;
}

std::string all_lines(ChildProcess &child)
{
    std::string text;
    for (const auto &line : child.lines()) {
        text += "\n  " + line;
    }
    return text;
}

// The scene's words, every one recognised, nothing else.
void expect_scene_words(const ubii_test::Received &record)
{
    ASSERT_EQ(record.type, UBII_RECORD_OBJECT2D_LIST);
    const auto boxes = ubii::ocr::decode_object2d_list(record.value.data(), record.value.size());
    const auto score = scenes::score_words(boxes, scene_file().scene.words);
    EXPECT_EQ(score.correct, score.expected) << scenes::describe(score);
    EXPECT_EQ(score.recognised, score.expected) << scenes::describe(score);
    for (const auto &box : boxes) {
        EXPECT_GE(box.confidence, 70.0f) << box.text;
    }
}

std::vector<const ubii_test::Received *> on_topic(const std::vector<ubii_test::Received> &records,
                                                  const std::string &topic)
{
    std::vector<const ubii_test::Received *> found;
    for (const auto &record : records) {
        if (record.topic == topic) {
            found.push_back(&record);
        }
    }
    return found;
}

class OcrModulesNode : public ::testing::Test
{
  protected:
    void SetUp() override
    {
        ASSERT_NO_THROW(scene_file());
        ASSERT_TRUE(receiver_.wait_ready());
        receiver_.collect(output_);
        receiver_.collect(errors_);
    }

    // Polls the receiving node until the child prints a line matching `pattern`.
    int wait_for_line(ChildProcess &child, const std::string &pattern,
                      std::chrono::milliseconds timeout, size_t from = 0)
    {
        const std::regex compiled(pattern);
        int found = -1;
        receiver_.poll_until([&] { return (found = find_line(child, compiled, from)) >= 0; },
                             timeout);
        return found;
    }

    const std::string input_ = ubii_test::unique_topic("/ocr/image");
    const std::string output_ = ubii_test::unique_topic("/ocr/objects");
    const std::string errors_ = ubii_test::unique_topic("/ocr/errors");
    std::vector<std::string> wires() const
    {
        return {"image=" + input_, "objects=" + output_, "error=" + errors_};
    }
    TestNode receiver_{"c-ocr-modules-receiver"};
};

TEST_F(OcrModulesNode, RecognisesAnImageFromTheNodeJsNodeAndPublishesTheWords)
{
    ChildProcess node(run_command(ubii_test::topic_zmq_url(), wires()));
    ASSERT_GE(wait_for_line(node, "connected as client", 15s), 0)
        << "ubii-node run did not start:" << all_lines(node);

    // Bursts of three: frames that arrive while one is being recognised replace each other.
    ChildProcess publisher(publisher_command(input_, 3));
    ASSERT_TRUE(receiver_.poll_until(
        [&] { return on_topic(receiver_.received(), output_).size() >= 2; }, 30s))
        << "no Object2DList arrived; ubii-node said:" << all_lines(node)
        << "\npublisher said:" << all_lines(publisher);
    expect_scene_words(*on_topic(receiver_.received(), output_).front());
    EXPECT_TRUE(on_topic(receiver_.received(), errors_).empty());
    publisher.stop(SIGTERM, 2s);

    // The module's timing on SIGUSR1: the passes made and the frames replaced before one ran.
    node.signal(SIGUSR1);
    const int timing =
        wait_for_line(node, "timing TesseractOCR_PURE .*passes=([0-9]+).*dropped=([0-9]+)", 5s);
    ASSERT_GE(timing, 0) << all_lines(node);
    std::smatch counts;
    const std::string line = node.lines()[static_cast<size_t>(timing)];
    ASSERT_TRUE(std::regex_search(line, counts, std::regex("passes=([0-9]+).*dropped=([0-9]+)")));
    EXPECT_GE(std::stoi(counts[1]), 2) << line;
    EXPECT_GT(std::stoi(counts[2]), 0) << "bursts of three frames, none replaced: " << line;

    // SIGINT stops it cleanly, deregistered.
    EXPECT_EQ(node.stop(SIGINT, 5s), 0) << all_lines(node);
    EXPECT_GE(find_line(node, std::regex(" stopped$")), 0) << all_lines(node);
    std::cout << "ubii-node said:" << all_lines(node) << '\n';
}

TEST_F(OcrModulesNode, AMalformedFrameGivesAnErrorRecordAndTheNextGoodFrameIsRecognised)
{
    // Over WebSocket topic data this time.
    ChildProcess node(run_command(ubii_test::topic_ws_url(), wires()));
    ASSERT_GE(wait_for_line(node, "connected as client", 15s), 0)
        << "ubii-node run did not start:" << all_lines(node);

    const std::string good_file = scene_file().directory + "/good";
    std::remove(good_file.c_str());
    ChildProcess publisher(publisher_command(input_, 1, good_file));
    ASSERT_TRUE(
        receiver_.poll_until([&] { return !on_topic(receiver_.received(), errors_).empty(); }, 15s))
        << "no error record for the malformed frame:" << all_lines(node)
        << "\npublisher said:" << all_lines(publisher);
    const auto *error = on_topic(receiver_.received(), errors_).front();
    ASSERT_EQ(error->type, UBII_RECORD_STRING);
    const std::string text(error->value.begin(), error->value.end());
    EXPECT_TRUE(std::regex_match(
        text, std::regex("TesseractOCR_PURE frame [0-9]+: Image2D of 1200x900x3 needs 3240000 "
                         "bytes, it has 3236400")))
        << text;
    EXPECT_TRUE(on_topic(receiver_.received(), output_).empty()) << "a malformed frame was read";

    std::ofstream(good_file).put('\n');
    ASSERT_TRUE(
        receiver_.poll_until([&] { return !on_topic(receiver_.received(), output_).empty(); }, 15s))
        << "the good frame after the bad one was not recognised:" << all_lines(node);
    expect_scene_words(*on_topic(receiver_.received(), output_).front());
    publisher.stop(SIGTERM, 2s);
    EXPECT_EQ(node.stop(SIGTERM, 5s), 0) << all_lines(node);
}

// Failures before any frame: a clear message and the CLI's exit status.
int run_to_exit(const std::vector<std::string> &command, std::vector<std::string> &output,
                const std::string &expected)
{
    std::vector<std::string> shell = {"sh", "-c", "exec \"$0\" \"$@\" 2>&1"};
    shell.insert(shell.end(), command.begin(), command.end());
    ChildProcess child(shell);
    const auto deadline = std::chrono::steady_clock::now() + 15s;
    while (find_line(child, std::regex(expected)) < 0 &&
           std::chrono::steady_clock::now() < deadline) {
        usleep(20000);
    }
    const int status = child.stop(SIGTERM, 5s); // it has ended by then, or is ending
    output = child.lines();
    return status;
}

TEST(OcrModulesNodeErrors, TheEastModuleWithoutItsModelSaysSoBeforeConnecting)
{
    std::vector<std::string> output;
    const std::string expected = "TesseractOCR_EAST could not start: EAST needs a model file";
    EXPECT_EQ(run_to_exit({UBII_NODE_CLI, "--service-url", ubii_test::service_url(), "run",
                           "TesseractOCR_EAST", "--wire", "TesseractOCR_EAST:image=/ocr/in"},
                          output, expected),
              5);
    ASSERT_FALSE(output.empty());
    EXPECT_TRUE(std::regex_search(output.back(), std::regex(expected))) << output.back();
}

TEST(OcrModulesNodeErrors, AnArgumentOutOfRangeRefusesTheModule)
{
    std::vector<std::string> output;
    const std::string expected = "minimum confidence must lie in 0..100";
    EXPECT_EQ(run_to_exit({UBII_NODE_CLI, "run", module, "--module-arg",
                           std::string(module) + ":min_confidence=200"},
                          output, expected),
              2);
    ASSERT_FALSE(output.empty());
    EXPECT_TRUE(std::regex_search(output.back(), std::regex(expected))) << output.back();
}

} // namespace

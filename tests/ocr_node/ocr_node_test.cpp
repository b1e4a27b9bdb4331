// examples/cpp/ocr_node against the real master: the official Node.js client node publishes a
// generated scene as an Image2D (nodejs_publish_image.js), ocr_node (a child process, PURE
// pipeline) recognises it and publishes an Object2DList, which a C node here receives and checks
// against the scene's ground truth.
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
            "/ocr_node_test.XXXXXX";
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

std::vector<std::string> ocr_node_command(const std::string &input, const std::string &output,
                                          const std::string &topic_url)
{
    return {UBII_OCR_NODE,  "pure",    "--service",         ubii_test::service_url(),
            "--topic-data", topic_url, "--input",           input,
            "--output",     output,    "--connect-timeout", "10"};
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

// The scene's words, every one recognised, nothing else; and the frame line saying the same.
void expect_scene_words(const ubii_test::Received &record, ChildProcess &ocr_node)
{
    ASSERT_EQ(record.type, UBII_RECORD_OBJECT2D_LIST);
    const auto boxes = ubii::ocr::decode_object2d_list(record.value.data(), record.value.size());
    const auto score = scenes::score_words(boxes, scene_file().scene.words);
    EXPECT_EQ(score.correct, score.expected) << scenes::describe(score);
    EXPECT_EQ(score.recognised, score.expected) << scenes::describe(score);
    for (const auto &box : boxes) {
        EXPECT_GE(box.confidence, 70.0f) << box.text;
    }

    const int line =
        find_line(ocr_node, std::regex("^frame [0-9]+ 1200x900: " + std::to_string(boxes.size()) +
                                       " boxes, [0-9.]+ ms, [0-9]+ dropped: \""));
    ASSERT_GE(line, 0) << "no frame line for " << boxes.size() << " boxes:" << all_lines(ocr_node);
    for (const auto &box : boxes) {
        EXPECT_NE(ocr_node.lines()[static_cast<size_t>(line)].find('"' + box.text + '"'),
                  std::string::npos)
            << box.text;
    }
}

class OcrNode : public ::testing::Test
{
  protected:
    void SetUp() override
    {
        ASSERT_NO_THROW(scene_file());
        ASSERT_TRUE(receiver_.wait_ready());
        receiver_.collect(output_);
    }

    // Polls the receiving node until ocr_node prints a line matching `pattern`.
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
    TestNode receiver_{"c-ocr-node-receiver"};
};

TEST_F(OcrNode, RecognisesAnImageFromTheNodeJsNodeAndPublishesTheWords)
{
    ChildProcess ocr_node(ocr_node_command(input_, output_, ubii_test::topic_zmq_url()));
    ASSERT_GE(wait_for_line(ocr_node, "^ocr_node: pure pipeline ready", 15s), 0)
        << "ocr_node did not start:" << all_lines(ocr_node);

    // Bursts of three: frames that arrive while one is being recognised are dropped.
    ChildProcess publisher(publisher_command(input_, 3));
    ASSERT_TRUE(receiver_.poll_until([&] { return receiver_.received().size() >= 2; }, 15s))
        << "no Object2DList arrived; ocr_node said:" << all_lines(ocr_node)
        << "\npublisher said:" << all_lines(publisher);
    expect_scene_words(receiver_.received().front(), ocr_node);
    publisher.stop(SIGTERM, 2s);

    // SIGINT stops it cleanly; every frame received was recognised or dropped.
    EXPECT_EQ(ocr_node.stop(SIGINT, 5s), 0) << all_lines(ocr_node);
    std::smatch summary;
    const std::string last = ocr_node.lines().empty() ? "" : ocr_node.lines().back();
    ASSERT_TRUE(std::regex_match(
        last, summary,
        std::regex("ocr_node: stopped \\(signal 2\\): ([0-9]+) frames, 0 failed, ([0-9]+) "
                   "dropped of ([0-9]+) received")))
        << last;
    const int frames = std::stoi(summary[1]), dropped = std::stoi(summary[2]),
              received = std::stoi(summary[3]);
    EXPECT_EQ(frames + dropped, received);
    EXPECT_GE(frames, 2);
    EXPECT_GT(dropped, 0) << "bursts of three frames, none dropped";
    std::cout << "ocr_node said:" << all_lines(ocr_node) << '\n';
}

TEST_F(OcrNode, AMalformedFrameGivesAnErrorLineAndTheNextGoodFrameIsRecognised)
{
    // Over WebSocket topic data this time.
    ChildProcess ocr_node(ocr_node_command(input_, output_, ubii_test::topic_ws_url()));
    ASSERT_GE(wait_for_line(ocr_node, "^ocr_node: pure pipeline ready", 15s), 0)
        << "ocr_node did not start:" << all_lines(ocr_node);

    const std::string good_file = scene_file().directory + "/good";
    std::remove(good_file.c_str());
    ChildProcess publisher(publisher_command(input_, 1, good_file));
    const int error_line = wait_for_line(
        ocr_node, "^frame [0-9]+ error: Image2D of 1200x900x3 needs 3240000 bytes, it has 3236400$",
        15s);
    ASSERT_GE(error_line, 0) << "no error line for the malformed frame:" << all_lines(ocr_node)
                             << "\npublisher said:" << all_lines(publisher);
    EXPECT_TRUE(receiver_.received().empty()) << "a malformed frame was published";

    std::ofstream(good_file).put('\n');
    ASSERT_TRUE(receiver_.poll_until([&] { return !receiver_.received().empty(); }, 15s))
        << "ocr_node did not recognise the good frame after the bad one:" << all_lines(ocr_node);
    EXPECT_GE(wait_for_line(ocr_node, "^frame [0-9]+ 1200x900: ", 1s,
                            static_cast<size_t>(error_line) + 1),
              0);
    expect_scene_words(receiver_.received().front(), ocr_node);
    publisher.stop(SIGTERM, 2s);
    EXPECT_EQ(ocr_node.stop(SIGTERM, 5s), 0) << all_lines(ocr_node);
    std::cout << "ocr_node said:" << all_lines(ocr_node) << '\n';
}

// Failures before any frame: a clear message and exit status 1.
int run_to_exit(const std::vector<std::string> &arguments, std::vector<std::string> &output,
                const std::string &expected)
{
    std::vector<std::string> command = {"sh", "-c", "exec \"$0\" \"$@\" 2>&1", UBII_OCR_NODE};
    command.insert(command.end(), arguments.begin(), arguments.end());
    ChildProcess child(command);
    const auto deadline = std::chrono::steady_clock::now() + 15s;
    while (find_line(child, std::regex(expected)) < 0 &&
           std::chrono::steady_clock::now() < deadline) {
        usleep(20000);
    }
    const int status = child.stop(SIGTERM, 5s); // it has ended by then, or is ending
    output = child.lines();
    return status;
}

TEST(OcrNodeErrors, TheEastPipelineWithoutItsModelFileSaysSo)
{
    std::vector<std::string> output;
    const std::string expected = "^ocr_node: cannot start the east pipeline: EAST model file "
                                 "'/nonexistent/frozen_east_text_detection.pb' is missing";
    EXPECT_EQ(run_to_exit({"east", "/nonexistent/frozen_east_text_detection.pb"}, output, expected),
              1);
    ASSERT_FALSE(output.empty());
    EXPECT_TRUE(std::regex_search(output.back(), std::regex(expected))) << output.back();
}

TEST(OcrNodeErrors, AMasterThatIsNotReachableIsReportedAfterTheTimeout)
{
    // Nothing listens there: the test master uses port_base() .. port_base() + 3.
    const std::string service = "tcp://127.0.0.1:" + std::to_string(ubii_test::port_base() + 40);
    const std::string expected =
        "^ocr_node: the master at " + service + " / [^ ]+ was not reachable within 1 s";
    std::vector<std::string> output;
    const auto start = std::chrono::steady_clock::now();
    EXPECT_EQ(
        run_to_exit({"pure", "--service", service, "--connect-timeout", "1"}, output, expected), 1);
    EXPECT_LT(std::chrono::steady_clock::now() - start, 10s);
    ASSERT_FALSE(output.empty());
    EXPECT_TRUE(std::regex_search(output.back(), std::regex(expected))) << output.back();
}

} // namespace

// ocr_session: the OCR modules at work. A node publishes generated scene images on /demo/ocr/image;
// TesseractOCR_PURE and TextDetection_DB, run by `ubii-node run` (the OCR plugin), read them and
// publish the words on /demo/ocr/words/<module>; this program prints the words per image and how
// long each module took, from publishing the image to receiving its words.
//
// With --session it first asks the master for a session mapping the topics to the modules (the
// current master assigns them to the `ubii-node run` offering them; scripts/run.sh) and stops it
// at the end. Without, the modules must be running already, wired to the topics
// (`ubii-node run --wire`, for the npm master, which assigns no sessions).
//
//   ocr_session_cpp SERVICE_URL TOPIC_URL [--session]
#include <chrono>
#include <cstdio>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include "scenes.hpp"
#include "ubii/ocr/image_records.hpp"
#include "ubii/ubii.hpp"

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

namespace
{

const std::vector<std::string> modules = {"TesseractOCR_PURE", "TextDetection_DB"};
const std::string image_topic = "/demo/ocr/image";
const std::string words_topic = "/demo/ocr/words/";
const std::string error_topic = "/demo/ocr/errors";

ubii::Session ocr_session()
{
    ubii::Session session;
    session.set_name("ocr-demo");
    for (const std::string &module : modules) {
        session.add_processing_modules()->set_name(module);
        ubii::IOMapping &mapping = *session.add_io_mappings();
        mapping.set_processing_module_name(module);
        auto &input = *mapping.add_input_mappings();
        input.set_input_name("image");
        input.set_topic(image_topic);
        auto &objects = *mapping.add_output_mappings();
        objects.set_output_name("objects");
        objects.set_topic(words_topic + module);
        auto &error = *mapping.add_output_mappings();
        error.set_output_name("error");
        error.set_topic(error_topic);
    }
    return session;
}

ubii::Image2D image_of(const cv::Mat &bgr)
{
    const ubii::ocr::Image2DData data = ubii::ocr::mat_to_image(bgr);
    ubii::Image2D image;
    image.set_width(data.width);
    image.set_height(data.height);
    image.set_data_format(static_cast<ubii::Image2D::DataFormat>(data.format));
    image.set_data(data.data.data(), data.data.size());
    return image;
}

std::string words_text(const ubii::Object2DList &words, std::size_t max_chars)
{
    std::string text;
    for (const auto &word : words.elements()) {
        if (text.size() + word.id().size() + 1 > max_chars)
            return text + " ...";
        text += (text.empty() ? "" : " ") + word.id();
    }
    return text;
}

struct Arrival {
    ubii::Object2DList words;
    Clock::time_point at;
};

} // namespace

int main(int argc, char **argv)
{
    if (argc < 3) {
        std::fprintf(stderr, "usage: ocr_session_cpp SERVICE_URL TOPIC_URL [--session]\n");
        return 2;
    }
    const bool with_session = argc > 3 && std::strcmp(argv[3], "--session") == 0;
    try {
        ubii::NodeOptions options;
        options.service_url = argv[1];
        options.topic_url = argv[2];
        options.name = "ocr-demo";
        ubii::Node node(options);
        node.connect(10s);

        std::map<std::string, Arrival> arrived;
        std::vector<std::string> errors;
        std::vector<ubii::Subscription> subscriptions;
        for (const std::string &module : modules)
            subscriptions.push_back(node.subscribe<ubii::Object2DList>(
                words_topic + module,
                [&arrived, module](const ubii::Object2DList &words, const ubii::RecordInfo &) {
                    arrived[module] = {words, Clock::now()};
                }));
        subscriptions.push_back(node.subscribe<std::string>(
            error_topic, [&errors](const std::string &error, const ubii::RecordInfo &) {
                errors.push_back(error);
            }));
        const auto poll_until = [&node](const auto &done, std::chrono::milliseconds timeout) {
            const auto until = Clock::now() + timeout;
            while (!done() && Clock::now() < until)
                node.poll(10ms);
            return done();
        };
        poll_until([&node] { return !node.subscriptions_pending(); }, 5s);

        std::string session_id;
        if (with_session) {
            auto started = node.sessions().start(ocr_session());
            if (!poll_until([&] { return started.done(); }, 10s))
                throw ubii::Timeout("the master did not answer the session start");
            session_id = started.get().id();
            std::printf("session %s started: %s %s on the node offering them\n", session_id.c_str(),
                        modules[0].c_str(), modules[1].c_str());
        }

        const auto scenes = ubii::ocr::testdata::all_scenes();
        int failures = 0;
        for (const auto &scene : scenes) {
            arrived.clear();
            errors.clear();
            const Clock::time_point sent = Clock::now();
            node.publish(image_topic, image_of(scene.image));
            // The first image also waits for the master to hand the session's modules their
            // subscriptions, and for each module's first pass to load its model.
            const bool complete = poll_until(
                [&] { return arrived.size() == modules.size() || !errors.empty(); }, 60s);
            std::printf("%s %dx%d (%zu words in the image)\n", scene.name.c_str(), scene.image.cols,
                        scene.image.rows, scene.words.size());
            for (const std::string &module : modules) {
                const auto found = arrived.find(module);
                if (found == arrived.end()) {
                    std::printf("  %-18s no words came back\n", module.c_str());
                    ++failures;
                    continue;
                }
                std::printf(
                    "  %-18s %2d words %5.0f ms  %s\n", module.c_str(),
                    found->second.words.elements_size(),
                    std::chrono::duration<double, std::milli>(found->second.at - sent).count(),
                    words_text(found->second.words, 80).c_str());
            }
            for (const std::string &error : errors)
                std::printf("  error: %s\n", error.c_str());
            if (!complete)
                ++failures;
        }

        if (with_session) {
            auto stopped = node.sessions().stop(session_id);
            poll_until([&] { return stopped.done(); }, 10s);
            std::printf("session %s stopped\n", session_id.c_str());
        }
        return failures == 0 ? 0 : 1;
    } catch (const std::exception &error) {
        std::fprintf(stderr, "ocr_session_cpp: %s\n", error.what());
        return 1;
    }
}

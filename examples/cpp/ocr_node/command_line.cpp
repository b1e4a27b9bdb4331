#include "command_line.hpp"

#include <cmath>
#include <cstdlib>
#include <functional>
#include <limits>
#include <map>
#include <utility>
#include <variant>
#include <vector>

namespace ocr_node
{
namespace
{

double to_number(const std::string &flag, const std::string &text)
{
    char *end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || end == nullptr || *end != '\0' || !std::isfinite(value))
        throw UsageError(flag + " needs a number, not '" + text + "'");
    return value;
}

int to_int(const std::string &flag, const std::string &text)
{
    const double value = to_number(flag, text);
    if (value < std::numeric_limits<int>::min() || value > std::numeric_limits<int>::max() ||
        value != std::trunc(value))
        throw UsageError(flag + " needs a whole number, not '" + text + "'");
    return static_cast<int>(value);
}

ubii::ocr::Segmentation to_segmentation(const std::string &text)
{
    using ubii::ocr::Segmentation;
    static const std::map<std::string, Segmentation> names = {
        {"auto", Segmentation::automatic},   {"block", Segmentation::single_block},
        {"line", Segmentation::single_line}, {"word", Segmentation::single_word},
        {"char", Segmentation::single_char}, {"sparse", Segmentation::sparse_text}};
    const auto found = names.find(text);
    if (found == names.end())
        throw UsageError("--psm takes auto, block, line, word, char or sparse, not '" + text + "'");
    return found->second;
}

template <typename Options> Options &options_of(Settings &settings, const std::string &flag)
{
    auto *options = std::get_if<Options>(&settings.pipeline);
    if (options == nullptr)
        throw UsageError(flag + " does not apply to the " +
                         std::string(to_string(ubii::ocr::kind_of(settings.pipeline))) +
                         " pipeline");
    return *options;
}

cv::Size to_size(const std::string &text)
{
    const auto x = text.find('x');
    if (x == std::string::npos)
        throw UsageError("--east-size takes WIDTHxHEIGHT, not '" + text + "'");
    return {to_int("--east-size", text.substr(0, x)), to_int("--east-size", text.substr(x + 1))};
}

using Setter = std::function<void(Settings &, const std::string &)>;

// Flags that take a value. The pipeline is known when they are applied.
const std::map<std::string, Setter> &value_flags()
{
    using namespace ubii::ocr;
    static const std::map<std::string, Setter> flags = {
        {"--service", [](Settings &s, const std::string &v) { s.service_url = v; }},
        {"--topic-data", [](Settings &s, const std::string &v) { s.topic_url = v; }},
        {"--input", [](Settings &s, const std::string &v) { s.input_topic = v; }},
        {"--output", [](Settings &s, const std::string &v) { s.output_topic = v; }},
        {"--connect-timeout",
         [](Settings &s, const std::string &v) {
             s.connect_timeout_s = to_number("--connect-timeout", v);
         }},
        {"--lang",
         [](Settings &s, const std::string &v) { tesseract_options(s.pipeline).language = v; }},
        {"--tessdata",
         [](Settings &s, const std::string &v) { tesseract_options(s.pipeline).data_path = v; }},
        {"--psm",
         [](Settings &s, const std::string &v) {
             tesseract_options(s.pipeline).segmentation = to_segmentation(v);
         }},
        {"--min-confidence",
         [](Settings &s, const std::string &v) {
             tesseract_options(s.pipeline).min_confidence =
                 static_cast<float>(to_number("--min-confidence", v));
         }},
        {"--var",
         [](Settings &s, const std::string &v) {
             const auto equals = v.find('=');
             if (equals == std::string::npos || equals == 0)
                 throw UsageError("--var takes NAME=VALUE, not '" + v + "'");
             tesseract_options(s.pipeline).variables[v.substr(0, equals)] = v.substr(equals + 1);
         }},
        {"--padding",
         [](Settings &s, const std::string &v) {
             const int padding = to_int("--padding", v);
             if (auto *east = std::get_if<EastOptions>(&s.pipeline))
                 east->padding_px = padding;
             else
                 options_of<MserOptions>(s, "--padding").padding_px = padding;
         }},
        {"--unit",
         [](Settings &s, const std::string &v) {
             using ubii::ocr::MserOptions;
             using ubii::ocr::Segmentation;
             static const std::map<std::string, std::pair<MserOptions::Unit, Segmentation>> units =
                 {{"characters", {MserOptions::Unit::characters, Segmentation::single_char}},
                  {"words", {MserOptions::Unit::words, Segmentation::single_word}},
                  {"lines", {MserOptions::Unit::lines, Segmentation::single_line}}};
             const auto found = units.find(v);
             if (found == units.end())
                 throw UsageError("--unit takes characters, words or lines, not '" + v + "'");
             auto &mser = options_of<MserOptions>(s, "--unit");
             mser.recognise_as = found->second.first;
             mser.tesseract.segmentation = found->second.second; // the mode that reads the unit
         }},
        {"--delta",
         [](Settings &s, const std::string &v) {
             options_of<MserOptions>(s, "--delta").delta = to_int("--delta", v);
         }},
        {"--min-area",
         [](Settings &s, const std::string &v) {
             options_of<MserOptions>(s, "--min-area").min_area = to_int("--min-area", v);
         }},
        {"--max-area",
         [](Settings &s, const std::string &v) {
             options_of<MserOptions>(s, "--max-area").max_area = to_int("--max-area", v);
         }},
        {"--max-variation",
         [](Settings &s, const std::string &v) {
             options_of<MserOptions>(s, "--max-variation").max_variation =
                 to_number("--max-variation", v);
         }},
        {"--nms",
         [](Settings &s, const std::string &v) {
             options_of<EastOptions>(s, "--nms").nms_threshold =
                 static_cast<float>(to_number("--nms", v));
         }},
        {"--east-confidence",
         [](Settings &s, const std::string &v) {
             options_of<EastOptions>(s, "--east-confidence").confidence_threshold =
                 static_cast<float>(to_number("--east-confidence", v));
         }},
        {"--east-size",
         [](Settings &s, const std::string &v) {
             options_of<EastOptions>(s, "--east-size").input_size = to_size(v);
         }},
    };
    return flags;
}

} // namespace

Settings parse_command_line(int argc, char **argv)
{
    std::vector<std::string> positional;
    std::vector<std::pair<std::string, std::string>> flags;
    bool colour = false;
    Settings settings;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "-h" || arg == "--help") {
            settings.help = true;
            return settings;
        }
        if (arg == "--colour") {
            colour = true;
        } else if (arg.rfind("--", 0) == 0) {
            if (value_flags().count(arg) == 0)
                throw UsageError("unknown option " + arg);
            if (i + 1 >= argc)
                throw UsageError(arg + " needs a value");
            flags.emplace_back(arg, argv[++i]);
        } else {
            positional.push_back(arg);
        }
    }
    if (positional.empty())
        throw UsageError("which pipeline? pure, mser or east");
    settings.pipeline = ubii::ocr::default_options(ubii::ocr::parse_pipeline_kind(positional[0]));
    if (auto *east = std::get_if<ubii::ocr::EastOptions>(&settings.pipeline)) {
        if (positional.size() < 2)
            throw UsageError("the east pipeline needs the model file: ocr_node east "
                             "PATH/frozen_east_text_detection.pb");
        east->model_path = positional[1];
    }
    const std::size_t expected =
        std::holds_alternative<ubii::ocr::EastOptions>(settings.pipeline) ? 2 : 1;
    if (positional.size() > expected)
        throw UsageError("unexpected argument '" + positional[expected] + "'");
    if (colour)
        options_of<ubii::ocr::MserOptions>(settings, "--colour").use_colour = true;
    for (const auto &[flag, value] : flags)
        value_flags().at(flag)(settings, value);
    if (!(settings.connect_timeout_s > 0 && settings.connect_timeout_s <= 1e6))
        throw UsageError("--connect-timeout must be more than 0 and at most 1e6 seconds");
    return settings;
}

std::string usage()
{
    return R"(usage: ocr_node [OPTIONS] pure|mser|east [EAST_MODEL]

Subscribes to Image2D records on the input topic, recognises the text in the newest one with the
chosen pipeline and publishes the words as an Object2DList on the output topic. Prints one line
per frame. Stop it with Ctrl-C (SIGINT) or SIGTERM.

  EAST_MODEL              the EAST network (east only), e.g. frozen_east_text_detection.pb

master and topics:
  --service URL           service endpoint (tcp://127.0.0.1:8101)
  --topic-data URL        topic data endpoint, tcp:// or ws:// (tcp://127.0.0.1:8103)
  --input TOPIC           images to read (/ocr/image)
  --output TOPIC          where the Object2DList goes (/ocr/objects)
  --connect-timeout S     give up if the master is not reached within S seconds (10)

Tesseract (every pipeline):
  --lang LANG             language data (eng)
  --tessdata DIR          folder holding LANG.traineddata (Tesseract's default)
  --psm MODE              auto|block|line|word|char|sparse (pure: auto, mser: line, east: line)
  --min-confidence N      drop words below N, 0..100 (70)
  --var NAME=VALUE        any Tesseract variable, e.g. tessedit_char_whitelist=0123456789

mser:
  --unit U                what Tesseract reads: characters|words|lines (lines); sets --psm to
                          char|word|line (a --psm after it overrides)
  --padding PX            around each unit (6)
  --delta N, --min-area N, --max-area N, --max-variation X   MSER parameters (3, 30, 14400, 0.25)
  --colour                MSER on the colour image (MSCR)

east:
  --padding PX            around each box (4)
  --nms X                 non-maximum suppression overlap threshold (0.5)
  --east-confidence X     score threshold (0.5)
  --east-size WxH         network input size, multiples of 32 (320x320)
)";
}

} // namespace ocr_node

#include "ubii/ocr/mser_pipeline.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <string>

#include <opencv2/features2d.hpp>
#include <opencv2/imgproc.hpp>

#include "character_regions.hpp"
#include "grayscale.hpp"
#include "line_crop.hpp"
#include "option_checks.hpp"
#include "tesseract_engine.hpp"
#include "ubii/ocr/error.hpp"
#include "word_grouping.hpp"

namespace ubii::ocr
{

namespace
{

// A run of three or more characters whose line turns further than this is cut out upright (two
// characters' boxes say little about an angle). At 2 degrees a long line of a slightly turned
// page drifts by its own height and Tesseract lost a word at its start (evaluation set).
constexpr float max_level_turn_degrees = 1.0f;

// Clutter (edges, lines) read as text comes back as punctuation alone ('\', '|', '/'): not text.
bool has_letter_or_digit(const std::string &text)
{
    // Bytes of multi-byte UTF-8 sequences (>= 0x80) count: letters beyond ASCII are text too.
    return std::any_of(text.begin(), text.end(), [](char c) {
        const auto byte = static_cast<unsigned char>(c);
        return byte >= 0x80 || std::isalnum(byte) != 0;
    });
}

// A character whitelist without a space makes the LSTM engine drop the spaces between words
// (tesseract-ocr/tesseract#2923): a run read as one line would come back as a single word. The
// space is no character a user means to exclude, so it is allowed when reading lines.
TesseractOptions engine_options(const MserOptions &options)
{
    TesseractOptions chosen = options.tesseract;
    const auto whitelist = chosen.variables.find("tessedit_char_whitelist");
    if (options.recognise_as == MserOptions::Unit::lines && whitelist != chosen.variables.end() &&
        !whitelist->second.empty() && whitelist->second.find(' ') == std::string::npos)
        whitelist->second += ' ';
    return chosen;
}

} // namespace

struct MserPipeline::Impl {
    explicit Impl(const MserOptions &chosen)
        : options(chosen), engine(engine_options(chosen)),
          mser(cv::MSER::create(chosen.delta, chosen.min_area, chosen.max_area,
                                chosen.max_variation, chosen.min_diversity))
    {
    }
    std::vector<TextBox> read_characters(const std::vector<std::vector<cv::Point>> &regions,
                                         const std::vector<detail::CharacterCandidate> &candidates);
    std::vector<TextBox> read_runs(const cv::Mat &gray,
                                   const std::vector<detail::CharacterCandidate> &candidates,
                                   float max_gap);

    MserOptions options;
    detail::TesseractEngine engine;
    cv::Ptr<cv::MSER> mser;
};

MserPipeline::MserPipeline(const MserOptions &options)
{
    detail::check(options);
    impl_ = std::make_unique<Impl>(options);
}

MserPipeline::~MserPipeline() = default;

std::vector<TextBox>
MserPipeline::Impl::read_characters(const std::vector<std::vector<cv::Point>> &regions,
                                    const std::vector<detail::CharacterCandidate> &candidates)
{
    // Each character is read from its own region's pixels, drawn black on white with the padding
    // around it. Cut from the frame instead, the padding takes in parts of the neighbouring
    // letters, which single-character mode then reads as extra characters. This also turns light
    // text on a dark ground into dark on light.
    const int padding = options.padding_px;
    std::vector<TextBox> characters;
    for (const auto &candidate : candidates) {
        const cv::Point origin = candidate.box.tl() - cv::Point(padding, padding);
        cv::Mat patch(candidate.box.height + 2 * padding, candidate.box.width + 2 * padding,
                      CV_8UC1, cv::Scalar(255));
        for (const std::size_t region : candidate.regions)
            for (const auto &pixel : regions[region])
                patch.at<std::uint8_t>(pixel - origin) = 0;
        engine.set_image(patch);
        auto character = options.tesseract.segmentation == Segmentation::single_char
                             ? engine.read_best_symbol(candidate.box)
                             : engine.read_as_one(candidate.box);
        if (character)
            characters.push_back(std::move(*character));
    }
    return detail::group_into_words(characters, options.word_gap);
}

std::vector<TextBox> MserPipeline::Impl::read_runs(
    const cv::Mat &gray, const std::vector<detail::CharacterCandidate> &candidates, float max_gap)
{
    std::vector<cv::Rect> characters;
    for (const auto &candidate : candidates)
        characters.push_back(candidate.box);
    const auto runs =
        detail::merge_runs_sharing_ink(characters, detail::cluster_words(characters, max_gap));

    // A run's line: the smallest rectangle, at any angle, around its characters. Level runs are
    // read where they are, through SetRectangle on one SetImage of the frame (no copies); a run
    // turned further is cut out upright first, because its upright bounding box would take in
    // parts of the lines above and below, which single-line mode then reads as one line.
    const cv::Rect frame(0, 0, gray.cols, gray.rows);
    const cv::Point margin(options.padding_px, options.padding_px);
    std::vector<TextBox> words;
    const auto keep = [&words](TextBox &word) {
        if (has_letter_or_digit(word.text))
            words.push_back(std::move(word));
    };
    std::vector<detail::LineQuad> turned;
    engine.set_image(gray);
    for (const auto &members : runs) {
        std::vector<cv::Point2f> corners;
        for (const std::size_t i : members) {
            const cv::Rect &box = characters[i];
            corners.emplace_back(static_cast<float>(box.x), static_cast<float>(box.y));
            corners.emplace_back(static_cast<float>(box.br().x), static_cast<float>(box.y));
            corners.emplace_back(static_cast<float>(box.br().x), static_cast<float>(box.br().y));
            corners.emplace_back(static_cast<float>(box.x), static_cast<float>(box.br().y));
        }
        std::array<cv::Point2f, 4> line;
        cv::minAreaRect(corners).points(line.data());
        const detail::LineQuad quad = detail::as_text_quad(line);
        if (members.size() > 2 && detail::turn_degrees(quad) > max_level_turn_degrees) {
            turned.push_back(quad);
            continue;
        }
        const cv::Rect run = cv::boundingRect(corners);
        engine.set_rectangle(cv::Rect(run.tl() - margin, run.br() + margin) & frame);
        for (auto &word : engine.read_words())
            keep(word);
    }
    for (const auto &quad : turned) {
        const float height = std::hypot(quad[3].x - quad[0].x, quad[3].y - quad[0].y);
        const detail::UprightLine line = detail::upright_line(
            gray, quad, static_cast<float>(options.padding_px) / std::max(height, 1.0f));
        if (line.pixels.empty())
            continue;
        engine.set_image(line.pixels);
        for (auto &word : engine.read_words())
            if (detail::place_in_frame(word, line.to_frame, frame))
                keep(word);
    }
    detail::sort_reading_order(words);
    return words;
}

std::vector<TextBox> MserPipeline::recognise_frame(const cv::Mat &image)
{
    const cv::Mat gray = detail::to_grayscale(image);
    std::vector<std::vector<cv::Point>> regions;
    std::vector<cv::Rect> region_boxes;
    const bool colour = impl_->options.use_colour && image.channels() != 1;
    // OpenCV's grayscale MSER finds dark-on-light and light-on-dark regions (two passes), so
    // light text on a dark panel needs no inverted pass of its own.
    impl_->mser->detectRegions(colour ? detail::to_bgr(image) : gray, regions, region_boxes);
    const auto candidates = detail::character_candidates(region_boxes);
    switch (impl_->options.recognise_as) {
    case MserOptions::Unit::characters:
        return impl_->read_characters(regions, candidates);
    case MserOptions::Unit::words:
        return impl_->read_runs(gray, candidates, impl_->options.word_gap);
    case MserOptions::Unit::lines:
        break;
    }
    return impl_->read_runs(gray, candidates, impl_->options.line_gap);
}

} // namespace ubii::ocr

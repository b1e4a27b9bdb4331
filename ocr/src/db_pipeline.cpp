#include "ubii/ocr/db_pipeline.hpp"

#include <cmath>
#include <cstdlib>

#include <opencv2/imgproc.hpp>

#include "db_detector.hpp"
#include "grayscale.hpp"
#include "option_checks.hpp"
#include "tesseract_engine.hpp"
#include "ubii/ocr/error.hpp"

namespace ubii::ocr
{
namespace
{

// Tesseract's LSTM model reads lines best with an x-height of about 20 px; smaller lines are
// scaled up to this height (capitals plus padding) before reading.
constexpr float min_read_height = 48.0f;

float distance(cv::Point2f from, cv::Point2f to)
{
    return std::hypot(to.x - from.x, to.y - from.y);
}

// The line turned upright, padded and scaled to a readable height, and the transform from the
// crop's pixels back to the frame's.
struct UprightLine {
    cv::Mat pixels;
    cv::Matx33d to_frame;
};

UprightLine upright(const cv::Mat &gray, const detail::LineQuad &quad, float padding)
{
    const float width = std::max(distance(quad[0], quad[1]), distance(quad[3], quad[2]));
    const float height = std::max(distance(quad[0], quad[3]), distance(quad[1], quad[2]));
    const float margin = padding * height;
    const float scale = std::max(1.0f, min_read_height / (height + 2 * margin));
    const float left = margin * scale, top = margin * scale;
    const float right = left + width * scale, bottom = top + height * scale;
    const cv::Point2f corners[4] = {quad[0], quad[1], quad[2], quad[3]};
    const cv::Point2f target[4] = {{left, top}, {right, top}, {right, bottom}, {left, bottom}};
    const cv::Mat to_crop = cv::getPerspectiveTransform(corners, target);
    UprightLine line;
    cv::warpPerspective(gray, line.pixels, to_crop,
                        cv::Size(static_cast<int>(std::ceil(right + left)),
                                 static_cast<int>(std::ceil(bottom + top))),
                        cv::INTER_LINEAR, cv::BORDER_REPLICATE);
    line.to_frame = cv::Matx33d(cv::Mat(to_crop.inv()));
    return line;
}

// A word's box in the crop, back in the frame: its corners through the inverse transform.
void place_in_frame(TextBox &word, const cv::Matx33d &to_frame, const cv::Rect &frame)
{
    const cv::Rect &box = word.box;
    const std::vector<cv::Point2f> in_crop = {
        cv::Point2f(static_cast<float>(box.x), static_cast<float>(box.y)),
        cv::Point2f(static_cast<float>(box.x + box.width), static_cast<float>(box.y)),
        cv::Point2f(static_cast<float>(box.x + box.width), static_cast<float>(box.y + box.height)),
        cv::Point2f(static_cast<float>(box.x), static_cast<float>(box.y + box.height))};
    std::vector<cv::Point2f> in_frame;
    cv::perspectiveTransform(in_crop, in_frame, cv::Mat(to_frame));
    word.box = cv::boundingRect(in_frame) & frame;
    word.rotated_box = cv::minAreaRect(in_frame);
}

} // namespace

std::string default_db_model_path()
{
    if (const char *chosen = std::getenv("UBII_OCR_DB_MODEL"); chosen != nullptr && *chosen != 0)
        return chosen;
    std::string cache;
    if (const char *ubii = std::getenv("UBII_CACHE_DIR"); ubii != nullptr && *ubii != 0)
        cache = ubii;
    else if (const char *xdg = std::getenv("XDG_CACHE_HOME"); xdg != nullptr && *xdg != 0)
        cache = std::string(xdg) + "/libubii";
    else if (const char *home = std::getenv("HOME"); home != nullptr && *home != 0)
        cache = std::string(home) + "/.cache/libubii";
    else
        cache = ".cache/libubii";
    return cache + "/models/ppocrv4-det/ppocrv4_det_opencv.onnx";
}

struct DbPipeline::Impl {
    explicit Impl(const DbOptions &chosen)
        : options(chosen), detector(chosen), engine(chosen.tesseract)
    {
    }
    DbOptions options;
    detail::DbDetector detector;
    detail::TesseractEngine engine;
};

DbPipeline::DbPipeline(const DbOptions &options)
{
    detail::check(options);
    impl_ = std::make_unique<Impl>(options);
}

DbPipeline::~DbPipeline() = default;

std::vector<TextBox> DbPipeline::recognise_frame(const cv::Mat &image)
{
    const cv::Mat gray = detail::to_grayscale(image);
    const cv::Rect frame(0, 0, gray.cols, gray.rows);
    std::vector<TextBox> words;
    for (const auto &quad : impl_->detector.detect(detail::to_bgr(image))) {
        UprightLine line = upright(gray, quad, impl_->options.padding);
        if (line.pixels.empty())
            continue;
        impl_->engine.set_image(line.pixels);
        for (auto &word : impl_->engine.read_words()) {
            place_in_frame(word, line.to_frame, frame);
            if (!word.box.empty())
                words.push_back(std::move(word));
        }
    }
    return words;
}

} // namespace ubii::ocr

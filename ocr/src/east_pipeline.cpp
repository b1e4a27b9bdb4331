#include "ubii/ocr/east_pipeline.hpp"

#include <cmath>
#include <fstream>

#include <opencv2/dnn.hpp>
#include <opencv2/imgproc.hpp>

#include "grayscale.hpp"
#include "option_checks.hpp"
#include "tesseract_engine.hpp"
#include "ubii/ocr/error.hpp"

namespace ubii::ocr
{
namespace
{

cv::dnn::TextDetectionModel_EAST load_detector(const EastOptions &options)
{
    if (options.model_path.empty())
        throw ModelError(
            "EAST needs a model file (EastOptions::model_path, the module argument model); "
            "libubii ships none and "
            "downloads nothing: use the public frozen_east_text_detection.pb");
    if (!std::ifstream(options.model_path, std::ios::binary).good())
        throw ModelError("EAST model file '" + options.model_path + "' is missing or unreadable");
    try {
        cv::dnn::TextDetectionModel_EAST detector(options.model_path);
        detector.setConfidenceThreshold(options.confidence_threshold)
            .setNMSThreshold(options.nms_threshold);
        detector.setInputParams(1.0, options.input_size, options.mean, options.swap_red_blue);
        return detector;
    } catch (const cv::Exception &error) {
        throw ModelError("OpenCV could not load the EAST model '" + options.model_path +
                         "': " + error.msg);
    }
}

// The oriented box, grown by the padding and turned upright, as its own small image.
cv::Mat upright_crop(const cv::Mat &gray, const cv::RotatedRect &box, int padding)
{
    const cv::Size2f size(box.size.width + 2.0f * static_cast<float>(padding),
                          box.size.height + 2.0f * static_cast<float>(padding));
    cv::Point2f corners[4];
    cv::RotatedRect(box.center, size, box.angle).points(corners);
    // points() lists bottom-left, top-left, top-right, bottom-right of the unrotated rectangle.
    const cv::Point2f upright[4] = {
        {0.0f, size.height}, {0.0f, 0.0f}, {size.width, 0.0f}, {size.width, size.height}};
    cv::Mat crop;
    cv::warpPerspective(
        gray, crop, cv::getPerspectiveTransform(corners, upright),
        cv::Size(static_cast<int>(std::ceil(size.width)), static_cast<int>(std::ceil(size.height))),
        cv::INTER_LINEAR, cv::BORDER_REPLICATE);
    return crop;
}

// Non-maximum suppression compares boxes by intersection over union, so a small box lying inside a
// large one survives it (a word inside its line, a fragment inside its word). Such boxes add only
// work and duplicated text: drop a box when most of it lies inside a larger one.
std::vector<cv::RotatedRect> without_contained(const std::vector<cv::RotatedRect> &boxes)
{
    constexpr double contained_fraction = 0.8;
    std::vector<cv::RotatedRect> kept;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        const cv::Rect inner = boxes[i].boundingRect();
        bool contained = false;
        for (std::size_t j = 0; j < boxes.size() && !contained; ++j) {
            const cv::Rect outer = boxes[j].boundingRect();
            contained = j != i && outer.area() > inner.area() &&
                        (inner & outer).area() >= contained_fraction * inner.area();
        }
        if (!contained)
            kept.push_back(boxes[i]);
    }
    return kept;
}

} // namespace

struct EastPipeline::Impl {
    explicit Impl(const EastOptions &chosen)
        : options(chosen), detector(load_detector(chosen)), engine(chosen.tesseract)
    {
    }
    EastOptions options;
    cv::dnn::TextDetectionModel_EAST detector;
    detail::TesseractEngine engine;
};

EastPipeline::EastPipeline(const EastOptions &options)
{
    detail::check(options);
    impl_ = std::make_unique<Impl>(options);
}

EastPipeline::~EastPipeline() = default;

std::vector<TextBox> EastPipeline::recognise_frame(const cv::Mat &image)
{
    const cv::Mat gray = detail::to_grayscale(image);
    std::vector<cv::RotatedRect> boxes;
    std::vector<float> scores;
    impl_->detector.detectTextRectangles(detail::to_bgr(image), boxes, scores);

    const cv::Rect frame(0, 0, gray.cols, gray.rows);
    std::vector<TextBox> words;
    for (const auto &box : without_contained(boxes)) {
        const cv::Rect bounds = box.boundingRect() & frame;
        if (bounds.empty())
            continue;
        const cv::Mat crop = upright_crop(gray, box, impl_->options.padding_px);
        if (crop.empty())
            continue;
        impl_->engine.set_image(crop);
        if (auto word = impl_->engine.read_as_one(bounds)) {
            word->rotated_box = box;
            words.push_back(std::move(*word));
        }
    }
    return words;
}

} // namespace ubii::ocr

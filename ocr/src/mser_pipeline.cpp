#include "ubii/ocr/mser_pipeline.hpp"

#include <opencv2/features2d.hpp>

#include "character_regions.hpp"
#include "grayscale.hpp"
#include "tesseract_engine.hpp"
#include "ubii/ocr/error.hpp"
#include "word_grouping.hpp"

namespace ubii::ocr
{

struct MserPipeline::Impl {
    explicit Impl(const MserOptions &chosen)
        : options(chosen), engine(chosen.tesseract),
          mser(cv::MSER::create(chosen.delta, chosen.min_area, chosen.max_area,
                                chosen.max_variation, chosen.min_diversity))
    {
    }
    MserOptions options;
    detail::TesseractEngine engine;
    cv::Ptr<cv::MSER> mser;
};

MserPipeline::MserPipeline(const MserOptions &options)
{
    if (options.delta <= 0 || options.min_area <= 0 || options.max_area < options.min_area ||
        options.max_variation <= 0.0 || options.padding_px < 0 || options.word_gap < 0.0f)
        throw InvalidArgument(
            "MSER options out of range: delta, min_area, max_variation must be > 0, "
            "max_area >= min_area, padding and word_gap >= 0");
    impl_ = std::make_unique<Impl>(options);
}

MserPipeline::~MserPipeline() = default;

std::vector<TextBox> MserPipeline::recognise(const cv::Mat &image)
{
    const cv::Mat gray = detail::to_grayscale(image);
    std::vector<std::vector<cv::Point>> regions;
    std::vector<cv::Rect> region_boxes;
    const bool colour = impl_->options.use_colour && image.channels() != 1;
    impl_->mser->detectRegions(colour ? detail::to_bgr(image) : gray, regions, region_boxes);

    // Each character is read from its own region's pixels, drawn black on white with the padding
    // around it. Cut from the frame instead, the padding takes in parts of the neighbouring
    // letters, which single-character mode then reads as extra characters. This also turns light
    // text on a dark ground into dark on light.
    const int padding = impl_->options.padding_px;
    std::vector<TextBox> characters;
    for (const auto &candidate : detail::character_candidates(region_boxes)) {
        const cv::Point origin = candidate.box.tl() - cv::Point(padding, padding);
        cv::Mat patch(candidate.box.height + 2 * padding, candidate.box.width + 2 * padding,
                      CV_8UC1, cv::Scalar(255));
        for (const std::size_t region : candidate.regions)
            for (const auto &pixel : regions[region])
                patch.at<std::uint8_t>(pixel - origin) = 0;
        impl_->engine.set_image(patch);
        auto character = impl_->options.tesseract.segmentation == Segmentation::single_char
                             ? impl_->engine.read_best_symbol(candidate.box)
                             : impl_->engine.read_as_one(candidate.box);
        if (character)
            characters.push_back(std::move(*character));
    }
    return detail::group_into_words(characters, impl_->options.word_gap);
}

} // namespace ubii::ocr

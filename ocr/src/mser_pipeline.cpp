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

    // One SetImage per frame; each character is then a rectangle of it, which spares a copy per
    // character.
    impl_->engine.set_image(gray);
    const cv::Rect frame(0, 0, gray.cols, gray.rows);
    const int padding = impl_->options.padding_px;
    std::vector<TextBox> characters;
    for (const auto &box : detail::character_candidates(region_boxes)) {
        const cv::Rect padded =
            (box + cv::Point(-padding, -padding) + cv::Size(2 * padding, 2 * padding)) & frame;
        impl_->engine.set_rectangle(padded);
        if (auto character = impl_->engine.read_as_one(box))
            characters.push_back(std::move(*character));
    }
    return detail::group_into_words(characters, impl_->options.word_gap);
}

} // namespace ubii::ocr

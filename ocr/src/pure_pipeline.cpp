#include "ubii/ocr/pure_pipeline.hpp"

#include "grayscale.hpp"
#include "tesseract_engine.hpp"

namespace ubii::ocr
{

struct PurePipeline::Impl {
    explicit Impl(const PureOptions &options) : engine(options.tesseract)
    {
    }
    detail::TesseractEngine engine;
};

PurePipeline::PurePipeline(const PureOptions &options) : impl_(std::make_unique<Impl>(options))
{
}
PurePipeline::~PurePipeline() = default;

std::vector<TextBox> PurePipeline::recognise_frame(const cv::Mat &image)
{
    impl_->engine.set_image(detail::to_grayscale(image));
    return impl_->engine.read_words();
}

} // namespace ubii::ocr

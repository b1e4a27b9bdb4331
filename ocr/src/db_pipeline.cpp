#include "ubii/ocr/db_pipeline.hpp"

#include <cstdlib>

#include "db_detector.hpp"
#include "grayscale.hpp"
#include "line_crop.hpp"
#include "option_checks.hpp"
#include "tesseract_engine.hpp"

namespace ubii::ocr
{

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
        const detail::UprightLine line = detail::upright_line(gray, quad, impl_->options.padding);
        if (line.pixels.empty())
            continue;
        impl_->engine.set_image(line.pixels);
        for (auto &word : impl_->engine.read_words())
            if (detail::place_in_frame(word, line.to_frame, frame))
                words.push_back(std::move(word));
    }
    return words;
}

} // namespace ubii::ocr

#include "option_checks.hpp"

#include <sstream>
#include <string>

#include "ubii/ocr/error.hpp"

// Every pipeline's option ranges in one place: the constructors check them before loading
// anything, and check_options (pipeline_factory.hpp) lets a caller refuse bad options without
// loading Tesseract or a model (a processing module's factory, a command line).
namespace ubii::ocr::detail
{
namespace
{

constexpr int network_stride = 32;

bool unit_interval(float value)
{
    return value >= 0.0f && value <= 1.0f;
}

} // namespace

void check(const TesseractOptions &options)
{
    if (options.language.empty())
        throw InvalidArgument("Tesseract language must not be empty (e.g. eng, deu, eng+deu)");
    if (!(options.min_confidence >= 0.0f && options.min_confidence <= 100.0f)) {
        std::ostringstream value;
        value << options.min_confidence;
        throw InvalidArgument("minimum confidence must lie in 0..100 (Tesseract's scale), not " +
                              value.str());
    }
    if (options.source_resolution_dpi < 1 || options.source_resolution_dpi > 2400)
        throw InvalidArgument("source resolution must lie in 1..2400 dpi, not " +
                              std::to_string(options.source_resolution_dpi));
}

void check(const PureOptions &options)
{
    check(options.tesseract);
}

void check(const MserOptions &options)
{
    check(options.tesseract);
    if (options.delta <= 0 || options.min_area <= 0 || options.max_area < options.min_area ||
        options.max_variation <= 0.0 || options.padding_px < 0 || options.word_gap < 0.0f ||
        options.line_gap < 0.0f)
        throw InvalidArgument(
            "MSER options out of range: delta, min_area, max_variation must be > 0, "
            "max_area >= min_area, padding, word_gap and line_gap >= 0");
}

void check(const EastOptions &options)
{
    check(options.tesseract);
    const auto multiple = [](int side) { return side > 0 && side % network_stride == 0; };
    if (!multiple(options.input_size.width) || !multiple(options.input_size.height))
        throw InvalidArgument("EAST input size must be positive multiples of 32, not " +
                              std::to_string(options.input_size.width) + "x" +
                              std::to_string(options.input_size.height));
    if (!unit_interval(options.confidence_threshold) || !unit_interval(options.nms_threshold) ||
        options.padding_px < 0)
        throw InvalidArgument("EAST thresholds must lie in 0..1 and the padding must be >= 0");
}

void check(const DbOptions &options)
{
    check(options.tesseract);
    if (options.max_side < network_stride || options.max_side > 4096)
        throw InvalidArgument("DB input size (the longer side) must lie in 32..4096 pixels, not " +
                              std::to_string(options.max_side));
    if (!unit_interval(options.binary_threshold) || !unit_interval(options.box_threshold))
        throw InvalidArgument("DB thresholds must lie in 0..1");
    if (!(options.unclip_ratio > 0.0f && options.unclip_ratio <= 10.0f))
        throw InvalidArgument("DB unclip ratio must lie in (0, 10]");
    if (options.max_candidates < 1)
        throw InvalidArgument("DB max_candidates must be at least 1");
    if (!(options.padding >= 0.0f && options.padding <= 2.0f))
        throw InvalidArgument("DB padding must lie in 0..2 line heights");
}

} // namespace ubii::ocr::detail

#include "module_options.hpp"

#include <cstdlib>
#include <map>

#include "ubii/error.hpp"
#include "ubii/ocr/error.hpp"

namespace ubii::ocr::modules
{
namespace
{

const std::map<std::string, Segmentation, std::less<>> &segmentations()
{
    static const std::map<std::string, Segmentation, std::less<>> names = {
        {"auto", Segmentation::automatic},   {"block", Segmentation::single_block},
        {"line", Segmentation::single_line}, {"word", Segmentation::single_word},
        {"char", Segmentation::single_char}, {"sparse", Segmentation::sparse_text}};
    return names;
}

Segmentation parse_segmentation(const std::string &text)
{
    const auto found = segmentations().find(text);
    if (found == segmentations().end())
        throw ubii::ocr::InvalidArgument(
            "psm must be auto, block, line, word, char or sparse, not '" + text + "'");
    return found->second;
}

// "WxH", each side a number.
cv::Size parse_size(const std::string &text)
{
    const auto x = text.find('x');
    char *end = nullptr;
    const long width = x == std::string::npos ? 0 : std::strtol(text.c_str(), &end, 10);
    const bool width_ok = x != std::string::npos && end == text.c_str() + x;
    const long height = width_ok ? std::strtol(text.c_str() + x + 1, &end, 10) : 0;
    if (!width_ok || *end != '\0' || width <= 0 || height <= 0 || width > 8192 || height > 8192)
        throw ubii::ocr::InvalidArgument("input_size must be WIDTHxHEIGHT, e.g. 320x320, not '" +
                                         text + "'");
    return {static_cast<int>(width), static_cast<int>(height)};
}

void read_tesseract(TesseractOptions &tesseract, const ModuleArguments &arguments)
{
    tesseract.language = arguments.get("lang", tesseract.language);
    tesseract.data_path = arguments.get("tessdata", tesseract.data_path);
    if (arguments.contains("psm"))
        tesseract.segmentation = parse_segmentation(arguments.get("psm", std::string()));
    tesseract.min_confidence = static_cast<float>(
        arguments.get("min_confidence", static_cast<double>(tesseract.min_confidence)));
    tesseract.source_resolution_dpi = arguments.get("dpi", tesseract.source_resolution_dpi);
}

} // namespace

PipelineOptions options_from(PipelineKind kind, const ModuleArguments &arguments)
{
    PipelineOptions options = default_options(kind);
    // Scenes, not pages: without a page layout to find, sparse text finds far more (ocr/README.md).
    if (kind == PipelineKind::pure)
        tesseract_options(options).segmentation = Segmentation::sparse_text;
    read_tesseract(tesseract_options(options), arguments);
    if (auto *east = std::get_if<EastOptions>(&options)) {
        east->model_path = arguments.get("model", east->model_path);
        if (arguments.contains("input_size"))
            east->input_size = parse_size(arguments.get("input_size", std::string()));
        east->confidence_threshold = static_cast<float>(
            arguments.get("confidence", static_cast<double>(east->confidence_threshold)));
    }
    if (auto *db = std::get_if<DbOptions>(&options)) {
        db->model_path = arguments.get("model", db->model_path);
        db->max_side = arguments.get("input_size", db->max_side);
    }
    check_options(options);
    return options;
}

std::string arguments_help(PipelineKind kind)
{
    std::string help =
        "Arguments: lang (eng), tessdata (Tesseract's path), psm (auto, block, line, "
        "word, char, sparse), min_confidence (0..100, 70), dpi (300)";
    switch (kind) {
    case PipelineKind::east:
        help += ", model (frozen_east_text_detection.pb: required, not shipped), input_size "
                "(WxH, multiples of 32; 320x320), confidence (0..1, 0.5)";
        break;
    case PipelineKind::db:
        help += ", model (default: scripts/ocr-models.sh's PP-OCRv4 detector in the cache), "
                "input_size (the longer side in pixels, 640)";
        break;
    case PipelineKind::pure:
    case PipelineKind::mser:
        break;
    }
    return help + ".";
}

} // namespace ubii::ocr::modules

#ifndef UBII_OCR_PIPELINE_FACTORY_HPP
#define UBII_OCR_PIPELINE_FACTORY_HPP

// Choosing a pipeline at run time (a command-line argument, a configuration value):
//
//     auto options = ubii::ocr::default_options(ubii::ocr::parse_pipeline_kind(argv[1]));
//     ubii::ocr::tesseract_options(options).segmentation = ubii::ocr::Segmentation::sparse_text;
//     if (auto *east = std::get_if<ubii::ocr::EastOptions>(&options))
//         east->model_path = argv[2];
//     auto pipeline = ubii::ocr::make_pipeline(options);

#include <memory>
#include <variant>

#include "ubii/ocr/db_pipeline.hpp"
#include "ubii/ocr/east_pipeline.hpp"
#include "ubii/ocr/mser_pipeline.hpp"
#include "ubii/ocr/pipeline.hpp"
#include "ubii/ocr/pure_pipeline.hpp"

namespace ubii::ocr
{

using PipelineOptions = std::variant<PureOptions, MserOptions, EastOptions, DbOptions>;

PipelineOptions default_options(PipelineKind kind);
PipelineKind kind_of(const PipelineOptions &options);
// The Tesseract settings every pipeline has.
TesseractOptions &tesseract_options(PipelineOptions &options);

// InvalidArgument for an option out of range, as the pipeline's constructor would throw it, but
// without loading Tesseract or a model (a few microseconds).
void check_options(const PipelineOptions &options);
// Throws what the chosen pipeline's constructor throws.
std::unique_ptr<Pipeline> make_pipeline(const PipelineOptions &options);

} // namespace ubii::ocr

#endif

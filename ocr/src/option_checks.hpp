#ifndef UBII_OCR_SRC_OPTION_CHECKS_HPP
#define UBII_OCR_SRC_OPTION_CHECKS_HPP

#include "ubii/ocr/db_pipeline.hpp"
#include "ubii/ocr/east_pipeline.hpp"
#include "ubii/ocr/mser_pipeline.hpp"
#include "ubii/ocr/pure_pipeline.hpp"
#include "ubii/ocr/tesseract_options.hpp"

namespace ubii::ocr::detail
{

// InvalidArgument, naming the option, for a value out of range; nothing is loaded.
void check(const TesseractOptions &options);
void check(const PureOptions &options);
void check(const MserOptions &options);
void check(const EastOptions &options);
void check(const DbOptions &options);

} // namespace ubii::ocr::detail

#endif

#ifndef UBII_OCR_MODULES_MODULE_OPTIONS_HPP
#define UBII_OCR_MODULES_MODULE_OPTIONS_HPP

// The OCR modules' arguments (`ubii-node run --module-arg TesseractOCR_PURE:lang=deu`), read
// into a pipeline's options and checked there, so that a value out of range refuses the module
// when it is made, not at its first frame.

#include <string>

#include "ubii/module_arguments.hpp"
#include "ubii/ocr/pipeline_factory.hpp"

namespace ubii::ocr::modules
{

// Every argument of `kind` read from `arguments`: ubii::InvalidArgument for a value that does not
// parse, ubii::ocr::InvalidArgument for one out of range.
PipelineOptions options_from(PipelineKind kind, const ModuleArguments &arguments);

// The arguments `kind` takes, one line each, for the module's description.
std::string arguments_help(PipelineKind kind);

} // namespace ubii::ocr::modules

#endif

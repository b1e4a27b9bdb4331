// The OCR plugin: what `ubii-node run` finds in <libdir>/ubii/modules and offers to masters.
#include "ocr_module.hpp"
#include "ubii/plugin.hpp"

UBII_PLUGIN("ubii-ocr", ubii::module_factory<ubii::ocr::modules::TesseractOcrPure>(),
            ubii::module_factory<ubii::ocr::modules::TesseractOcrMser>(),
            ubii::module_factory<ubii::ocr::modules::TesseractOcrEast>(),
            ubii::module_factory<ubii::ocr::modules::TextDetectionDb>())

#ifndef UBII_OCR_OCR_HPP
#define UBII_OCR_OCR_HPP

// Text recognition on Tesseract and OpenCV for Ubi-Interact nodes (ocr/README.md).

#include "ubii/ocr/db_pipeline.hpp"
#include "ubii/ocr/east_pipeline.hpp"
#include "ubii/ocr/error.hpp"
#include "ubii/ocr/image_records.hpp"
#include "ubii/ocr/mser_pipeline.hpp"
#include "ubii/ocr/object_records.hpp"
#include "ubii/ocr/omp.hpp"
#include "ubii/ocr/pipeline.hpp"
#include "ubii/ocr/pipeline_factory.hpp"
#include "ubii/ocr/pure_pipeline.hpp"
#include "ubii/ocr/tesseract_messages.hpp"
#include "ubii/ocr/tesseract_options.hpp"
#include "ubii/ocr/text_box.hpp"

#endif

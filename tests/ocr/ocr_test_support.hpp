#ifndef UBII_TESTS_OCR_TEST_SUPPORT_HPP
#define UBII_TESTS_OCR_TEST_SUPPORT_HPP

// Scenes and pipelines shared by the OCR tests of one executable: generating a scene and loading
// Tesseract's model take long enough that each is done once.

#include <memory>

#include "scenes.hpp"
#include "ubii/ocr/ocr.hpp"

namespace ubii::ocr::test
{

const testdata::Scene &scene(const std::string &name); // "baseline", "sign" or "webcam"

// The settings the accuracy figures are stated for: PURE with automatic segmentation on the
// baseline and sparse text on the two scenes, MSER with its defaults, EAST with the generated test
// network at the scene's input size (testdata::east_test_input_size).
PipelineOptions options_for(PipelineKind kind, const testdata::Scene &scene);

} // namespace ubii::ocr::test

#endif

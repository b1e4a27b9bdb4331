#ifndef UBII_OCR_PIPELINE_HPP
#define UBII_OCR_PIPELINE_HPP

// The interface every pipeline implements. To choose one at run time see pipeline_factory.hpp.
//
// Each pipeline owns one Tesseract instance, created in its constructor (loading the model costs
// about 100 ms) and reused for every frame. A pipeline works on one frame at a time: use one per
// thread.

#include <string_view>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "ubii/ocr/text_box.hpp"

namespace ubii::ocr
{

enum class PipelineKind { pure, mser, east, db };

// "pure", "mser", "east", "db" (any case); anything else throws InvalidArgument.
PipelineKind parse_pipeline_kind(std::string_view name);
std::string_view to_string(PipelineKind kind);

class Pipeline
{
  public:
    virtual ~Pipeline() = default;
    Pipeline(const Pipeline &) = delete;
    Pipeline &operator=(const Pipeline &) = delete;

    // `image`: 8-bit grayscale, BGR or BGRA (OpenCV's channel order) and not empty, otherwise
    // InvalidImage. Blocks until the frame is recognised. Boxes are in `image`'s pixels. Every
    // failure is an ocr::Error (what OpenCV throws inside comes out as one, with its message).
    std::vector<TextBox> recognise(const cv::Mat &image);
    virtual PipelineKind kind() const = 0;

  protected:
    Pipeline() = default;
    virtual std::vector<TextBox> recognise_frame(const cv::Mat &image) = 0;
};

} // namespace ubii::ocr

#endif

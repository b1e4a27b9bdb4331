#include "ubii/ocr/pipeline.hpp"

#include <string>

#include <opencv2/core.hpp>

#include "ubii/ocr/error.hpp"

namespace ubii::ocr
{
namespace
{

// No glyph fits in fewer pixels; OpenCV's MSER refuses such images outright.
constexpr int min_text_side = 3;

} // namespace

std::vector<TextBox> Pipeline::recognise(const cv::Mat &image)
{
    if (!image.empty() && (image.cols < min_text_side || image.rows < min_text_side) &&
        image.depth() == CV_8U)
        return {};
    try {
        return recognise_frame(image);
    } catch (const Error &) {
        throw;
    } catch (const cv::Exception &error) {
        throw Error("OpenCV failed on a " + std::to_string(image.cols) + "x" +
                    std::to_string(image.rows) + " frame: " + error.msg);
    }
}

} // namespace ubii::ocr

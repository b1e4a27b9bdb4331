#include "grayscale.hpp"

#include <string>

#include <opencv2/imgproc.hpp>

#include "ubii/ocr/error.hpp"

namespace ubii::ocr::detail
{
namespace
{

void check_input(const cv::Mat &image)
{
    if (image.empty())
        throw InvalidImage("the image is empty");
    if (image.depth() != CV_8U ||
        (image.channels() != 1 && image.channels() != 3 && image.channels() != 4))
        throw InvalidImage("the image must be 8-bit grayscale, BGR or BGRA, not OpenCV type " +
                           std::to_string(image.type()));
}

} // namespace

cv::Mat to_grayscale(const cv::Mat &image)
{
    check_input(image);
    if (image.channels() == 1)
        return image;
    cv::Mat gray;
    cv::cvtColor(image, gray, image.channels() == 3 ? cv::COLOR_BGR2GRAY : cv::COLOR_BGRA2GRAY);
    return gray;
}

cv::Mat to_bgr(const cv::Mat &image)
{
    check_input(image);
    if (image.channels() == 3)
        return image;
    cv::Mat bgr;
    cv::cvtColor(image, bgr, image.channels() == 1 ? cv::COLOR_GRAY2BGR : cv::COLOR_BGRA2BGR);
    return bgr;
}

} // namespace ubii::ocr::detail

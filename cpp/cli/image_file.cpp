#include "image_file.hpp"

#include <filesystem>
#include <system_error>

#include "cli_error.hpp"

#ifdef UBII_CLI_WITH_OPENCV
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#endif

namespace ubii::cli
{

#ifdef UBII_CLI_WITH_OPENCV
ubii::Image2D read_image_file(const std::string &path)
{
    // Checked first: OpenCV would print a warning of its own before saying nothing useful.
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error))
        throw CliError(exit_usage, path + ": no such file");
    cv::Mat image = cv::imread(path, cv::IMREAD_UNCHANGED);
    if (image.empty())
        throw CliError(exit_usage, path + " is not an image file OpenCV can read");
    if (image.depth() != CV_8U)
        image.convertTo(image, CV_8U, image.depth() == CV_16U ? 1.0 / 257 : 255.0);
    ubii::Image2D message;
    switch (image.channels()) {
    case 1:
        message.set_data_format(ubii::Image2D::GRAY8);
        break;
    case 3:
        cv::cvtColor(image, image, cv::COLOR_BGR2RGB);
        message.set_data_format(ubii::Image2D::RGB8);
        break;
    case 4:
        cv::cvtColor(image, image, cv::COLOR_BGRA2RGBA);
        message.set_data_format(ubii::Image2D::RGBA8);
        break;
    default:
        throw CliError(exit_usage, path + " has " + std::to_string(image.channels()) +
                                       " channels; an Image2D has 1, 3 or 4");
    }
    if (!image.isContinuous())
        image = image.clone();
    message.set_width(image.cols);
    message.set_height(image.rows);
    message.set_data(image.data, image.total() * image.elemSize());
    return message;
}
#else
ubii::Image2D read_image_file(const std::string &path)
{
    throw CliError(exit_usage, "cannot read " + path + ": this ubii-node was built without OpenCV");
}
#endif

} // namespace ubii::cli

#include "ubii/ocr/image_records.hpp"

#include <algorithm>
#include <cstring>
#include <string>

#include <opencv2/imgproc.hpp>

#include "ubii/ocr/error.hpp"

namespace ubii::ocr
{
namespace
{

// The format as the integer the C side stored: the view is filled by C code from the wire, where
// any value may arrive, and C++ may not load an out-of-range value through the enum type itself.
int format_value(const ubii_image_view &image)
{
    int value = 0;
    static_assert(sizeof image.format == sizeof value, "C enums are ints");
    std::memcpy(&value, &image.format, sizeof value);
    return value;
}

int channels_of(const ubii_image_view &image)
{
    switch (format_value(image)) {
    case ubii_dataStructure_Image2D_DataFormat_GRAY8:
        return 1;
    case ubii_dataStructure_Image2D_DataFormat_RGB8:
        return 3;
    case ubii_dataStructure_Image2D_DataFormat_RGBA8:
        return 4;
    default:
        throw InvalidImage("unknown Image2D data format " + std::to_string(format_value(image)));
    }
}

} // namespace

cv::Mat image_to_mat(const ubii_image_view &image)
{
    const int channels = channels_of(image);
    if (image.width <= 0 || image.height <= 0)
        throw InvalidImage("Image2D of " + std::to_string(image.width) + "x" +
                           std::to_string(image.height) + " pixels is empty");
    // In 64 bits the product of two positive int32 values and 4 cannot overflow.
    const auto expected = static_cast<std::uint64_t>(image.width) *
                          static_cast<std::uint64_t>(image.height) *
                          static_cast<std::uint64_t>(channels);
    if (image.data == nullptr || image.size != expected)
        throw InvalidImage("Image2D of " + std::to_string(image.width) + "x" +
                           std::to_string(image.height) + "x" + std::to_string(channels) +
                           " needs " + std::to_string(expected) + " bytes, it has " +
                           std::to_string(image.data == nullptr ? 0 : image.size));

    // The record's pixels are lent for the callback only: wrap them, then convert or clone.
    const cv::Mat lent(image.height, image.width, CV_8UC(channels),
                       const_cast<std::uint8_t *>(image.data));
    cv::Mat owned;
    if (channels == 1)
        owned = lent.clone();
    else
        cv::cvtColor(lent, owned, channels == 3 ? cv::COLOR_RGB2BGR : cv::COLOR_RGBA2BGRA);
    return owned;
}

ubii_image_view Image2DData::view() const
{
    return ubii_image_view{width, height, format, data.data(), data.size()};
}

Image2DData mat_to_image(const cv::Mat &image)
{
    if (image.empty())
        throw InvalidImage("the image is empty");
    if (image.depth() != CV_8U || image.channels() == 2 || image.channels() > 4)
        throw InvalidImage(
            "only 8-bit grayscale, BGR and BGRA images map to Image2D, not OpenCV type " +
            std::to_string(image.type()));
    cv::Mat ordered;
    Image2DData result;
    switch (image.channels()) {
    case 1:
        ordered = image;
        result.format = ubii_dataStructure_Image2D_DataFormat_GRAY8;
        break;
    case 3:
        cv::cvtColor(image, ordered, cv::COLOR_BGR2RGB);
        result.format = ubii_dataStructure_Image2D_DataFormat_RGB8;
        break;
    default:
        cv::cvtColor(image, ordered, cv::COLOR_BGRA2RGBA);
        result.format = ubii_dataStructure_Image2D_DataFormat_RGBA8;
        break;
    }
    result.width = image.cols;
    result.height = image.rows;
    const std::size_t row_bytes = static_cast<std::size_t>(image.cols) * ordered.elemSize();
    result.data.resize(row_bytes * static_cast<std::size_t>(image.rows));
    for (int row = 0; row < ordered.rows; ++row)
        std::copy_n(ordered.ptr<std::uint8_t>(row), row_bytes,
                    result.data.data() + row_bytes * static_cast<std::size_t>(row));
    return result;
}

} // namespace ubii::ocr

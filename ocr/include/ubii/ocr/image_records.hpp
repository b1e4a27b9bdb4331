#ifndef UBII_OCR_IMAGE_RECORDS_HPP
#define UBII_OCR_IMAGE_RECORDS_HPP

// Ubi-Interact Image2D records <-> OpenCV images.

#include <cstdint>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "ubii/image.h"

namespace ubii::ocr
{

// Copies an Image2D (from ubii_record_image) into a new Mat in OpenCV's channel order:
// GRAY8 -> CV_8UC1, RGB8 -> CV_8UC3 BGR, RGBA8 -> CV_8UC4 BGRA. The copy lets the Mat outlive
// the subscription callback that lent `image`. Throws InvalidImage for a width or height <= 0,
// an unknown data format, missing data or a byte count other than width x height x channels.
cv::Mat image_to_mat(const ubii_image_view &image);

// An Image2D's fields, owning its pixels (for ubii_publish_image).
struct Image2DData {
    std::int32_t width = 0;
    std::int32_t height = 0;
    ubii_dataStructure_Image2D_DataFormat format = ubii_dataStructure_Image2D_DataFormat_GRAY8;
    std::vector<std::uint8_t> data; // rows top to bottom, no padding

    // Borrows `data`: valid while this object is alive and unchanged.
    ubii_image_view view() const;
};

// The reverse of image_to_mat: CV_8UC1 -> GRAY8, CV_8UC3 (BGR) -> RGB8, CV_8UC4 (BGRA) -> RGBA8.
// Throws InvalidImage for an empty Mat or another pixel type.
Image2DData mat_to_image(const cv::Mat &image);

} // namespace ubii::ocr

#endif

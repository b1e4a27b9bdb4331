#ifndef UBII_OCR_MODULES_OBJECT_LIST_HPP
#define UBII_OCR_MODULES_OBJECT_LIST_HPP

// The modules' records in the C++ layer's types: an Image2D record's pixels as a cv::Mat, and the
// recognised words as an Object2DList (the convention of ocr/README.md, "Records").

#include <vector>

#include <opencv2/core/mat.hpp>

#include "ubii/messages.hpp"
#include "ubii/ocr/text_box.hpp"
#include "ubii/record.hpp"

namespace ubii::ocr::modules
{

// A copy in OpenCV's channel order; ubii::ocr::InvalidImage for a header that does not match its
// pixels or an unknown format.
cv::Mat image_to_mat(const ImageView &image);

Object2DList to_object2d_list(const std::vector<TextBox> &words);

} // namespace ubii::ocr::modules

#endif

#ifndef UBII_CLI_IMAGE_FILE_HPP
#define UBII_CLI_IMAGE_FILE_HPP

#include <string>

#include "ubii/ubii.hpp"

namespace ubii::cli
{

// An image file (anything OpenCV reads) as an Image2D: GRAY8, RGB8 or RGBA8 by its channels,
// 16-bit images scaled to 8 bits. CliError(exit_usage) for a file that is not an image, or in a
// build without OpenCV.
ubii::Image2D read_image_file(const std::string &path);

} // namespace ubii::cli

#endif

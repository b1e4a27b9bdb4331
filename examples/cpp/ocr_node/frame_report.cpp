#include "frame_report.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace ocr_node
{

std::string frame_line(std::uint64_t frame, int width, int height,
                       const std::vector<ubii::ocr::TextBox> &boxes, double milliseconds,
                       std::uint64_t dropped_so_far)
{
    std::ostringstream line;
    line << "frame " << frame << ' ' << width << 'x' << height << ": " << boxes.size()
         << (boxes.size() == 1 ? " box, " : " boxes, ") << std::fixed << std::setprecision(1)
         << milliseconds << " ms, " << dropped_so_far << " dropped";
    const char *separator = ": ";
    for (const auto &box : boxes) {
        line << separator << std::quoted(box.text) << ' ' << box.box.x << ',' << box.box.y << ' '
             << box.box.width << 'x' << box.box.height << ' ' << std::setprecision(0)
             << (std::isnan(box.confidence) ? 0.0f : box.confidence);
        separator = "; ";
    }
    return line.str();
}

std::string frame_error_line(std::uint64_t frame, const std::string &error)
{
    return "frame " + std::to_string(frame) + " error: " + error;
}

} // namespace ocr_node

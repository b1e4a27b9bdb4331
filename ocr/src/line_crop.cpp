#include "line_crop.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/imgproc.hpp>

namespace ubii::ocr::detail
{
namespace
{

// Tesseract's LSTM model reads lines best with an x-height of about 20 px; smaller lines are
// scaled up to this height (capitals plus padding) before reading.
constexpr float min_read_height = 48.0f;

float distance(cv::Point2f from, cv::Point2f to)
{
    return std::hypot(to.x - from.x, to.y - from.y);
}

} // namespace

LineQuad as_text_quad(const std::array<cv::Point2f, 4> &corners)
{
    const auto horizontalness = [](cv::Point2f from, cv::Point2f to) {
        return std::abs(to.x - from.x) - std::abs(to.y - from.y);
    };
    // Sides 0-1 and 2-3, or 1-2 and 3-0: the first index of the top side's pair.
    const int first =
        horizontalness(corners[0], corners[1]) >= horizontalness(corners[1], corners[2]) ? 0 : 1;
    const int a = first, b = (first + 1) % 4, c = (first + 2) % 4, d = (first + 3) % 4;
    // Sides a-b and c-d run along the text; the one higher in the frame is the top.
    const bool ab_on_top = corners[a].y + corners[b].y <= corners[c].y + corners[d].y;
    const int top_from = ab_on_top ? a : c, top_to = ab_on_top ? b : d;
    // Corners are cyclic: the bottom neighbour of each top corner is the one not on the top side.
    const int next_of_to = (top_to + 1) % 4, next_of_from = (top_from + 3) % 4;
    if (corners[top_from].x <= corners[top_to].x)
        return {corners[top_from], corners[top_to], corners[next_of_to], corners[next_of_from]};
    return {corners[top_to], corners[top_from], corners[next_of_from], corners[next_of_to]};
}

float turn_degrees(const LineQuad &quad)
{
    const cv::Point2f along = quad[1] - quad[0];
    return static_cast<float>(std::abs(std::atan2(along.y, along.x)) * 180.0 / CV_PI);
}

UprightLine upright_line(const cv::Mat &gray, const LineQuad &quad, float padding)
{
    const float width = std::max(distance(quad[0], quad[1]), distance(quad[3], quad[2]));
    const float height = std::max(distance(quad[0], quad[3]), distance(quad[1], quad[2]));
    const float margin = padding * height;
    const float scale = std::max(1.0f, min_read_height / (height + 2 * margin));
    const float left = margin * scale, top = margin * scale;
    const float right = left + width * scale, bottom = top + height * scale;
    const cv::Point2f corners[4] = {quad[0], quad[1], quad[2], quad[3]};
    const cv::Point2f target[4] = {{left, top}, {right, top}, {right, bottom}, {left, bottom}};
    const cv::Mat to_crop = cv::getPerspectiveTransform(corners, target);
    UprightLine line;
    cv::warpPerspective(gray, line.pixels, to_crop,
                        cv::Size(static_cast<int>(std::ceil(right + left)),
                                 static_cast<int>(std::ceil(bottom + top))),
                        cv::INTER_LINEAR, cv::BORDER_REPLICATE);
    line.to_frame = cv::Matx33d(cv::Mat(to_crop.inv()));
    return line;
}

bool place_in_frame(TextBox &word, const cv::Matx33d &to_frame, const cv::Rect &frame)
{
    const cv::Rect &box = word.box;
    const std::vector<cv::Point2f> in_crop = {
        cv::Point2f(static_cast<float>(box.x), static_cast<float>(box.y)),
        cv::Point2f(static_cast<float>(box.x + box.width), static_cast<float>(box.y)),
        cv::Point2f(static_cast<float>(box.x + box.width), static_cast<float>(box.y + box.height)),
        cv::Point2f(static_cast<float>(box.x), static_cast<float>(box.y + box.height))};
    std::vector<cv::Point2f> in_frame;
    cv::perspectiveTransform(in_crop, in_frame, cv::Mat(to_frame));
    word.box = cv::boundingRect(in_frame) & frame;
    word.rotated_box = cv::minAreaRect(in_frame);
    return !word.box.empty();
}

} // namespace ubii::ocr::detail

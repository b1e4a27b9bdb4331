#include "db_detector.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <string>

#include <opencv2/dnn.hpp>
#include <opencv2/imgproc.hpp>

#include "line_crop.hpp"
#include "ubii/ocr/error.hpp"

namespace ubii::ocr::detail
{
namespace
{

constexpr int db_stride = 32; // the network halves the frame five times
constexpr float min_line_side = 3.0f;
// PaddleOCR's normalisation: ImageNet's mean, and its standard deviations' mean as one scale.
const cv::Scalar imagenet_mean(0.485 * 255, 0.456 * 255, 0.406 * 255);
constexpr double imagenet_scale = 1.0 / (255.0 * 0.226);

constexpr const char *fetch_hint =
    " (scripts/ocr-models.sh fetches PaddleOCR's PP-OCRv4 detector and rewrites it for OpenCV "
    "4.6; or set DbOptions::model_path, the module argument `model` or UBII_OCR_DB_MODEL)";

constexpr std::size_t kept_networks = 4;

std::vector<uchar> read_model(const std::string &path)
{
    std::ifstream file(path, std::ios::binary);
    if (!file.good())
        throw ModelError("the DB text detector '" + path + "' is missing or unreadable" +
                         fetch_hint);
    return std::vector<uchar>(std::istreambuf_iterator<char>(file), {});
}

cv::dnn::Net load_network(const std::vector<uchar> &model, const std::string &path)
{
    try {
        cv::dnn::Net net = cv::dnn::readNetFromONNX(model);
        if (net.empty())
            throw ModelError("'" + path + "' holds no network" + std::string(fetch_hint));
        return net;
    } catch (const cv::Exception &error) {
        throw ModelError("OpenCV could not load the DB text detector '" + path + "': " + error.msg +
                         fetch_hint);
    }
}

int stride_multiple(double side)
{
    return std::max(db_stride, static_cast<int>(std::lround(side / db_stride)) * db_stride);
}

// Mean probability inside the contour: DB's box score, which sorts faint blobs from text.
double mean_inside(const cv::Mat &probability, const std::vector<cv::Point> &contour)
{
    const cv::Rect bounds = cv::boundingRect(contour) & cv::Rect({}, probability.size());
    if (bounds.empty())
        return 0.0;
    cv::Mat mask = cv::Mat::zeros(bounds.size(), CV_8UC1);
    std::vector<cv::Point> shifted;
    shifted.reserve(contour.size());
    for (const auto &point : contour)
        shifted.push_back(point - bounds.tl());
    cv::fillPoly(mask, std::vector<std::vector<cv::Point>>{shifted}, cv::Scalar(255));
    return cv::mean(probability(bounds), mask)[0];
}

// The network predicts each line shrunk by the same rule; growing the rectangle by
// area * ratio / perimeter on every side undoes it (DB's "unclip", exact for rectangles).
cv::RotatedRect unclipped(const cv::RotatedRect &kernel, float ratio)
{
    const float area = kernel.size.area();
    const float perimeter = 2.0f * (kernel.size.width + kernel.size.height);
    const float grow = area * ratio / perimeter;
    return {kernel.center, cv::Size2f(kernel.size.width + 2 * grow, kernel.size.height + 2 * grow),
            kernel.angle};
}

} // namespace

DbDetector::DbDetector(const DbOptions &options)
    : options_(options),
      path_(options.model_path.empty() ? default_db_model_path() : options.model_path),
      model_(read_model(path_)), unused_(load_network(model_, path_))
{
}

cv::dnn::Net &DbDetector::network_for(cv::Size input)
{
    for (auto entry = networks_.begin(); entry != networks_.end(); ++entry)
        if (entry->first == input) {
            networks_.splice(networks_.begin(), networks_, entry);
            return networks_.front().second;
        }
    cv::dnn::Net net = unused_.empty() ? load_network(model_, path_) : unused_;
    unused_ = cv::dnn::Net();
    networks_.emplace_front(input, std::move(net));
    if (networks_.size() > kept_networks)
        networks_.pop_back();
    return networks_.front().second;
}

cv::Size DbDetector::input_size(cv::Size frame) const
{
    const double scale =
        options_.max_side / static_cast<double>(std::max(frame.width, frame.height));
    return {stride_multiple(frame.width * scale), stride_multiple(frame.height * scale)};
}

std::vector<LineQuad> DbDetector::detect(const cv::Mat &bgr)
{
    const cv::Size input = input_size(bgr.size());
    cv::dnn::Net &net = network_for(input);
    net.setInput(cv::dnn::blobFromImage(bgr, imagenet_scale, input, imagenet_mean, true, false));
    cv::Mat output;
    try {
        output = net.forward();
    } catch (const cv::Exception &error) {
        throw ModelError("the DB text detector failed on a " + std::to_string(input.width) + "x" +
                         std::to_string(input.height) + " input: " + error.msg);
    }
    if (output.dims != 4 || output.size[0] != 1 || output.size[1] != 1 || output.type() != CV_32F)
        throw ModelError("the DB text detector's output is not one 1x1xHxW probability map");
    const cv::Mat probability(output.size[2], output.size[3], CV_32F, output.ptr<float>());

    cv::Mat text_pixels = probability >= options_.binary_threshold;
    std::vector<std::vector<cv::Point>> contours;
    cv::findContours(text_pixels, contours, cv::RETR_LIST, cv::CHAIN_APPROX_SIMPLE);

    const float to_frame_x = static_cast<float>(bgr.cols) / static_cast<float>(probability.cols);
    const float to_frame_y = static_cast<float>(bgr.rows) / static_cast<float>(probability.rows);
    std::vector<LineQuad> lines;
    const std::size_t candidates =
        std::min(contours.size(), static_cast<std::size_t>(options_.max_candidates));
    for (std::size_t i = 0; i < candidates; ++i) {
        const cv::RotatedRect kernel = cv::minAreaRect(contours[i]);
        if (std::min(kernel.size.width, kernel.size.height) < min_line_side)
            continue;
        if (mean_inside(probability, contours[i]) < options_.box_threshold)
            continue;
        const cv::RotatedRect line = unclipped(kernel, options_.unclip_ratio);
        if (std::min(line.size.width, line.size.height) < min_line_side + 2)
            continue;
        std::array<cv::Point2f, 4> corners;
        line.points(corners.data());
        for (auto &corner : corners)
            corner = {corner.x * to_frame_x, corner.y * to_frame_y};
        lines.push_back(as_text_quad(corners));
    }
    std::sort(lines.begin(), lines.end(), [](const LineQuad &left, const LineQuad &right) {
        return std::make_pair(left[0].y, left[0].x) < std::make_pair(right[0].y, right[0].x);
    });
    return lines;
}

} // namespace ubii::ocr::detail

#include "process_frame.hpp"

#include <chrono>
#include <exception>

#include "frame_report.hpp"
#include "ubii/dataStructure/object2d.pb.h"
#include "ubii/ocr/image_records.hpp"
#include "ubii/ocr/object_records.hpp"

namespace ocr_node
{
namespace
{

FrameResult recognise_and_publish(ubii::ocr::Pipeline &pipeline, ubii_node *node,
                                  const std::string &output_topic, const Frame &frame,
                                  std::uint64_t number, std::uint64_t dropped_so_far)
{
    if (frame.out_of_memory)
        return {false, frame_error_line(number, "out of memory copying the image")};
    if (frame.status != UBII_OK)
        return {false, frame_error_line(number, std::string("the record is not an Image2D (") +
                                                    ubii_strerror(frame.status) + ")")};

    const auto start = std::chrono::steady_clock::now();
    const cv::Mat image = ubii::ocr::image_to_mat(frame.view()); // throws InvalidImage
    std::vector<ubii::ocr::TextBox> boxes = pipeline.recognise(image);
    const std::chrono::duration<double, std::milli> took = std::chrono::steady_clock::now() - start;

    const ubii::ocr::Object2DListMessage message(std::move(boxes));
    const ubii_status status =
        ubii_publish_message(node, output_topic.c_str(), UBII_RECORD_OBJECT2D_LIST,
                             ubii_dataStructure_Object2DList_fields, message.get());
    std::string line =
        frame_line(number, image.cols, image.rows, message.boxes(), took.count(), dropped_so_far);
    if (status != UBII_OK)
        return {false, line + " (not published: " + ubii_strerror(status) + ")"};
    return {true, line};
}

// Builds the error result without letting an allocation failure escape.
FrameResult failed(std::uint64_t number, const char *what) noexcept
{
    try {
        return {false, frame_error_line(number, what)};
    } catch (...) {
        return {};
    }
}

} // namespace

FrameResult process_frame(ubii::ocr::Pipeline &pipeline, ubii_node *node,
                          const std::string &output_topic, const Frame &frame, std::uint64_t number,
                          std::uint64_t dropped_so_far) noexcept
{
    try {
        return recognise_and_publish(pipeline, node, output_topic, frame, number, dropped_so_far);
    } catch (const std::exception &error) {
        return failed(number, error.what());
    } catch (...) {
        return failed(number, "unknown exception");
    }
}

} // namespace ocr_node

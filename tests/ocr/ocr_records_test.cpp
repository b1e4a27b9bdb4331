// Ubi-Interact records in and out: Image2D -> cv::Mat (and back), text boxes -> Object2DList ->
// the same boxes; and a frame that arrives as an Image2D is read like the Mat it came from.
#include <cmath>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <pb_decode.h>

#include "ocr_test_support.hpp"
#include "ubii/lists.h"

namespace
{

using namespace ubii::ocr;

TEST(Image2DToMat, Rgb8BecomesBgrWithThePixelsInPlace)
{
    // 2x1 pixels: pure red, then (1, 2, 3).
    const std::vector<std::uint8_t> bytes = {255, 0, 0, 1, 2, 3};
    const cv::Mat mat = image_to_mat(
        {2, 1, ubii_dataStructure_Image2D_DataFormat_RGB8, bytes.data(), bytes.size()});
    ASSERT_EQ(mat.type(), CV_8UC3);
    ASSERT_EQ(mat.size(), cv::Size(2, 1));
    EXPECT_EQ(mat.at<cv::Vec3b>(0, 0), cv::Vec3b(0, 0, 255));
    EXPECT_EQ(mat.at<cv::Vec3b>(0, 1), cv::Vec3b(3, 2, 1));
}

TEST(Image2DToMat, Rgba8AndGray8KeepTheirChannels)
{
    const std::vector<std::uint8_t> rgba = {10, 20, 30, 40};
    const cv::Mat bgra =
        image_to_mat({1, 1, ubii_dataStructure_Image2D_DataFormat_RGBA8, rgba.data(), rgba.size()});
    ASSERT_EQ(bgra.type(), CV_8UC4);
    EXPECT_EQ(bgra.at<cv::Vec4b>(0, 0), cv::Vec4b(30, 20, 10, 40));

    const std::vector<std::uint8_t> gray = {1, 2, 3, 4, 5, 6};
    const cv::Mat mat =
        image_to_mat({3, 2, ubii_dataStructure_Image2D_DataFormat_GRAY8, gray.data(), gray.size()});
    ASSERT_EQ(mat.type(), CV_8UC1);
    EXPECT_EQ(mat.at<std::uint8_t>(1, 0), 4);
    EXPECT_EQ(mat.at<std::uint8_t>(1, 2), 6);
}

TEST(Image2DToMat, TheMatOwnsItsPixels)
{
    std::vector<std::uint8_t> gray = {7, 8};
    const cv::Mat mat =
        image_to_mat({2, 1, ubii_dataStructure_Image2D_DataFormat_GRAY8, gray.data(), gray.size()});
    gray.assign({0, 0});
    EXPECT_EQ(mat.at<std::uint8_t>(0, 0), 7);
}

TEST(MatToImage2D, RoundTripsEveryFormatOfAScene)
{
    const cv::Mat bgr = test::scene("webcam").image;
    cv::Mat gray, bgra;
    cv::cvtColor(bgr, gray, cv::COLOR_BGR2GRAY);
    cv::cvtColor(bgr, bgra, cv::COLOR_BGR2BGRA);
    for (const cv::Mat &original : {bgr, gray, bgra}) {
        const Image2DData image = mat_to_image(original);
        EXPECT_EQ(image.data.size(), original.total() * original.elemSize());
        const cv::Mat back = image_to_mat(image.view());
        ASSERT_EQ(back.type(), original.type());
        EXPECT_EQ(cv::norm(back, original, cv::NORM_INF), 0.0);
    }
    EXPECT_EQ(mat_to_image(bgr).format, ubii_dataStructure_Image2D_DataFormat_RGB8);
    // A view into a larger Mat (rows with padding) comes out packed.
    const Image2DData roi = mat_to_image(bgr(cv::Rect(10, 10, 7, 3)));
    EXPECT_EQ(roi.data.size(), 7u * 3u * 3u);
}

TEST(Image2DToPipeline, AFrameArrivingAsImage2DIsReadLikeTheOriginal)
{
    const auto &baseline = test::scene("baseline");
    const Image2DData image = mat_to_image(baseline.image);
    PurePipeline pipeline;
    const auto words = pipeline.recognise(image_to_mat(image.view()));
    EXPECT_EQ(testdata::score_words(words, baseline.words).recall(), 1.0);
}

std::vector<TextBox> sample_boxes()
{
    return {
        {"Grüße", 87.25f, cv::Rect(12, 34, 56, 78), std::nullopt},
        {"NO ENTRY", 95.5f, cv::Rect(300, 200, 340, 70),
         cv::RotatedRect(cv::Point2f(470.5f, 235.25f), cv::Size2f(338.5f, 66.0f), -3.75f)},
        {"42", 70.0f, cv::Rect(0, 0, 1, 1), std::nullopt},
    };
}

TEST(Object2DList, BoxesSurviveEncodingAndDecoding)
{
    const auto boxes = sample_boxes();
    const Object2DListMessage message(boxes);
    const auto bytes = message.encode();
    const auto decoded = decode_object2d_list(bytes.data(), bytes.size());
    ASSERT_EQ(decoded.size(), boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        EXPECT_EQ(decoded[i].text, boxes[i].text);
        EXPECT_EQ(decoded[i].confidence, boxes[i].confidence);
        EXPECT_EQ(decoded[i].box, boxes[i].box);
        ASSERT_EQ(decoded[i].rotated_box.has_value(), boxes[i].rotated_box.has_value());
        if (boxes[i].rotated_box) {
            EXPECT_EQ(decoded[i].rotated_box->center, boxes[i].rotated_box->center);
            EXPECT_EQ(decoded[i].rotated_box->size, boxes[i].rotated_box->size);
            EXPECT_EQ(decoded[i].rotated_box->angle, boxes[i].rotated_box->angle);
        }
    }
}

TEST(Object2DList, FieldsFollowTheDocumentedConvention)
{
    // Read back with the schema's own types, not with decode_object2d_list.
    const Object2DListMessage message(sample_boxes());
    const auto bytes = message.encode();
    ubii_list_iter elements{bytes.data(), bytes.size(), 0, nullptr, 0, false};
    const std::uint8_t *element = nullptr;
    std::size_t element_size = 0;
    ASSERT_TRUE(ubii_list_next_bytes(&elements, &element, &element_size));

    std::string id, json;
    const auto read_text = [](pb_istream_t *stream, const pb_field_t *, void **arg) {
        auto *text = static_cast<std::string *>(*arg);
        text->resize(stream->bytes_left);
        return pb_read(stream, reinterpret_cast<pb_byte_t *>(text->data()), text->size());
    };
    ubii_dataStructure_Object2D object = ubii_dataStructure_Object2D_init_zero;
    object.id.funcs.decode = read_text;
    object.id.arg = &id;
    object.user_data_json.funcs.decode = read_text;
    object.user_data_json.arg = &json;
    pb_istream_t stream = pb_istream_from_buffer(element, element_size);
    ASSERT_TRUE(pb_decode(&stream, ubii_dataStructure_Object2D_fields, &object));
    EXPECT_EQ(id, "Grüße");
    EXPECT_EQ(object.pose.position.x, 12.0); // top-left corner, pixels
    EXPECT_EQ(object.pose.position.y, 34.0);
    EXPECT_EQ(object.pose.which_orientation, 0);
    EXPECT_EQ(object.size.x, 56.0);
    EXPECT_EQ(object.size.y, 78.0);
    EXPECT_EQ(json, R"({"confidence":87.25})");

    int count = 1;
    while (ubii_list_next_bytes(&elements, &element, &element_size))
        ++count;
    EXPECT_EQ(count, 3);
    EXPECT_FALSE(elements.malformed);
}

TEST(Object2DList, ARecordHoldingTheListDecodes)
{
    const Object2DListMessage message(sample_boxes());
    const auto bytes = message.encode();
    ubii_record record{};
    record.topic = "/ocr/text";
    record.client_id = "";
    record.type = UBII_RECORD_OBJECT2D_LIST;
    record.value = bytes.data();
    record.value_size = bytes.size();
    EXPECT_EQ(decode_object2d_list(record).size(), 3u);
    record.type = UBII_RECORD_STRING;
    EXPECT_THROW(decode_object2d_list(record), InvalidArgument);
}

TEST(Object2DList, ConfidenceIsNaNWhenTheJsonHasNone)
{
    // An Object2D from another producer: id and pose only.
    const std::vector<TextBox> plain = {{"x", 1.0f, cv::Rect(1, 2, 3, 4), std::nullopt}};
    auto bytes = Object2DListMessage(plain).encode();
    // Cut the user_data_json field (the element's last bytes: tag 0x22, length, text).
    const std::size_t json_size = std::string(R"({"confidence":1})").size();
    bytes.resize(bytes.size() - json_size - 2);
    bytes[1] = static_cast<std::uint8_t>(bytes[1] - json_size - 2); // the element's length
    const auto decoded = decode_object2d_list(bytes.data(), bytes.size());
    ASSERT_EQ(decoded.size(), 1u);
    EXPECT_TRUE(std::isnan(decoded[0].confidence));
    EXPECT_EQ(decoded[0].box, cv::Rect(1, 2, 3, 4));
}

TEST(Object2DList, EmptyListEncodesToNothing)
{
    const Object2DListMessage message({});
    EXPECT_TRUE(message.encode().empty());
    EXPECT_TRUE(decode_object2d_list(nullptr, 0).empty());
}

} // namespace

// Uses an installed libubii's OCR pipelines the way a desktop application does: find_package(ubii
// COMPONENTS ocr), a PURE pipeline, an Image2D view in and recognised words out.
#include <cstdio>
#include <string>

#include <opencv2/imgproc.hpp>

#include "ubii/ocr/ocr.hpp"

int main(int argc, char **argv)
{
    ubii::ocr::ensure_single_omp_thread(argc, argv);
    cv::Mat page(200, 900, CV_8UC1, cv::Scalar(255));
    cv::putText(page, "HELLO WORLD", cv::Point(30, 130), cv::FONT_HERSHEY_SIMPLEX, 3.0,
                cv::Scalar(0), 8, cv::LINE_AA);
    const ubii::ocr::Image2DData image = ubii::ocr::mat_to_image(page);

    auto pipeline = ubii::ocr::make_pipeline(ubii::ocr::PureOptions{});
    std::string text;
    for (const auto &word : pipeline->recognise(ubii::ocr::image_to_mat(image.view())))
        text += (text.empty() ? "" : " ") + word.text;
    std::printf("consumer_ocr: read \"%s\"\n", text.c_str());
    if (text != "HELLO WORLD") {
        std::fprintf(stderr, "consumer_ocr: expected HELLO WORLD\n");
        return 1;
    }
    try {
        ubii_image_view broken = image.view();
        broken.size -= 1;
        ubii::ocr::image_to_mat(broken);
    } catch (const ubii::ocr::InvalidImage &error) {
        std::printf("consumer_ocr: a short Image2D is refused: %s\n", error.what());
        return 0;
    }
    std::fprintf(stderr, "consumer_ocr: a short Image2D was accepted\n");
    return 1;
}

#include "scenes.hpp"

#include <algorithm>
#include <cctype>
#include <sstream>

#include <opencv2/freetype.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace ubii::ocr::testing
{
namespace
{

constexpr double min_box_overlap = 0.5; // of the smaller box, for a word to count as found

cv::Ptr<cv::freetype::FreeType2> font()
{
    static const cv::Ptr<cv::freetype::FreeType2> loaded = [] {
        auto face = cv::freetype::createFreeType2();
        face->loadFontData(UBII_OCR_TEST_FONT, 0);
        return face;
    }();
    return loaded;
}

// Writes `lines` (words separated by single spaces) from `origin` downwards and returns each
// word's ink box, measured from what was actually drawn.
std::vector<GroundTruthWord> write_lines(cv::Mat &canvas, const std::vector<std::string> &lines,
                                         cv::Point origin, int height, const cv::Scalar &colour)
{
    const auto face = font();
    int baseline = 0;
    const int space = face->getTextSize(" ", height, -1, &baseline).width + height / 8;
    std::vector<GroundTruthWord> words;
    cv::Point position = origin;
    for (const auto &line : lines) {
        std::istringstream split(line);
        std::string word;
        while (split >> word) {
            // FreeType draws on 3-channel images only.
            cv::Mat ink = cv::Mat::zeros(canvas.size(), CV_8UC3), ink_gray;
            face->putText(ink, word, position, height, cv::Scalar::all(255), -1, cv::LINE_AA, false);
            face->putText(canvas, word, position, height, colour, -1, cv::LINE_AA, false);
            cv::cvtColor(ink, ink_gray, cv::COLOR_BGR2GRAY);
            words.push_back({word, cv::boundingRect(ink_gray)});
            position.x += face->getTextSize(word, height, -1, &baseline).width + space;
        }
        position.x = origin.x;
        position.y += height * 3 / 2;
    }
    return words;
}

void add_clutter(cv::Mat &canvas, cv::RNG &rng, int shapes)
{
    const auto random_colour = [&] {
        return cv::Scalar(rng.uniform(0, 256), rng.uniform(0, 256), rng.uniform(0, 256));
    };
    for (int i = 0; i < shapes; ++i) {
        const cv::Point a(rng.uniform(0, canvas.cols), rng.uniform(0, canvas.rows));
        const cv::Point b(rng.uniform(0, canvas.cols), rng.uniform(0, canvas.rows));
        switch (rng.uniform(0, 3)) {
        case 0:
            cv::rectangle(canvas, a, b, random_colour(), rng.uniform(-1, 6));
            break;
        case 1:
            cv::circle(canvas, a, rng.uniform(5, canvas.rows / 5), random_colour(),
                       rng.uniform(-1, 6), cv::LINE_AA);
            break;
        default:
            cv::line(canvas, a, b, random_colour(), rng.uniform(1, 8), cv::LINE_AA);
            break;
        }
    }
}

void add_noise(cv::Mat &canvas, cv::RNG &rng, double sigma)
{
    cv::Mat noise(canvas.size(), CV_16SC3);
    rng.fill(noise, cv::RNG::NORMAL, 0, sigma);
    cv::Mat widened;
    canvas.convertTo(widened, CV_16SC3);
    widened += noise;
    widened.convertTo(canvas, CV_8UC3); // saturating
}

std::string normalised(const std::string &word)
{
    std::string kept;
    for (const char c : word)
        if (std::isalnum(static_cast<unsigned char>(c)))
            kept += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return kept;
}

double overlap_of_smaller(const cv::Rect &a, const cv::Rect &b)
{
    const double smaller = std::min(a.area(), b.area());
    return smaller <= 0 ? 0.0 : (a & b).area() / smaller;
}

} // namespace

Scene baseline_scene()
{
    Scene scene{"baseline", cv::Mat(900, 1200, CV_8UC3, cv::Scalar::all(255)), {}};
    scene.words = write_lines(
        scene.image,
        {"Ubiquitous interaction connects many devices",
         "Text recognition runs on every camera frame", "The master forwards images to this node",
         "Seventeen orange boxes wait near platform 42", "Quick brown foxes jump over lazy dogs",
         "Numbers like 2024 and 314 appear here too"},
        cv::Point(60, 90), 40, cv::Scalar::all(25));
    return scene;
}

Scene sign_scene()
{
    cv::RNG rng(20240501);
    // The sign, flat: dark letters on a yellow panel with a dark rim.
    cv::Mat panel(360, 720, CV_8UC3, cv::Scalar(40, 200, 250));
    cv::rectangle(panel, cv::Rect(0, 0, panel.cols, panel.rows), cv::Scalar(30, 30, 30), 12);
    const auto panel_words = write_lines(panel, {"NO ENTRY", "Staff Only", "Exit 12"},
                                         cv::Point(70, 50), 72, cv::Scalar(30, 30, 30));

    Scene scene{"sign", cv::Mat(900, 1200, CV_8UC3), {}};
    cv::Mat gradient(scene.image.size(), CV_8UC3);
    for (int row = 0; row < gradient.rows; ++row)
        gradient.row(row).setTo(cv::Scalar(90 + row / 10, 110 + row / 12, 100));
    scene.image = gradient;
    add_clutter(scene.image, rng, 60);

    // Seen from below and to the left: a perspective warp of the panel into the scene.
    const cv::Point2f flat[4] = {{0, 0}, {720, 0}, {720, 360}, {0, 360}};
    const cv::Point2f seen[4] = {{250, 220}, {930, 260}, {910, 640}, {270, 610}};
    const cv::Mat warp = cv::getPerspectiveTransform(flat, seen);
    cv::Mat warped, mask;
    cv::warpPerspective(panel, warped, warp, scene.image.size(), cv::INTER_LINEAR);
    cv::warpPerspective(cv::Mat(panel.size(), CV_8UC1, cv::Scalar(255)), mask, warp,
                        scene.image.size(), cv::INTER_NEAREST);
    warped.copyTo(scene.image, mask);
    for (const auto &word : panel_words) {
        const cv::Rect &b = word.box;
        std::vector<cv::Point2f> corners = {
            cv::Point2f(float(b.x), float(b.y)), cv::Point2f(float(b.x + b.width), float(b.y)),
            cv::Point2f(float(b.x + b.width), float(b.y + b.height)),
            cv::Point2f(float(b.x), float(b.y + b.height))};
        cv::perspectiveTransform(corners, corners, warp);
        scene.words.push_back({word.text, cv::boundingRect(corners)});
    }
    cv::GaussianBlur(scene.image, scene.image, cv::Size(0, 0), 1.5);
    add_noise(scene.image, rng, 8.0);
    return scene;
}

Scene webcam_scene()
{
    cv::RNG rng(20240502);
    Scene scene{"webcam", cv::Mat(480, 640, CV_8UC3, cv::Scalar(120, 130, 125)), {}};
    // A sheet of paper pinned to a busy wall; the text on it is small and faint.
    const cv::Rect sheet(170, 150, 300, 150);
    add_clutter(scene.image, rng, 80);
    scene.image(sheet).setTo(cv::Scalar(170, 175, 175));
    scene.words =
        write_lines(scene.image, {"Meeting room 3", "open Monday to Friday", "back at noon"},
                    cv::Point(sheet.x + 18, sheet.y + 22), 20, cv::Scalar(95, 100, 100));
    cv::GaussianBlur(scene.image, scene.image, cv::Size(0, 0), 0.9);
    add_noise(scene.image, rng, 4.0);
    std::vector<std::uint8_t> jpeg;
    cv::imencode(".jpg", scene.image, jpeg, {cv::IMWRITE_JPEG_QUALITY, 30});
    scene.image = cv::imdecode(jpeg, cv::IMREAD_COLOR);
    return scene;
}

std::vector<Scene> all_scenes()
{
    return {baseline_scene(), sign_scene(), webcam_scene()};
}

WordScore score_words(const std::vector<TextBox> &recognised,
                      const std::vector<GroundTruthWord> &truth)
{
    WordScore score;
    score.expected = static_cast<int>(truth.size());
    std::vector<bool> found(truth.size(), false);
    for (const auto &box : recognised) {
        // A box may hold several words (EAST lines, MSER merges): each counts on its own.
        std::istringstream split(box.text);
        std::string word;
        while (split >> word) {
            const std::string key = normalised(word);
            if (key.empty())
                continue;
            ++score.recognised;
            bool matched = false;
            for (std::size_t i = 0; i < truth.size() && !matched; ++i) {
                if (!found[i] && normalised(truth[i].text) == key &&
                    overlap_of_smaller(box.box, truth[i].box) >= min_box_overlap) {
                    found[i] = matched = true;
                    ++score.correct;
                }
            }
            if (!matched)
                score.spurious.push_back(word);
        }
    }
    for (std::size_t i = 0; i < truth.size(); ++i)
        if (!found[i])
            score.missed.push_back(truth[i].text);
    return score;
}

std::string describe(const WordScore &score)
{
    std::ostringstream text;
    text.precision(3);
    text << "precision " << score.precision() << " (" << score.correct << "/" << score.recognised
         << "), recall " << score.recall() << " (" << score.correct << "/" << score.expected << ")";
    if (!score.missed.empty()) {
        text << "; missed:";
        for (const auto &word : score.missed)
            text << ' ' << word;
    }
    if (!score.spurious.empty()) {
        text << "; spurious:";
        for (const auto &word : score.spurious)
            text << " '" << word << "'";
    }
    return text.str();
}

} // namespace ubii::ocr::testing

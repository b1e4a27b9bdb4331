#include "evaluation_set.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <fstream>
#include <map>

#include <opencv2/freetype.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace ubii::ocr::testdata
{
namespace
{

constexpr int images_per_kind = 6;

// None of the tuning scenes' words on purpose: common English words, a few capitalised, and
// numbers.
const std::vector<std::string> &vocabulary()
{
    static const std::vector<std::string> words = {
        "garden", "window",  "market",   "bridge",  "winter",  "yellow",  "silver",   "coffee",
        "ticket", "station", "museum",   "library", "kitchen", "harbour", "lantern",  "meadow",
        "forest", "pencil",  "button",   "basket",  "candle",  "mirror",  "planet",   "rocket",
        "travel", "morning", "evening",  "friday",  "summer",  "autumn",  "river",    "castle",
        "Open",   "Closed",  "Sale",     "Fresh",   "Bakery",  "Parking", "Office",   "Welcome",
        "North",  "South",   "East",     "West",    "Center",  "Street",  "Avenue",   "Square",
        "please", "thank",   "you",      "only",    "daily",   "hours",   "from",     "until",
        "price",  "total",   "each",     "with",    "more",    "less",    "best",     "good",
        "Apple",  "Orange",  "Lemon",    "Bread",   "Cheese",  "Butter",  "Honey",    "Tomato",
        "green",  "purple",  "black",    "white",   "brown",   "golden",  "light",    "dark",
        "table",  "chair",   "lamp",     "door",    "floor",   "stairs",  "room",     "hall",
        "music",  "dance",   "theatre",  "cinema",  "gallery", "concert", "festival", "show",
        "2025",   "17",      "480",      "1999",    "36",      "250",     "8",        "71",
        "quiet",  "zone",    "entrance", "exit",    "push",    "pull",    "stop",     "slow",
        "danger", "caution", "notice",   "private", "public",  "service", "level",    "floor",
        "Monday", "Tuesday", "Sunday",   "July",    "March",   "October", "noon",     "night",
    };
    return words;
}

struct Font {
    std::string file;
    cv::Ptr<cv::freetype::FreeType2> face;
};

const Font &font(const std::string &file)
{
    static std::map<std::string, Font> loaded;
    auto found = loaded.find(file);
    if (found == loaded.end()) {
        Font entry{file, cv::freetype::createFreeType2()};
        entry.face->loadFontData(std::string(UBII_OCR_FONT_DIR) + "/" + file, 0);
        found = loaded.emplace(file, std::move(entry)).first;
    }
    return found->second;
}

// What varies between kinds; every image draws its own values from these ranges.
struct KindSettings {
    std::string name;
    cv::Size scene;
    double panel_width, panel_height; // of the scene
    std::vector<std::string> fonts;
    int min_height, max_height; // text height in panel pixels
    bool mixed_sizes;           // a size per line rather than per image
    int min_lines, max_lines, max_words_per_line;
    double min_turn, max_turn; // degrees, either way
    double perspective;        // corner jitter, of the panel's size
    double min_blur, max_blur; // Gaussian sigma, px
    double noise;              // sigma
    int jpeg_quality;          // 0: none
    int clutter;               // shapes around (and for photo, under) the panel
    enum class Panel { paper, coloured, pastel, textured, light, sheet } panel;
};

const std::vector<KindSettings> &kinds()
{
    using P = KindSettings::Panel;
    static const std::vector<KindSettings> all = {
        {"document",
         {1200, 900},
         0.92,
         0.9,
         {"DejaVuSerif.ttf", "DejaVuSans.ttf", "DejaVuSansMono.ttf"},
         26,
         40,
         false,
         5,
         7,
         6,
         0.0,
         2.0,
         0.0,
         0.0,
         0.6,
         3,
         0,
         0,
         P::paper},
        {"sign", {1200, 900}, 0.62,  0.42, {"DejaVuSans-Bold.ttf", "DejaVuSerif-Bold.ttf"},
         56,     84,          false, 2,    3,
         3,      2.0,         10.0,  0.08, 0.8,
         1.4,    6,           0,     50,   P::coloured},
        {"label",
         {900, 700},
         0.8,
         0.6,
         {"DejaVuSans-Bold.ttf", "DejaVuSans.ttf", "DejaVuSansMono-Bold.ttf"},
         26,
         60,
         true,
         2,
         4,
         4,
         0.0,
         5.0,
         0.03,
         0.3,
         0.7,
         4,
         0,
         12,
         P::pastel},
        {"photo",
         {1200, 900},
         0.7,
         0.5,
         {"DejaVuSans.ttf", "DejaVuSerif.ttf", "DejaVuSans-Bold.ttf"},
         36,
         60,
         false,
         2,
         4,
         4,
         0.0,
         8.0,
         0.05,
         1.0,
         1.5,
         8,
         0,
         40,
         P::textured},
        {"tilted",
         {1200, 900},
         0.85,
         0.7,
         {"DejaVuSans.ttf", "DejaVuSerif.ttf", "DejaVuSansMono.ttf"},
         32,
         48,
         false,
         3,
         5,
         5,
         6.0,
         10.0,
         0.06,
         0.4,
         0.7,
         4,
         0,
         0,
         P::light},
        {"lowres", {640, 480}, 0.62,  0.5,  {"DejaVuSans.ttf", "DejaVuSerif.ttf"},
         18,       26,         false, 3,    4,
         4,        0.0,        4.0,   0.04, 0.8,
         1.1,      6,          35,    20,   P::sheet},
    };
    return all;
}

// Every draw from the generator is its own statement: the order in which a call's arguments are
// evaluated is unspecified, and compilers differ, which would change the images.
cv::Scalar random_colour(cv::RNG &rng, int low, int high)
{
    const int blue = rng.uniform(low, high);
    const int green = rng.uniform(low, high);
    const int red = rng.uniform(low, high);
    return cv::Scalar(blue, green, red);
}

cv::Point random_point(cv::RNG &rng, cv::Size size)
{
    const int x = rng.uniform(0, size.width);
    const int y = rng.uniform(0, size.height);
    return {x, y};
}

double luminance(const cv::Scalar &bgr)
{
    return 0.114 * bgr[0] + 0.587 * bgr[1] + 0.299 * bgr[2];
}

// A saturated colour from a random hue, as a sign is painted.
cv::Scalar saturated_colour(cv::RNG &rng)
{
    const int hue = rng.uniform(0, 180);
    const int saturation = rng.uniform(150, 256);
    const int value = rng.uniform(150, 256);
    cv::Mat hsv(1, 1, CV_8UC3, cv::Scalar(hue, saturation, value));
    cv::Mat bgr;
    cv::cvtColor(hsv, bgr, cv::COLOR_HSV2BGR);
    const cv::Vec3b pixel = bgr.at<cv::Vec3b>(0, 0);
    return cv::Scalar(pixel[0], pixel[1], pixel[2]);
}

void add_shapes(cv::Mat &canvas, cv::RNG &rng, int shapes, int max_thickness)
{
    for (int i = 0; i < shapes; ++i) {
        const cv::Point a = random_point(rng, canvas.size());
        const cv::Point b = random_point(rng, canvas.size());
        const cv::Scalar colour = random_colour(rng, 0, 256);
        switch (rng.uniform(0, 3)) {
        case 0:
            cv::rectangle(canvas, a, b, colour, rng.uniform(-1, max_thickness));
            break;
        case 1: {
            const int radius = rng.uniform(5, canvas.rows / 5);
            cv::circle(canvas, a, radius, colour, rng.uniform(-1, max_thickness), cv::LINE_AA);
            break;
        }
        default:
            cv::line(canvas, a, b, colour, rng.uniform(1, max_thickness + 2), cv::LINE_AA);
            break;
        }
    }
}

void add_noise(cv::Mat &canvas, cv::RNG &rng, double sigma)
{
    cv::Mat noise(canvas.size(), CV_16SC3), widened;
    rng.fill(noise, cv::RNG::NORMAL, 0, sigma);
    canvas.convertTo(widened, CV_16SC3);
    widened += noise;
    widened.convertTo(canvas, CV_8UC3);
}

// The panel's ground and a text colour that stands out from it.
std::pair<cv::Mat, cv::Scalar> make_panel(const KindSettings &kind, cv::Size size, cv::RNG &rng)
{
    using P = KindSettings::Panel;
    cv::Mat panel(size, CV_8UC3);
    cv::Scalar ground, text;
    switch (kind.panel) {
    case P::paper:
        ground = random_colour(rng, 232, 256);
        text = random_colour(rng, 10, 60);
        break;
    case P::coloured:
        ground = saturated_colour(rng);
        text = luminance(ground) > 120 ? random_colour(rng, 10, 45) : random_colour(rng, 225, 256);
        break;
    case P::pastel:
        ground = random_colour(rng, 180, 245);
        text = random_colour(rng, 15, 80);
        break;
    case P::textured:
        ground = random_colour(rng, 150, 230);
        text = random_colour(rng, 10, 50);
        break;
    case P::light:
        ground = random_colour(rng, 200, 250);
        text = random_colour(rng, 20, 70);
        break;
    case P::sheet:
        ground = cv::Scalar::all(rng.uniform(170, 200));
        text = cv::Scalar::all(rng.uniform(70, 100));
        break;
    }
    panel.setTo(ground);
    if (kind.panel == P::textured) {
        // A soft gradient and faint blotches under the text, as on a photographed wall.
        for (int row = 0; row < panel.rows; ++row)
            panel.row(row) += cv::Scalar::all(30.0 * row / panel.rows);
        cv::Mat blotches = panel.clone();
        add_shapes(blotches, rng, 25, 30);
        cv::GaussianBlur(blotches, blotches, cv::Size(0, 0), 12);
        cv::addWeighted(panel, 0.8, blotches, 0.2, 0, panel);
    }
    if (kind.panel == P::coloured)
        cv::rectangle(panel, cv::Rect({}, size), text, std::max(4, size.height / 40));
    return {panel, text};
}

// Lines of random words that fit the panel, drawn from the top; each word's ink box measured on a
// canvas of its own.
std::vector<GroundTruthWord> write_text(cv::Mat &panel, const KindSettings &kind,
                                        const cv::Scalar &colour, cv::RNG &rng)
{
    const Font &chosen = font(
        kind.fonts[static_cast<std::size_t>(rng.uniform(0, static_cast<int>(kind.fonts.size())))]);
    const auto &words = vocabulary();
    const int lines = rng.uniform(kind.min_lines, kind.max_lines + 1);
    int height = rng.uniform(kind.min_height, kind.max_height + 1);
    const int margin = std::max(12, panel.cols / 16);
    int y = margin;
    std::vector<GroundTruthWord> truth;
    for (int line = 0; line < lines; ++line) {
        if (kind.mixed_sizes)
            height = rng.uniform(kind.min_height, kind.max_height + 1);
        if (y + height * 3 / 2 > panel.rows - margin / 2)
            break;
        int baseline = 0;
        const int space = chosen.face->getTextSize(" ", height, -1, &baseline).width + height / 6;
        int x = margin;
        const int count = rng.uniform(1, kind.max_words_per_line + 1);
        for (int i = 0; i < count; ++i) {
            const std::string &word =
                words[static_cast<std::size_t>(rng.uniform(0, static_cast<int>(words.size())))];
            const cv::Size size = chosen.face->getTextSize(word, height, -1, &baseline);
            if (x + size.width > panel.cols - margin)
                break;
            const int pad = height;
            cv::Mat ink = cv::Mat::zeros(size.height + 2 * pad, size.width + 2 * pad, CV_8UC3);
            chosen.face->putText(ink, word, cv::Point(pad, pad), height, cv::Scalar::all(255), -1,
                                 cv::LINE_AA, false);
            chosen.face->putText(panel, word, cv::Point(x, y), height, colour, -1, cv::LINE_AA,
                                 false);
            cv::Mat gray;
            cv::cvtColor(ink, gray, cv::COLOR_BGR2GRAY);
            const cv::Rect box = cv::boundingRect(gray > 40);
            truth.push_back({word, box + cv::Point(x - pad, y - pad)});
            x += size.width + space;
        }
        y += height * 3 / 2 + rng.uniform(0, height / 3);
    }
    return truth;
}

// Where the panel's corners land in the scene: centred with some play, turned, each corner moved
// a little for perspective, and shrunk until all four lie inside the scene (no word is cut off).
cv::Mat placement(const KindSettings &kind, cv::Size panel, cv::RNG &rng)
{
    const double degrees = rng.uniform(kind.min_turn, kind.max_turn + 1e-9);
    const double turn = (rng.uniform(0, 2) == 0 ? -degrees : degrees) * CV_PI / 180.0;
    const int shift_x = rng.uniform(-kind.scene.width / 20, kind.scene.width / 20 + 1);
    const int shift_y = rng.uniform(-kind.scene.height / 20, kind.scene.height / 20 + 1);
    const cv::Point2f centre(static_cast<float>(kind.scene.width / 2 + shift_x),
                             static_cast<float>(kind.scene.height / 2 + shift_y));
    const cv::Point2f flat[4] = {
        {0, 0},
        {static_cast<float>(panel.width), 0},
        {static_cast<float>(panel.width), static_cast<float>(panel.height)},
        {0, static_cast<float>(panel.height)}};
    cv::Point2f offsets[4];
    for (int i = 0; i < 4; ++i) {
        const double dx = flat[i].x - panel.width / 2.0, dy = flat[i].y - panel.height / 2.0;
        const double jitter_x =
            rng.uniform(-kind.perspective, kind.perspective + 1e-9) * panel.width;
        const double jitter_y =
            rng.uniform(-kind.perspective, kind.perspective + 1e-9) * panel.height;
        offsets[i] =
            cv::Point2f(static_cast<float>(dx * std::cos(turn) - dy * std::sin(turn) + jitter_x),
                        static_cast<float>(dx * std::sin(turn) + dy * std::cos(turn) + jitter_y));
    }
    const cv::Rect2f inside(1.0f, 1.0f, static_cast<float>(kind.scene.width - 2),
                            static_cast<float>(kind.scene.height - 2));
    cv::Point2f seen[4];
    for (float scale = 1.0f;; scale *= 0.97f) {
        bool fits = true;
        for (int i = 0; i < 4; ++i) {
            seen[i] = centre + offsets[i] * scale;
            fits = fits && inside.contains(seen[i]);
        }
        if (fits)
            return cv::getPerspectiveTransform(flat, seen);
    }
}

cv::Rect transformed_box(const cv::Rect &box, const cv::Mat &warp, cv::Size scene)
{
    std::vector<cv::Point2f> corners = {
        cv::Point2f(static_cast<float>(box.x), static_cast<float>(box.y)),
        cv::Point2f(static_cast<float>(box.x + box.width), static_cast<float>(box.y)),
        cv::Point2f(static_cast<float>(box.x + box.width), static_cast<float>(box.y + box.height)),
        cv::Point2f(static_cast<float>(box.x), static_cast<float>(box.y + box.height))};
    cv::perspectiveTransform(corners, corners, warp);
    const cv::Rect bounds = cv::boundingRect(corners);
    CV_Assert((bounds & cv::Rect({}, scene)) == bounds); // placement() keeps the panel inside
    return bounds;
}

} // namespace

const std::vector<std::string> &evaluation_kinds()
{
    static const std::vector<std::string> names = [] {
        std::vector<std::string> list;
        for (const auto &kind : kinds())
            list.push_back(kind.name);
        return list;
    }();
    return names;
}

int evaluation_set_size()
{
    return static_cast<int>(kinds().size()) * images_per_kind;
}

EvaluationScene evaluation_scene(int index)
{
    const KindSettings &kind = kinds().at(static_cast<std::size_t>(index / images_per_kind));
    cv::RNG rng(kUbiiEvaluationSeed + static_cast<unsigned>(index));
    const cv::Size panel_size(static_cast<int>(kind.scene.width * kind.panel_width),
                              static_cast<int>(kind.scene.height * kind.panel_height));
    auto [panel, colour] = make_panel(kind, panel_size, rng);
    const auto words = write_text(panel, kind, colour, rng);

    cv::Mat image(kind.scene, CV_8UC3);
    image.setTo(random_colour(rng, 60, 200));
    add_shapes(image, rng, kind.clutter, 8);
    const cv::Mat warp = placement(kind, panel_size, rng);
    cv::Mat warped, mask;
    cv::warpPerspective(panel, warped, warp, kind.scene, cv::INTER_LINEAR);
    cv::warpPerspective(cv::Mat(panel_size, CV_8UC1, cv::Scalar(255)), mask, warp, kind.scene,
                        cv::INTER_NEAREST);
    warped.copyTo(image, mask);

    EvaluationScene made{kind.name, Scene{}};
    char name[32];
    std::snprintf(name, sizeof name, "%02d-%s", index, kind.name.c_str());
    made.scene.name = name;
    for (const auto &word : words) {
        const cv::Rect box = transformed_box(word.box, warp, kind.scene);
        if (!box.empty())
            made.scene.words.push_back({word.text, box});
    }
    const double blur = rng.uniform(kind.min_blur, kind.max_blur + 1e-9);
    if (blur > 0.05)
        cv::GaussianBlur(image, image, cv::Size(0, 0), blur);
    add_noise(image, rng, kind.noise);
    if (kind.jpeg_quality > 0) {
        std::vector<std::uint8_t> jpeg;
        cv::imencode(".jpg", image, jpeg, {cv::IMWRITE_JPEG_QUALITY, kind.jpeg_quality});
        image = cv::imdecode(jpeg, cv::IMREAD_COLOR);
    }
    made.scene.image = image;
    return made;
}

std::vector<EvaluationScene> evaluation_set()
{
    std::vector<EvaluationScene> set;
    for (int i = 0; i < evaluation_set_size(); ++i)
        set.push_back(evaluation_scene(i));
    return set;
}

void write_evaluation_set(const std::string &dir)
{
    std::filesystem::create_directories(dir);
    for (const auto &entry : evaluation_set()) {
        const std::string base = dir + "/" + entry.scene.name;
        if (!cv::imwrite(base + ".png", entry.scene.image))
            throw std::runtime_error("cannot write " + base + ".png");
        std::ofstream truth(base + ".txt");
        if (!truth)
            throw std::runtime_error("cannot write " + base + ".txt");
        for (const auto &word : entry.scene.words)
            truth << word.box.x << ' ' << word.box.y << ' ' << word.box.width << ' '
                  << word.box.height << ' ' << word.text << '\n';
    }
}

} // namespace ubii::ocr::testdata

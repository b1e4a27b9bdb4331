#include "tesseract_engine.hpp"

#include <cctype>
#include <string>

#include <tesseract/baseapi.h>
#include <tesseract/resultiterator.h>

#include "option_checks.hpp"
#include "tesseract_messages.hpp"
#include "ubii/ocr/error.hpp"

namespace ubii::ocr::detail
{
namespace
{

struct TextDeleter {
    void operator()(char *text) const
    {
        delete[] text;
    } // Tesseract allocates results with new[]
};
using TesseractText = std::unique_ptr<char, TextDeleter>;

std::string trimmed(const char *text)
{
    std::string result = text == nullptr ? std::string() : std::string(text);
    const auto is_space = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
    while (!result.empty() && is_space(result.back()))
        result.pop_back();
    std::size_t first = 0;
    while (first < result.size() && is_space(result[first]))
        ++first;
    return result.substr(first);
}

} // namespace

TesseractEngine::TesseractEngine(const TesseractOptions &options)
    : api_(std::make_unique<tesseract::TessBaseAPI>()), options_(options)
{
    check(options);
    // Tesseract's messages into memory, not onto the process's stderr (tesseract_messages.hpp).
    if (const std::string &messages = tesseract_message_file(); !messages.empty())
        api_->SetVariable("debug_file", messages.c_str());
    const char *data_path = options.data_path.empty() ? nullptr : options.data_path.c_str();
    if (api_->Init(data_path, options.language.c_str(),
                   static_cast<tesseract::OcrEngineMode>(options.engine_mode)) != 0) {
        throw EngineError(
            "Tesseract could not load language '" + options.language + "' from " +
            (data_path != nullptr ? options.data_path : std::string("its default path")) +
            " (is tesseract-ocr-" + options.language +
            " installed, and does the engine mode suit its traineddata?)");
    }
    for (const auto &[name, value] : options.variables) {
        if (!api_->SetVariable(name.c_str(), value.c_str()))
            throw EngineError("Tesseract has no variable '" + name + "'");
    }
    api_->SetPageSegMode(static_cast<tesseract::PageSegMode>(options.segmentation));
}

TesseractEngine::~TesseractEngine()
{
    api_->End();
}

void TesseractEngine::set_image(const cv::Mat &gray)
{
    CV_Assert(gray.type() == CV_8UC1);
    api_->SetImage(gray.data, gray.cols, gray.rows, 1, static_cast<int>(gray.step[0]));
    // Set after SetImage, which forgets it; without it Tesseract estimates (and prints) it.
    api_->SetSourceResolution(options_.source_resolution_dpi);
}

void TesseractEngine::set_rectangle(const cv::Rect &area)
{
    api_->SetRectangle(area.x, area.y, area.width, area.height);
}

bool TesseractEngine::recognise()
{
    return api_->Recognize(nullptr) == 0;
}

std::vector<TextBox> TesseractEngine::read_words()
{
    std::vector<TextBox> words;
    if (!recognise())
        return words;
    const std::unique_ptr<tesseract::ResultIterator> word(api_->GetIterator());
    if (!word)
        return words;
    constexpr auto level = tesseract::RIL_WORD;
    do {
        if (word->Empty(level))
            continue;
        const float confidence = word->Confidence(level);
        if (confidence < options_.min_confidence)
            continue;
        std::string text = trimmed(TesseractText(word->GetUTF8Text(level)).get());
        int left = 0, top = 0, right = 0, bottom = 0;
        if (text.empty() || !word->BoundingBox(level, &left, &top, &right, &bottom))
            continue;
        words.push_back({std::move(text), confidence,
                         cv::Rect(left, top, right - left, bottom - top), std::nullopt});
    } while (word->Next(level));
    return words;
}

std::optional<TextBox> TesseractEngine::read_as_one(const cv::Rect &box)
{
    if (!recognise())
        return std::nullopt;
    const std::unique_ptr<tesseract::ResultIterator> word(api_->GetIterator());
    if (!word)
        return std::nullopt;
    constexpr auto level = tesseract::RIL_WORD;
    std::string joined;
    float confidence_sum = 0.0f;
    int count = 0;
    do {
        if (word->Empty(level))
            continue;
        const std::string text = trimmed(TesseractText(word->GetUTF8Text(level)).get());
        if (text.empty())
            continue;
        if (!joined.empty())
            joined += ' ';
        joined += text;
        confidence_sum += word->Confidence(level);
        ++count;
    } while (word->Next(level));
    if (count == 0)
        return std::nullopt;
    const float confidence = confidence_sum / static_cast<float>(count);
    if (confidence < options_.min_confidence)
        return std::nullopt;
    return TextBox{std::move(joined), confidence, box, std::nullopt};
}

std::optional<TextBox> TesseractEngine::read_best_symbol(const cv::Rect &box)
{
    if (!recognise())
        return std::nullopt;
    const std::unique_ptr<tesseract::ResultIterator> symbol(api_->GetIterator());
    if (!symbol)
        return std::nullopt;
    constexpr auto level = tesseract::RIL_SYMBOL;
    std::optional<TextBox> best;
    do {
        if (symbol->Empty(level))
            continue;
        const float confidence = symbol->Confidence(level);
        if (confidence < options_.min_confidence || (best && confidence <= best->confidence))
            continue;
        std::string text = trimmed(TesseractText(symbol->GetUTF8Text(level)).get());
        if (!text.empty())
            best = TextBox{std::move(text), confidence, box, std::nullopt};
    } while (symbol->Next(level));
    return best;
}

} // namespace ubii::ocr::detail

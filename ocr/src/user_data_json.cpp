#include "user_data_json.hpp"

#include <array>
#include <charconv>
#include <limits>
#include <optional>

namespace ubii::ocr::detail
{
namespace
{

void append_number(std::string &out, float value)
{
    std::array<char, 32> digits{};
    const auto result = std::to_chars(digits.data(), digits.data() + digits.size(), value);
    out.append(digits.data(), result.ptr);
}

// A tiny reader for the numbers this file writes: positions in `json`, moved past what was read.
class Reader
{
  public:
    explicit Reader(std::string_view json) : json_(json)
    {
    }

    bool seek_key(std::string_view key)
    {
        const std::string quoted = "\"" + std::string(key) + "\"";
        const auto found = json_.find(quoted, position_);
        if (found == std::string_view::npos)
            return false;
        position_ = found + quoted.size();
        return expect(':');
    }
    bool expect(char wanted)
    {
        skip_space();
        if (position_ >= json_.size() || json_[position_] != wanted)
            return false;
        ++position_;
        return true;
    }
    std::optional<float> number()
    {
        skip_space();
        float value = 0.0f;
        const auto result =
            std::from_chars(json_.data() + position_, json_.data() + json_.size(), value);
        if (result.ec != std::errc())
            return std::nullopt;
        position_ = static_cast<std::size_t>(result.ptr - json_.data());
        return value;
    }
    std::optional<cv::Point2f> pair()
    {
        if (!expect('['))
            return std::nullopt;
        const auto first = number();
        if (!first || !expect(','))
            return std::nullopt;
        const auto second = number();
        if (!second || !expect(']'))
            return std::nullopt;
        return cv::Point2f(*first, *second);
    }

  private:
    void skip_space()
    {
        while (position_ < json_.size() && (json_[position_] == ' ' || json_[position_] == '\t' ||
                                            json_[position_] == '\n' || json_[position_] == '\r'))
            ++position_;
    }
    std::string_view json_;
    std::size_t position_ = 0;
};

std::optional<cv::RotatedRect> read_rotated_box(std::string_view json)
{
    Reader reader(json);
    if (!reader.seek_key("rotated_box") || !reader.expect('{') || !reader.seek_key("center"))
        return std::nullopt;
    const auto center = reader.pair();
    if (!center || !reader.expect(',') || !reader.seek_key("size"))
        return std::nullopt;
    const auto size = reader.pair();
    if (!size || !reader.expect(',') || !reader.seek_key("angle"))
        return std::nullopt;
    const auto angle = reader.number();
    if (!angle)
        return std::nullopt;
    return cv::RotatedRect(*center, cv::Size2f(size->x, size->y), *angle);
}

} // namespace

std::string user_data_json(const TextBox &box)
{
    std::string json = "{\"confidence\":";
    append_number(json, box.confidence);
    if (box.rotated_box) {
        const auto &rotated = *box.rotated_box;
        json += ",\"rotated_box\":{\"center\":[";
        append_number(json, rotated.center.x);
        json += ',';
        append_number(json, rotated.center.y);
        json += "],\"size\":[";
        append_number(json, rotated.size.width);
        json += ',';
        append_number(json, rotated.size.height);
        json += "],\"angle\":";
        append_number(json, rotated.angle);
        json += '}';
    }
    json += '}';
    return json;
}

void read_user_data_json(std::string_view json, TextBox &box)
{
    Reader reader(json);
    std::optional<float> confidence;
    if (reader.seek_key("confidence"))
        confidence = reader.number();
    box.confidence = confidence.value_or(std::numeric_limits<float>::quiet_NaN());
    box.rotated_box = read_rotated_box(json);
}

} // namespace ubii::ocr::detail

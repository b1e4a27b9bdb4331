#include "character_regions.hpp"

#include <algorithm>

namespace ubii::ocr::detail
{
namespace
{

constexpr double duplicate_overlap = 0.8;    // intersection over union of two reports of one region
constexpr int min_character_height_px = 8;   // below this Tesseract reads nothing reliably
constexpr double max_width_per_height = 2.0; // wider than 'W' or 'm' in any common font
constexpr double max_height_per_width = 12.0; // thinner than 'l' or 'I' at any size
constexpr double dot_reach = 0.6; // how far above a stem (in stem heights) its dot may sit

double overlap(const cv::Rect &a, const cv::Rect &b)
{
    const double intersection = (a & b).area();
    return intersection / (a.area() + b.area() - intersection);
}

bool contains(const cv::Rect &outer, const cv::Rect &inner)
{
    return outer != inner && (outer & inner) == inner;
}

bool character_shaped(const cv::Rect &box)
{
    return box.height >= min_character_height_px && box.width > 0 &&
           box.width <= max_width_per_height * box.height &&
           box.height <= max_height_per_width * box.width;
}

bool side_by_side(const cv::Rect &a, const cv::Rect &b)
{
    return a.x + a.width <= b.x || b.x + b.width <= a.x;
}

std::vector<CharacterCandidate> without_duplicates(const std::vector<cv::Rect> &boxes)
{
    // Larger first, so that the outermost report of a region is the one kept.
    std::vector<std::size_t> order(boxes.size());
    for (std::size_t i = 0; i < order.size(); ++i)
        order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return boxes[a].area() > boxes[b].area();
    });
    std::vector<CharacterCandidate> kept;
    for (const std::size_t i : order) {
        const bool duplicate =
            std::any_of(kept.begin(), kept.end(), [&](const CharacterCandidate &other) {
                return overlap(boxes[i], other.box) >= duplicate_overlap;
            });
        if (!duplicate)
            kept.push_back({boxes[i], {i}});
    }
    return kept;
}

bool holds_two_side_by_side(const cv::Rect &box, const std::vector<CharacterCandidate> &candidates)
{
    std::vector<cv::Rect> inside;
    for (const auto &other : candidates)
        if (contains(box, other.box))
            inside.push_back(other.box);
    for (std::size_t i = 0; i < inside.size(); ++i)
        for (std::size_t j = i + 1; j < inside.size(); ++j)
            if (side_by_side(inside[i], inside[j]))
                return true;
    return false;
}

} // namespace

std::vector<CharacterCandidate> character_candidates(const std::vector<cv::Rect> &regions)
{
    const std::vector<CharacterCandidate> distinct = without_duplicates(regions);

    // Small regions (dots, specks) are kept aside: they may still be the dot of an i or j.
    std::vector<CharacterCandidate> shaped, small;
    for (const auto &candidate : distinct)
        (character_shaped(candidate.box) ? shaped : small).push_back(candidate);

    std::vector<CharacterCandidate> characters;
    for (const auto &candidate : shaped)
        if (!holds_two_side_by_side(candidate.box, shaped))
            characters.push_back(candidate);

    std::vector<CharacterCandidate> outermost;
    for (const auto &candidate : characters) {
        const bool inner =
            std::any_of(characters.begin(), characters.end(), [&](const CharacterCandidate &other) {
                return contains(other.box, candidate.box);
            });
        if (!inner)
            outermost.push_back(candidate);
    }

    for (auto &character : outermost) {
        cv::Rect &stem = character.box;
        for (const auto &small_region : small) {
            const cv::Rect &dot = small_region.box;
            const bool above = dot.y + dot.height <= stem.y &&
                               stem.y - (dot.y + dot.height) <= dot_reach * stem.height;
            const bool over = dot.x >= stem.x - dot.width / 2 &&
                              dot.x + dot.width <= stem.x + stem.width + dot.width / 2;
            if (above && over && dot.width <= stem.width * 2) {
                stem |= dot;
                character.regions.push_back(small_region.regions.front());
            }
        }
    }
    return outermost;
}

} // namespace ubii::ocr::detail

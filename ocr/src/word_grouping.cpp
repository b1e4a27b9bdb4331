#include "word_grouping.hpp"

#include <algorithm>
#include <numeric>

namespace ubii::ocr::detail
{
namespace
{

constexpr double min_line_overlap = 0.5; // of the shorter character's height
// Letters of one line differ in height by less than this factor (ascenders and descenders against
// x-height letters, about 1.5 in common fonts); a taller region beside them is clutter or a panel,
// and joining it would chain lines together.
constexpr double max_height_ratio = 2.0;
// Two word boxes sharing more than this fraction of the smaller one hold the same letters.
constexpr double max_shared_area = 0.5;

bool same_word(const cv::Rect &a, const cv::Rect &b, float max_gap)
{
    const int overlap_top = std::max(a.y, b.y);
    const int overlap_bottom = std::min(a.y + a.height, b.y + b.height);
    const int shorter = std::min(a.height, b.height);
    if (std::max(a.height, b.height) > max_height_ratio * shorter)
        return false;
    if (overlap_bottom - overlap_top < min_line_overlap * shorter)
        return false;
    const int gap = std::max(a.x, b.x) - std::min(a.x + a.width, b.x + b.width);
    return static_cast<float>(gap) <= max_gap * static_cast<float>(shorter);
}

struct DisjointSets {
    explicit DisjointSets(std::size_t size) : parent(size)
    {
        std::iota(parent.begin(), parent.end(), 0);
    }
    std::size_t root(std::size_t i)
    {
        while (parent[i] != i)
            i = parent[i] = parent[parent[i]];
        return i;
    }
    void join(std::size_t a, std::size_t b)
    {
        parent[root(a)] = root(b);
    }
    std::vector<std::size_t> parent;
};

} // namespace

std::vector<std::vector<std::size_t>> cluster_words(const std::vector<cv::Rect> &boxes,
                                                    float max_gap)
{
    DisjointSets sets(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i)
        for (std::size_t j = i + 1; j < boxes.size(); ++j)
            if (same_word(boxes[i], boxes[j], max_gap))
                sets.join(i, j);

    std::vector<std::vector<std::size_t>> members(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i)
        members[sets.root(i)].push_back(i);
    members.erase(std::remove_if(members.begin(), members.end(),
                                 [](const auto &word) { return word.empty(); }),
                  members.end());
    for (auto &word : members)
        std::sort(word.begin(), word.end(),
                  [&](std::size_t a, std::size_t b) { return boxes[a].x < boxes[b].x; });
    return members;
}

std::vector<TextBox> group_into_words(const std::vector<TextBox> &characters, float max_gap)
{
    std::vector<cv::Rect> boxes;
    for (const auto &character : characters)
        boxes.push_back(character.box);
    std::vector<TextBox> words;
    for (const auto &word : cluster_words(boxes, max_gap)) {
        TextBox joined{"", 0.0f, characters[word.front()].box, std::nullopt};
        for (const std::size_t i : word) {
            joined.text += characters[i].text;
            joined.confidence += characters[i].confidence;
            joined.box |= characters[i].box;
        }
        joined.confidence /= static_cast<float>(word.size());
        words.push_back(std::move(joined));
    }
    sort_reading_order(words);
    return words;
}

std::vector<std::vector<std::size_t>>
merge_runs_sharing_ink(const std::vector<cv::Rect> &boxes,
                       std::vector<std::vector<std::size_t>> runs)
{
    const auto share_ink = [&](const std::vector<std::size_t> &a,
                               const std::vector<std::size_t> &b) {
        for (const std::size_t i : a)
            for (const std::size_t j : b) {
                const double smaller = std::min(boxes[i].area(), boxes[j].area());
                if ((boxes[i] & boxes[j]).area() > max_shared_area * smaller)
                    return true;
            }
        return false;
    };
    // Repeated until nothing changes: a joined run can come to share ink with another.
    for (bool merged = true; merged;) {
        merged = false;
        for (std::size_t i = 0; i < runs.size() && !merged; ++i)
            for (std::size_t j = i + 1; j < runs.size() && !merged; ++j)
                if (share_ink(runs[i], runs[j])) {
                    runs[i].insert(runs[i].end(), runs[j].begin(), runs[j].end());
                    runs.erase(runs.begin() + static_cast<std::ptrdiff_t>(j));
                    merged = true;
                }
    }
    return runs;
}

void sort_reading_order(std::vector<TextBox> &words)
{
    // A stable order for callers: top to bottom, then left to right.
    std::sort(words.begin(), words.end(), [](const TextBox &a, const TextBox &b) {
        return a.box.y != b.box.y ? a.box.y < b.box.y : a.box.x < b.box.x;
    });
}

} // namespace ubii::ocr::detail

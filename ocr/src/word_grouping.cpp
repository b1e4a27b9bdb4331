#include "word_grouping.hpp"

#include <algorithm>
#include <numeric>

namespace ubii::ocr::detail
{
namespace
{

constexpr double min_line_overlap = 0.5; // of the shorter character's height

bool same_word(const cv::Rect &a, const cv::Rect &b, float max_gap)
{
    const int overlap_top = std::max(a.y, b.y);
    const int overlap_bottom = std::min(a.y + a.height, b.y + b.height);
    const int shorter = std::min(a.height, b.height);
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

std::vector<TextBox> group_into_words(const std::vector<TextBox> &characters, float max_gap)
{
    DisjointSets sets(characters.size());
    for (std::size_t i = 0; i < characters.size(); ++i)
        for (std::size_t j = i + 1; j < characters.size(); ++j)
            if (same_word(characters[i].box, characters[j].box, max_gap))
                sets.join(i, j);

    std::vector<std::vector<std::size_t>> members(characters.size());
    for (std::size_t i = 0; i < characters.size(); ++i)
        members[sets.root(i)].push_back(i);

    std::vector<TextBox> words;
    for (auto &word : members) {
        if (word.empty())
            continue;
        std::sort(word.begin(), word.end(), [&](std::size_t a, std::size_t b) {
            return characters[a].box.x < characters[b].box.x;
        });
        TextBox joined{"", 0.0f, characters[word.front()].box, std::nullopt};
        for (const std::size_t i : word) {
            joined.text += characters[i].text;
            joined.confidence += characters[i].confidence;
            joined.box |= characters[i].box;
        }
        joined.confidence /= static_cast<float>(word.size());
        words.push_back(std::move(joined));
    }
    // A stable order for callers: top to bottom, then left to right.
    std::sort(words.begin(), words.end(), [](const TextBox &a, const TextBox &b) {
        return a.box.y != b.box.y ? a.box.y < b.box.y : a.box.x < b.box.x;
    });
    return words;
}

} // namespace ubii::ocr::detail

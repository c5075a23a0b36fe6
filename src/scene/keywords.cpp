#include "scene/keywords.h"

#include <cctype>

namespace prt {
namespace {

// Levenshtein distance, ignoring case: "Radius" is one edit-free step from "radius".
size_t editDistance(std::string_view a, std::string_view b) {
  const auto same = [](char x, char y) {
    return std::tolower(static_cast<unsigned char>(x)) ==
           std::tolower(static_cast<unsigned char>(y));
  };
  std::vector<size_t> previous(b.size() + 1);
  std::vector<size_t> current(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) previous[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t substitute = previous[j - 1] + (same(a[i - 1], b[j - 1]) ? 0 : 1);
      current[j] = std::min({substitute, previous[j] + 1, current[j - 1] + 1});
    }
    std::swap(previous, current);
  }
  return previous[b.size()];
}

}  // namespace

std::string didYouMean(std::string_view word, const std::vector<std::string_view>& names) {
  // Up to one edit in three letters: "radus" finds "radius", "box" does not find "fov".
  const size_t allowed = std::max<size_t>(1, word.size() / 3);
  std::string_view best;
  size_t bestDistance = allowed + 1;
  for (const std::string_view name : names) {
    const size_t distance = editDistance(word, name);
    if (distance < bestDistance) {
      best = name;
      bestDistance = distance;
    }
  }
  if (best.empty()) return {};
  return " (did you mean '" + std::string(best) + "'?)";
}

}  // namespace prt

#include "dream/config/name_suggestion.h"

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <limits>

namespace dream::config {
namespace {

std::string Lower(const std::string& text) {
  std::string lower = text;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return lower;
}

// Edits (insert, delete, replace, swap of neighbours) from a to b: the
// optimal string alignment distance. Names are short, so O(|a| |b|) is fine.
size_t EditDistance(const std::string& a, const std::string& b) {
  std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
  for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
      }
    }
  }
  return d[a.size()][b.size()];
}

}  // namespace

std::string DidYouMean(const std::string& given, const std::vector<std::string>& names) {
  // Config text is bounded, but a name this long is no typo of a key.
  constexpr size_t kLongestName = 64;
  if (given.empty() || given.size() > kLongestName) return "";
  const std::string lower = Lower(given);
  const std::string* best = nullptr;
  size_t best_distance = std::numeric_limits<size_t>::max();
  for (const std::string& name : names) {
    if (name == given || name.size() > kLongestName) continue;
    const size_t distance = EditDistance(lower, Lower(name));
    // Up to two edits, one for names of five letters or fewer.
    const size_t allowed = std::min(given.size(), name.size()) <= 5 ? 1 : 2;
    if (distance <= allowed && distance < best_distance) {
      best = &name;
      best_distance = distance;
    }
  }
  if (best == nullptr && given.size() >= 3) {
    for (const std::string& name : names) {
      if (name.size() > given.size() && Lower(name).compare(0, lower.size(), lower) == 0) {
        best = &name;
        break;
      }
    }
  }
  return best == nullptr ? "" : " (did you mean '" + *best + "'?)";
}

}  // namespace dream::config

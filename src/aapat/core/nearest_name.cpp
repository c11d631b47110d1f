#include "aapat/core/nearest_name.h"

#include <algorithm>
#include <cctype>
#include <numeric>

namespace aapat {

size_t edit_distance(std::string_view a, std::string_view b) {
  const auto same = [](char x, char y) {
    return std::tolower(static_cast<unsigned char>(x)) ==
           std::tolower(static_cast<unsigned char>(y));
  };
  // d[i][j]: edits from a's first i characters to b's first j; three rows kept.
  const size_t w = b.size() + 1;
  std::vector<size_t> before(w), previous(w), row(w);
  std::iota(previous.begin(), previous.end(), size_t{0});
  for (size_t i = 1; i <= a.size(); ++i) {
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      row[j] = std::min(
          {previous[j] + 1, row[j - 1] + 1, previous[j - 1] + (same(a[i - 1], b[j - 1]) ? 0 : 1)});
      if (i > 1 && j > 1 && same(a[i - 1], b[j - 2]) && same(a[i - 2], b[j - 1]))
        row[j] = std::min(row[j], before[j - 2] + 1);  // two neighbours swapped
    }
    std::swap(before, previous);
    std::swap(previous, row);
  }
  return previous[b.size()];
}

std::optional<std::string> nearest_name(std::string_view name,
                                        const std::vector<std::string>& candidates) {
  std::optional<std::string> best;
  size_t best_distance = 0;
  constexpr size_t kMostAllowed = 3;
  for (const std::string& c : candidates) {
    const bool prefix = name.size() >= 3 && c.starts_with(name);
    // The distance is at least the difference in length: past the most ever
    // allowed, no need to compute it (a 100 KB argument against every name
    // took seconds).
    const size_t gap = name.size() > c.size() ? name.size() - c.size() : c.size() - name.size();
    if (gap > kMostAllowed && !prefix) continue;
    const size_t d = edit_distance(name, c);
    const size_t allowed = std::clamp<size_t>(std::max(name.size(), c.size()) / 3, 1, kMostAllowed);
    if ((d <= allowed || prefix) && (!best || d < best_distance)) {
      best = c;
      best_distance = d;
    }
  }
  return best;
}

std::string did_you_mean(std::string_view name, const std::vector<std::string>& candidates) {
  const auto nearest = nearest_name(name, candidates);
  return nearest ? " (did you mean '" + *nearest + "'?)" : "";
}

}  // namespace aapat

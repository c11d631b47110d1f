// The two string helpers every spec parser needs: comma lists and trimming.
#pragma once

#include <string_view>
#include <vector>

namespace aapat {

inline std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
    s.remove_suffix(1);
  return s;
}

// "a,b,c" -> {"a", "b", "c"}; an empty text has no items.
inline std::vector<std::string_view> split(std::string_view text, char sep = ',') {
  std::vector<std::string_view> items;
  while (!text.empty()) {
    const auto at = text.find(sep);
    items.push_back(text.substr(0, at));
    text = at == std::string_view::npos ? std::string_view{} : text.substr(at + 1);
  }
  return items;
}

}  // namespace aapat

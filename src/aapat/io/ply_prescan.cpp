#include "aapat/io/ply_prescan.h"

#include <fmt/format.h>

#include <charconv>
#include <cstdint>
#include <vector>

#include "aapat/core/geometry.h"
#include "aapat/core/text.h"
#include "aapat/render/mesh.h"

namespace aapat {
namespace {

struct Element {
  std::string name;
  uint64_t count = 0;
  int properties = 0;
  bool one_list = false;  // exactly one property, a list
};

// The next line of `bytes` from `at` (without its end), moving `at` past it.
std::string_view next_line(std::string_view bytes, size_t& at) {
  const size_t end = std::min(bytes.find('\n', at), bytes.size());
  std::string_view line = bytes.substr(at, end - at);
  if (line.ends_with('\r')) line.remove_suffix(1);
  at = end + 1;
  return line;
}

std::vector<std::string_view> words(std::string_view line) {
  std::vector<std::string_view> out;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    const size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

}  // namespace

bool looks_like_ply(std::string_view bytes) {
  return bytes.starts_with("ply\n") || bytes.starts_with("ply\r\n");
}

void prescan_ply(std::string_view bytes, const std::string& path) {
  size_t at = 0;
  next_line(bytes, at);  // "ply"
  std::vector<Element> elements;
  bool ascii = false, ended = false;
  while (at < bytes.size()) {
    const std::vector<std::string_view> w = words(next_line(bytes, at));
    if (w.empty()) continue;
    if (w[0] == "end_header") {
      ended = true;
      break;
    }
    if (w[0] == "format" && w.size() > 1) ascii = w[1] == "ascii";
    if (w[0] == "element" && w.size() > 2) {
      Element e;
      e.name = std::string(w[1]);
      const auto [end, ec] = std::from_chars(w[2].data(), w[2].data() + w[2].size(), e.count);
      if (ec != std::errc() || end != w[2].data() + w[2].size())
        throw Error(fmt::format("model '{}': element {} has count '{}', not a whole number", path,
                                w[1], w[2]));
      elements.push_back(e);
    }
    if (w[0] == "property" && !elements.empty()) {
      Element& e = elements.back();
      ++e.properties;
      e.one_list = e.properties == 1 && w.size() > 1 && w[1] == "list";
    }
  }
  if (!ended) throw Error(fmt::format("model '{}': a PLY header without end_header", path));
  for (const Element& e : elements) {
    const uint64_t limit = e.name == "vertex" ? kMaxMeshVertices
                           : e.name == "face" ? kMaxMeshTriangles
                                              : 0;
    if (limit > 0 && e.count > limit)
      throw Error(fmt::format("model '{}': {} {} elements; at most {} (docs/limits.md)", path,
                              e.count, e.name, limit));
  }
  if (!ascii) return;
  // ASCII: one line per element, in order; a face list's count must match.
  for (const Element& e : elements) {
    for (uint64_t k = 0; k < e.count && at < bytes.size(); ++k) {
      const std::string_view line = next_line(bytes, at);
      if (e.name != "face" || !e.one_list) continue;
      const std::vector<std::string_view> w = words(line);
      uint64_t listed = 0;
      if (w.empty() ||
          std::from_chars(w[0].data(), w[0].data() + w[0].size(), listed).ec != std::errc() ||
          listed != w.size() - 1)
        throw Error(fmt::format("model '{}': face {} lists {} indices but its line gives {}", path,
                                k, w.empty() ? "no" : std::string(w[0]),
                                w.empty() ? 0 : w.size() - 1));
    }
  }
}

}  // namespace aapat

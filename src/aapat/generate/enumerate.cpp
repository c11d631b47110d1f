#include "aapat/generate/enumerate.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "aapat/core/geometry.h"

namespace aapat {
namespace {

// Quarter turn counter-clockwise: bottom-left -> bottom-right -> top-right ->
// top-left, and bottom edge -> right -> top -> left.
PlacementConfig rotate(const PlacementConfig& c) {
  PlacementConfig r = c;
  for (int i = 0; i < 4; ++i) {
    r.corners[(i + 1) % 4] = c.corners[i];
    r.edges[(i + 1) % 4] = c.edges[i];
  }
  return r;
}

// Mirror in x: left and right swap, bottom and top stay.
PlacementConfig mirror(const PlacementConfig& c) {
  PlacementConfig r = c;
  r.corners = {c.corners[1], c.corners[0], c.corners[3], c.corners[2]};
  r.edges = {c.edges[0], c.edges[3], c.edges[2], c.edges[1]};
  return r;
}

bool on_one_border_line(const PlacementConfig& c) {
  if (c.inside > 0) return false;
  // Border line i: edge i with corners i and i+1 (bottom: bottom-left, bottom-right).
  for (int i = 0; i < 4; ++i) {
    int off = 0;
    for (int j = 0; j < 4; ++j) {
      if (j != i) off += c.edges[j];
      if (j != i && j != (i + 1) % 4) off += c.corners[j];
    }
    if (off == 0) return true;
  }
  return false;
}

}  // namespace

double PlacementConfig::cost() const {
  double n = inside;
  for (int i = 0; i < 4; ++i) n += 0.25 * corners[i] + 0.5 * edges[i];
  return n;
}

int PlacementConfig::samples() const {
  int s = inside;
  for (int i = 0; i < 4; ++i) s += corners[i] + edges[i];
  return s;
}

std::string PlacementConfig::sites() const {
  static const char* kCorner[] = {"bottom-left", "bottom-right", "top-right", "top-left"};
  static const char* kEdge[] = {"bottom", "right", "top", "left"};
  std::string s;
  auto add = [&](const char* site) {
    if (!s.empty()) s += ',';
    s += site;
  };
  for (int i = 0; i < 4; ++i)
    if (corners[i]) add(kCorner[i]);
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < edges[i]; ++k) add(kEdge[i]);
  for (int k = 0; k < inside; ++k) add("inside");
  return s;
}

std::array<PlacementConfig, 8> symmetric_images(const PlacementConfig& c) {
  std::array<PlacementConfig, 8> out;
  PlacementConfig r = c;
  for (int i = 0; i < 4; ++i) {
    out[2 * i] = r;
    out[2 * i + 1] = mirror(r);
    r = rotate(r);
  }
  return out;
}

std::vector<PlacementConfig> enumerate_placements(double n, const EnumerationRules& rules) {
  const long quarters = std::lround(n * 4);
  if (!(n > 0) || std::abs(quarters - n * 4) > 1e-9 || quarters > 64)
    throw ParameterError("cost", fmt::format(": {} is not a multiple of 1/4 in (0, 16]", n));
  std::set<PlacementConfig> found;
  // Corners (4 bits), then edges and inside within the remaining budget.
  for (int mask = 0; mask < 16; ++mask) {
    PlacementConfig c;
    int used = 0;
    for (int i = 0; i < 4; ++i) used += c.corners[i] = (mask >> i) & 1;
    const long left = quarters - used;  // in quarters
    if (left < 0) continue;
    const int max_edge = std::min<int>(rules.max_per_edge, static_cast<int>(left / 2));
    for (int b = 0; b <= max_edge; ++b)
      for (int r = 0; r <= max_edge; ++r)
        for (int t = 0; t <= max_edge; ++t)
          for (int l = 0; l <= max_edge; ++l) {
            const long rest = left - 2L * (b + r + t + l);
            if (rest < 0 || rest % 4 != 0) continue;
            c.edges = {b, r, t, l};
            c.inside = static_cast<int>(rest / 4);
            if (rules.cull_one_edge && on_one_border_line(c)) continue;
            const auto images = symmetric_images(c);
            found.insert(*std::min_element(images.begin(), images.end()));
          }
  }
  return {found.begin(), found.end()};
}

}  // namespace aapat

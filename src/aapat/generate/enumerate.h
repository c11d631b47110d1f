// Every placement configuration of the mirrored P(4,1+,n) family
// (Hasselgren et al. Sec. 5.1): which corners hold a sample, how many samples
// sit on each edge, how many inside, for a cost n (corner 1/4, edge 1/2,
// inside 1), keeping one configuration of each class under the pixel's
// rotations (90, 180, 270 degrees) and reflections.
//
// Counts (tested): with any number of samples per edge, n = 1.25, 1.5, 1.75, 2
// give 9 + 19 + 19 + 38 = 85 configurations, and adding n = 1 (9 more) gives
// the 94 the paper reports "in our target families". With at most one sample
// per edge the four costs give 7 + 12 + 9 + 15 = 43.
#pragma once

#include <array>
#include <string>
#include <tuple>
#include <vector>

namespace aapat {

struct PlacementConfig {
  std::array<int, 4> corners{};  // bottom-left, bottom-right, top-right, top-left: 0 or 1
  std::array<int, 4> edges{};    // samples on the bottom, right, top, left edges
  int inside = 0;

  double cost() const;
  int samples() const;  // samples the base pixel's kernel reads
  // The --placement string of `aapat optimize`, e.g. "bottom-left,left,top,right".
  std::string sites() const;
  friend bool operator==(const PlacementConfig&, const PlacementConfig&) = default;
  // By hand, not a defaulted <=>: the WebAssembly build's libc++ has no <=> for std::array.
  friend bool operator<(const PlacementConfig& a, const PlacementConfig& b) {
    return std::tie(a.corners, a.edges, a.inside) < std::tie(b.corners, b.edges, b.inside);
  }
  friend bool operator<=(const PlacementConfig& a, const PlacementConfig& b) { return !(b < a); }
};

struct EnumerationRules {
  int max_per_edge = 8;        // samples one edge may hold (8: as many as the cost allows)
  bool cull_one_edge = false;  // drop configurations whose samples all lie on one border
                               // line (an edge and its two corners), the paper's hand cull
};

// The canonical configurations of cost n (each the least of its 8 images),
// in increasing order. n must be a positive multiple of 1/4.
std::vector<PlacementConfig> enumerate_placements(double n, const EnumerationRules& rules = {});

// The 8 images of a configuration under the pixel's symmetries.
std::array<PlacementConfig, 8> symmetric_images(const PlacementConfig& c);

}  // namespace aapat

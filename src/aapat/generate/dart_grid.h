// Dart throwing's occupancy grid on the unit torus (poisson and
// poisson-maximal): cells of side below r / sqrt(2), so each holds at most one
// point of a set with minimum distance r, and every point within r of a spot
// lies in the 5 x 5 cells around the spot's own, in one flat array. The grid
// stops at 2048 cells a side (64 MB; r below about 6.9e-4): there a cell can
// hold more than one point, and the others are kept by cell on the side.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <unordered_map>
#include <vector>

#include "aapat/core/geometry.h"

namespace aapat {

// The shortest gaps between a and b along each axis of the unit torus.
inline Vec2 torus_gap(Vec2 a, Vec2 b) {
  const double dx = std::abs(a.x - b.x), dy = std::abs(a.y - b.y);
  return {std::min(dx, 1 - dx), std::min(dy, 1 - dy)};
}

// Distance on the unit torus, so that tiled point sets keep their spacing.
inline double torus_distance(Vec2 a, Vec2 b) {
  const Vec2 g = torus_gap(a, b);
  return std::sqrt(g.x * g.x + g.y * g.y);  // not hypot: the same bits with every libm
}

class DartGrid {
 public:
  static constexpr int kMaxSide = 2048;
  explicit DartGrid(double r)
      : g_(std::clamp(static_cast<int>(std::sqrt(2.0) / r) + 1, 1, kMaxSide)),
        reach_(std::min(g_ / 2, static_cast<int>(std::ceil(r * g_)))),
        cells_(static_cast<size_t>(g_) * g_, Vec2{NAN, NAN}) {}
  int side() const { return g_; }
  int cell(double v) const { return std::min(g_ - 1, static_cast<int>(v * g_)); }
  // The point in cell (cx, cy) (each in [0, g)), or NaN.
  const Vec2& at(int cx, int cy) const {
    return cells_[static_cast<size_t>(wrap(cy)) * g_ + wrap(cx)];
  }
  void add(Vec2 p) {
    const size_t i = static_cast<size_t>(cell(p.y)) * g_ + cell(p.x);
    if (std::isnan(cells_[i].x))
      cells_[i] = p;
    else
      more_[i].push_back(p);  // only on a grid at kMaxSide
  }
  // Whether near(e) holds for a point e in the cells within r of cell (cx, cy)
  // (each in [0, g)).
  template <class Near>
  bool any_near(int cx, int cy, Near near) const {
    for (int dy = -reach_; dy <= reach_; ++dy) {
      const size_t row = static_cast<size_t>(wrap(cy + dy)) * g_;
      for (int dx = -reach_; dx <= reach_; ++dx) {
        const size_t i = row + wrap(cx + dx);
        const Vec2& e = cells_[i];
        if (std::isnan(e.x)) continue;
        if (near(e)) return true;
        if (more_.empty()) continue;
        if (const auto it = more_.find(i); it != more_.end())
          for (const Vec2& m : it->second)
            if (near(m)) return true;
      }
    }
    return false;
  }
  bool any_within(Vec2 c, double r) const {
    return any_near(cell(c.x), cell(c.y), [&](Vec2 e) { return torus_distance(e, c) < r; });
  }

 private:
  // i in [-g, 2g), as a cell's neighbours are, onto [0, g) without a division.
  int wrap(int i) const { return i < 0 ? i + g_ : i >= g_ ? i - g_ : i; }
  int g_, reach_;
  std::vector<Vec2> cells_;
  std::unordered_map<size_t, std::vector<Vec2>> more_;  // a cell's second point on
};

}  // namespace aapat

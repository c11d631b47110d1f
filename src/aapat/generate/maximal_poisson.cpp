#include "aapat/generate/maximal_poisson.h"
#include "aapat/generate/portable_random.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <numbers>

#include "aapat/core/interrupt.h"
#include "aapat/generate/dart_grid.h"

namespace aapat {
namespace {

// A square of the active set: column x and row y of the level's grid, which
// splits each of the dart grid's g x g cells into 2^level x 2^level.
struct Cell {
  int64_t x, y;
};

// Past this level a cell is narrower than 1e-12 r: what is left uncovered
// there is rounding, not room for a point.
constexpr int kDeepestLevel = 40;

// Whether a and b are closer than r on the torus (r2 = r^2).
bool closer(Vec2 a, Vec2 b, double r2) {
  const Vec2 g = torus_gap(a, b);
  return g.x * g.x + g.y * g.y < r2;
}

// v shifted by a whole period to the image nearest `to`.
double nearest_image(double v, double to) {
  if (v - to > 0.5) return v - 1;
  if (to - v > 0.5) return v + 1;
  return v;
}

// Whether the disk of radius r around e (its image nearest the square)
// holds the square [x0, x1] x [y0, y1] whole: a disk is convex, so its four
// corners suffice.
bool covers(Vec2 e, double x0, double x1, double y0, double y1, double r2) {
  const double ex = nearest_image(e.x, (x0 + x1) / 2), ey = nearest_image(e.y, (y0 + y1) / 2);
  const double dx = std::max(std::abs(x0 - ex), std::abs(x1 - ex));
  const double dy = std::max(std::abs(y0 - ey), std::abs(y1 - ey));
  return dx * dx + dy * dy < r2;
}

}  // namespace

std::vector<Vec2> maximal_poisson_disk(double r, std::mt19937_64& rng,
                                       const ItemsProgress& progress) {
  if (!(r >= kMinMaximalPoissonRadius && r <= 1))
    throw Error(fmt::format(
        "poisson-maximal: radius = {} is out of range [{}, 1] (a maximal set of radius r has "
        "about 0.7 / r^2 points)",
        r, kMinMaximalPoissonRadius));
  Hundredths done(progress);
  const double expected = 4 * kRsaSaturationCoverage / (std::numbers::pi * r * r);
  DartGrid grid(r);
  const int g = grid.side();
  const double r2 = r * r;
  const auto u = [](std::mt19937_64& r) { return unit_double(r); };
  std::vector<Vec2> points;
  std::vector<Cell> active, next;
  for (int y = 0; y < g; ++y)
    for (int x = 0; x < g; ++x) active.push_back({x, y});
  for (int level = 0; !active.empty() && level <= kDeepestLevel; ++level) {
    const double per_axis = std::ldexp(static_cast<double>(g), level);  // exact: g < 2^14
    // A round of darts, as many as there are active cells, each in a cell
    // drawn uniformly (all of one area): uniform on the active region.
    for (size_t t = 0; t < active.size(); ++t) {
      if (t % 65536 == 0) throw_if_interrupted();
      const Cell& c = active[uniform_below(rng, active.size())];
      const double ux = u(rng), uy = u(rng);
      const Vec2 d{(static_cast<double>(c.x) + ux) / per_axis,
                   (static_cast<double>(c.y) + uy) / per_axis};
      if (!(d.x < 1 && d.y < 1)) continue;  // rounded onto the seam, which is 0
      if (grid.any_near(grid.cell(d.x), grid.cell(d.y), [&](Vec2 e) { return closer(e, d, r2); }))
        continue;
      grid.add(d);
      points.push_back(d);
      done.at(static_cast<double>(points.size()) / expected);
    }
    // The children of each active cell that no disk holds whole. A dart
    // grid cell with a point in it is covered by that point's disk (its
    // diagonal is below r), and so is every cell inside it.
    next.clear();
    const double half = 2 * per_axis;
    for (const Cell& c : active) {
      const int cx = static_cast<int>(c.x >> level), cy = static_cast<int>(c.y >> level);
      if (!std::isnan(grid.at(cx, cy).x)) continue;
      for (int k = 0; k < 4; ++k) {
        const Cell child{2 * c.x + (k & 1), 2 * c.y + (k >> 1)};
        const double x0 = static_cast<double>(child.x) / half,
                     x1 = static_cast<double>(child.x + 1) / half,
                     y0 = static_cast<double>(child.y) / half,
                     y1 = static_cast<double>(child.y + 1) / half;
        if (!grid.any_near(cx, cy, [&](Vec2 e) { return covers(e, x0, x1, y0, y1, r2); }))
          next.push_back(child);
      }
    }
    active.swap(next);
  }
  return points;
}

}  // namespace aapat

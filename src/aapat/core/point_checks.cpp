#include "aapat/core/point_checks.h"

#include <fmt/format.h>

#include <cmath>

namespace aapat {

void check_unit_square(std::span<const Vec2> points, std::string_view what) {
  if (points.empty()) throw Error(fmt::format("{}: no points", what));
  for (size_t i = 0; i < points.size(); ++i) {
    const Vec2 p = points[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
      throw Error(fmt::format("{}: point {} ({}, {}) is not finite", what, i, p.x, p.y));
    if (!(p.x >= 0 && p.x <= 1 && p.y >= 0 && p.y <= 1))
      throw Error(fmt::format("{}: point {} ({}, {}) lies outside the unit square [0, 1] x [0, 1]",
                              what, i, p.x, p.y));
  }
}

void check_in_pixel(std::span<const double> xy, std::string_view what) {
  for (size_t i = 0; i < xy.size(); ++i) {
    const char* axis = i % 2 ? "y" : "x";
    if (!std::isfinite(xy[i]))
      throw Error(fmt::format("{}: sample {} {} = {} is not finite", what, i / 2, axis, xy[i]));
    if (std::abs(xy[i]) > 0.5)
      throw Error(fmt::format(
          "{}: sample {} {} = {} lies outside the pixel [-0.5, 0.5] (pixels from its centre)", what,
          i / 2, axis, xy[i]));
  }
}

}  // namespace aapat

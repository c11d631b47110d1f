#include "aapat/core/lattice.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace aapat {
namespace {

bool on_border(double v) {
  return std::abs(std::abs(v) - 0.5) < kSameSampleEps;
}

}  // namespace

double snap_coordinate(double v, int steps) {
  if (on_border(v)) return v > 0 ? 0.5 : -0.5;
  const double k = std::clamp(std::round(v * steps), -(steps / 2.0 - 1), steps / 2.0 - 1);
  return k / steps;
}

Vec2 snap_sample(Vec2 v, int steps, bool shared_borders, bool y_down) {
  if (shared_borders) return {snap_coordinate(v.x, steps), snap_coordinate(v.y, steps)};
  const double half = steps / 2.0;
  const double y = y_down ? std::clamp(std::round(v.y * steps), -(half - 1), half)
                          : std::clamp(std::round(v.y * steps), -half, half - 1);
  return {std::clamp(std::round(v.x * steps), -half, half - 1) / steps, y / steps};
}

Pattern snap_to_lattice(const Pattern& p, int steps, bool y_down) {
  if (steps < 2 || steps > 256 || steps % 2 != 0)
    throw ParameterError("lattice",
                         fmt::format(" {}: expected an even number of steps from 2 to 256", steps));
  Pattern q = p;
  for (auto& set : q.sets)
    for (Vec2& s : set) s = snap_sample(s, steps, p.footprint.plus, y_down);
  q.provenance.emplace_back("lattice", fmt::format("snapped to 1/{} pixel", steps));
  validate(q);  // two samples that met on one lattice point are caught here
  return q;
}

std::string off_lattice_sample(const Pattern& p, int steps) {
  for (size_t k = 0; k < p.sets.size(); ++k)
    for (size_t i = 0; i < p.sets[k].size(); ++i) {
      const Vec2 s = p.sets[k][i];
      for (double v : {s.x, s.y})
        if (std::abs(v * steps - std::round(v * steps)) > 1e-9)
          return fmt::format("sets[{}][{}] = ({:.6g}, {:.6g}) is not on the 1/{} lattice", k, i,
                             s.x, s.y, steps);
    }
  return {};
}

}  // namespace aapat

#include "aapat/temporal/model/pan_distribution.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "aapat/generate/unit_random.h"
#include "aapat/temporal/sequence/sequence_generators.h"

namespace aapat {

std::vector<Vec2> random_pan_velocities(int count, double max_speed, uint64_t seed) {
  if (count < 1 || count > kMaxRandomPanVelocities)
    throw ParameterError("random-velocities", fmt::format(" {}: expected 1 to {} velocities", count,
                                                          kMaxRandomPanVelocities));
  if (!(max_speed > 0 && max_speed <= kMaxPanSpeed))  // NaN fails too
    throw ParameterError("max-speed", fmt::format(" {}: expected a speed in (0, {:g}] pixels per "
                                                  "frame",
                                                  max_speed, kMaxPanSpeed));
  std::mt19937_64 rng(seed);
  const auto draw = [&] {
    return std::round((2 * unit_double(rng) - 1) * max_speed * 1000) / 1000;
  };
  std::vector<Vec2> out(static_cast<size_t>(count));
  for (Vec2& v : out) {
    const double x = draw();
    v = {x, draw()};
  }
  return out;
}

std::vector<Vec2> resonant_velocities() {
  const double axis[] = {0, 0.25, -0.25, 1.0 / 3, -1.0 / 3, 0.5};
  std::vector<Vec2> out;
  for (const double x : axis)
    for (const double y : axis) out.push_back({x, y});
  const Vec2 r2{1 / kPlasticNumber, 1 / (kPlasticNumber * kPlasticNumber)};
  out.push_back(r2);
  out.push_back({-r2.x, -r2.y});
  return out;
}

std::vector<Vec2> pan_velocities(const std::optional<std::vector<Vec2>>& given, int random_count,
                                 double max_speed, uint64_t seed) {
  std::vector<Vec2> out = given               ? *given
                          : random_count == 0 ? default_pan_velocities()
                                              : std::vector<Vec2>{};
  if (random_count != 0)
    for (const Vec2 v : random_pan_velocities(random_count, max_speed, seed)) out.push_back(v);
  return out;
}

PanComparison compare_pans(const std::vector<PanReport>& ours,
                           const std::vector<PanReport>& theirs) {
  if (ours.size() != theirs.size() || ours.empty())
    throw Error(fmt::format("compare_pans: {} against {} velocities", ours.size(), theirs.size()));
  PanComparison c;
  c.velocities = static_cast<int>(ours.size());
  c.lowest_change = HUGE_VAL;
  c.highest_change = -HUGE_VAL;
  for (size_t i = 0; i < ours.size(); ++i) {
    const double change = ours[i].mean_e2 / theirs[i].mean_e2 - 1;
    c.lower += ours[i].mean_e2 < theirs[i].mean_e2;
    c.mean_change += change / static_cast<double>(ours.size());
    c.lowest_change = std::min(c.lowest_change, change);
    c.highest_change = std::max(c.highest_change, change);
  }
  return c;
}

}  // namespace aapat

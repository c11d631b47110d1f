#include "aapat/generate/point_processes.h"
#include "aapat/generate/portable_random.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace aapat {

SeedKind parse_seed_kind(std::string_view text) {
  if (text == "jittered") return SeedKind::kJittered;
  if (text == "poisson") return SeedKind::kPoisson;
  if (text == "uniform") return SeedKind::kUniform;
  throw ParameterError(
      "seeds", fmt::format(": '{}' is not jittered, poisson, uniform or a pattern file", text));
}

std::vector<std::vector<Vec2>> tile_points(int side, int m, SeedKind kind, std::mt19937_64& rng,
                                           double limit) {
  const auto u = [](std::mt19937_64& r) { return unit_double(r); };
  auto clampv = [&](Vec2 v) {
    return Vec2{std::clamp(v.x, -limit, limit), std::clamp(v.y, -limit, limit)};
  };
  std::vector<std::vector<Vec2>> sets(side * side);
  if (kind == SeedKind::kPoisson) {
    // Darts of radius 0.75 of the densest packing's, shrinking when they keep missing.
    double d = 0.75 * std::sqrt(2 / (std::sqrt(3.0) * std::max(m, 1)));
    std::vector<Vec2> world;  // tile coordinates, pixel centres at integers
    auto torus = [&](double a) {
      a = std::fmod(std::abs(a), static_cast<double>(side));
      return std::min(a, side - a);
    };
    for (int k = 0; k < side * side; ++k) {
      const int tx = k % side, ty = k / side;
      while (static_cast<int>(sets[k].size()) < m) {
        bool placed = false;
        for (int attempt = 0; attempt < 300 && !placed; ++attempt) {
          const Vec2 c = clampv({u(rng) - 0.5, u(rng) - 0.5});
          const Vec2 w{tx + c.x, ty + c.y};
          placed = std::all_of(world.begin(), world.end(), [&](Vec2 q) {
            const double dx = torus(q.x - w.x), dy = torus(q.y - w.y);
            return std::sqrt(dx * dx + dy * dy) >= d;
          });
          if (placed) {
            sets[k].push_back(c);
            world.push_back(w);
          }
        }
        if (!placed) d *= 0.95;
      }
    }
    return sets;
  }
  for (auto& pts : sets) {
    if (kind == SeedKind::kJittered) {
      // m strata of a g x g grid, chosen at random, one jittered point each.
      const int g = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(m))));
      std::vector<int> cells(g * g);
      for (int i = 0; i < g * g; ++i) cells[i] = i;
      shuffle(cells.begin(), cells.end(), rng);
      for (int i = 0; i < m; ++i)
        pts.push_back(
            clampv({(cells[i] % g + u(rng)) / g - 0.5, (cells[i] / g + u(rng)) / g - 0.5}));
    } else {
      for (int i = 0; i < m; ++i) pts.push_back(clampv({u(rng) - 0.5, u(rng) - 0.5}));
    }
  }
  return sets;
}

std::vector<double> line_points(std::string_view kind, int n, uint64_t seed) {
  std::mt19937_64 rng(seed);
  const auto u = [](std::mt19937_64& r) { return unit_double(r); };
  std::vector<double> xs;
  if (kind == "jittered") {
    for (int i = 0; i < n; ++i) xs.push_back(i + u(rng));
  } else if (kind == "poisson") {
    // Dart throwing on [0, n) with minimum distance 0.6 (on the circle).
    std::set<double> placed;
    const double d = 0.6;
    while (static_cast<int>(placed.size()) < n) {
      const double x = u(rng) * n;
      auto hi = placed.lower_bound(x);
      auto dist = [&](double a) {
        const double t = std::abs(a - x);
        return std::min(t, n - t);
      };
      bool ok = true;
      if (hi != placed.end()) ok = ok && dist(*hi) >= d;
      if (hi != placed.begin()) ok = ok && dist(*std::prev(hi)) >= d;
      if (!placed.empty()) ok = ok && dist(*placed.begin()) >= d && dist(*placed.rbegin()) >= d;
      if (ok) placed.insert(x);
    }
    xs.assign(placed.begin(), placed.end());
  } else {
    throw ParameterError("1d", fmt::format(": '{}' is not poisson or jittered", kind));
  }
  return xs;
}

}  // namespace aapat

#include "aapat/optimize/problem.h"
#include "aapat/generate/portable_random.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <fmt/format.h>

namespace aapat {
namespace {

// Samples inside a pixel of a sharing footprint stay this far off the
// border, so that they never turn into shared samples (changing n).
constexpr double kBorderMargin = 1e-6;

bool near(double v, double target) {
  return std::abs(v - target) <= kSameSampleEps;
}

Generator generator_at(Vec2 pos, bool sharing) {
  const bool vx = near(std::abs(pos.x), 0.5), vy = near(std::abs(pos.y), 0.5);
  Generator g{pos, Freedom::kFree, 0.5};
  if (vx && vy)
    g.freedom = Freedom::kFixed;
  else if (vy)
    g.freedom = Freedom::kSlideX;  // on a horizontal border: moves along x
  else if (vx)
    g.freedom = Freedom::kSlideY;
  if (sharing || g.freedom != Freedom::kFree) g.limit = 0.5 - kBorderMargin;
  return g;
}

// Kernel reads from the set placements, in kernel_samples order.
void add_kernels(Problem& pr, bool share_weights) {
  const Pattern& p = pr.layout;
  for (int k = 0; k < p.set_count(); ++k) {
    std::vector<KernelRead> reads;
    std::vector<int> group;
    for (const KernelSample& s : kernel_samples(p, k)) {
      Placement place = pr.set_samples[s.set][s.index];
      const Vec2 base = place.at(pr.generators);  // the sample in its own pixel
      place.offset = place.offset + (s.pos - base);
      const int weight =
          share_weights ? static_cast<int>(reads.size()) : static_cast<int>(pr.weights.size());
      if (!share_weights || k == 0) {
        pr.weights.push_back(p.weights[k][reads.size()]);
        group.push_back(weight);
      }
      reads.push_back({place, weight});
    }
    if (!group.empty()) pr.weight_groups.push_back(group);
    pr.kernels.push_back(std::move(reads));
  }
}

}  // namespace

bool is_mirrored_tile(const Pattern& p) {
  if (p.tile_w != 2 || p.tile_h != 2 || p.footprint != Footprint{1, true}) return false;
  for (int k = 1; k < 4; ++k) {
    if (p.sets[k].size() != p.sets[0].size() || p.weights[k] != p.weights[0]) return false;
    const double sx = k & 1 ? -1 : 1, sy = k & 2 ? -1 : 1;
    for (size_t i = 0; i < p.sets[0].size(); ++i)
      if (!same_point(p.sets[k][i], {sx * p.sets[0][i].x, sy * p.sets[0][i].y})) return false;
  }
  return true;
}

Problem mirrored_problem(const Pattern& tile) {
  Problem pr;
  pr.layout = tile;
  for (const Vec2& s : tile.sets[0]) pr.generators.push_back(generator_at(s, true));
  for (int k = 0; k < 4; ++k) {
    std::vector<Placement> set;
    for (size_t i = 0; i < tile.sets[0].size(); ++i)
      set.push_back({static_cast<int>(i), k & 1 ? -1.0 : 1.0, k & 2 ? -1.0 : 1.0, {0, 0}});
    pr.set_samples.push_back(std::move(set));
  }
  add_kernels(pr, true);
  return pr;
}

Problem problem_from_pattern(const Pattern& p) {
  validate(
      p);  // a pattern built in code, weights and sets of different sizes: an Error, not a crash
  if (is_mirrored_tile(p)) return mirrored_problem(p);
  Problem pr;
  pr.layout = p;
  // One generator per physical sample: the orbit of its tile position.
  std::map<std::pair<long long, long long>, int> orbit_generator;
  for (int k = 0; k < p.set_count(); ++k) {
    std::vector<Placement> set;
    for (const Vec2& s : p.sets[k]) {
      auto [it, inserted] =
          orbit_generator.try_emplace(sample_key(p, k, s), static_cast<int>(pr.generators.size()));
      if (inserted) pr.generators.push_back(generator_at(s, p.footprint.plus));
      set.push_back({it->second, 1, 1, s - pr.generators[it->second].pos});
    }
    pr.set_samples.push_back(std::move(set));
  }
  add_kernels(pr, false);
  return pr;
}

Pattern pattern_of(const Problem& pr) {
  Pattern p = pr.layout;
  for (size_t k = 0; k < pr.set_samples.size(); ++k)
    for (size_t i = 0; i < pr.set_samples[k].size(); ++i)
      p.sets[k][i] = pr.set_samples[k][i].at(pr.generators);
  for (size_t k = 0; k < pr.kernels.size(); ++k)
    for (size_t i = 0; i < pr.kernels[k].size(); ++i)
      p.weights[k][i] = pr.weights[pr.kernels[k][i].weight];
  return p;
}

void lock_samples(Problem& pr, const std::vector<int>& set0_samples) {
  for (int i : set0_samples) {
    if (i < 0 || i >= static_cast<int>(pr.set_samples[0].size()))
      throw ParameterError(
          "lock", fmt::format(": sample {} does not exist: the base pixel has samples 0..{}", i,
                              pr.set_samples[0].size() - 1));
    pr.generators[pr.set_samples[0][i].generator].freedom = Freedom::kFixed;
  }
}

Problem perturbed(const Problem& problem, double amount, std::mt19937_64& rng) {
  const auto u = [amount](std::mt19937_64& r) { return uniform_real(r, -amount, amount); };
  Problem p = problem;
  for (Generator& g : p.generators) {
    if (g.freedom == Freedom::kFree || g.freedom == Freedom::kSlideX) g.pos.x += u(rng);
    if (g.freedom == Freedom::kFree || g.freedom == Freedom::kSlideY) g.pos.y += u(rng);
  }
  project_to_constraints(p, false);
  return p;
}

void keep_strictly_inside(Problem& pr, double margin) {
  if (pr.layout.footprint.plus) return;
  for (Generator& g : pr.generators)
    if (g.freedom == Freedom::kFree) g.limit = std::min(g.limit, 0.5 - margin);
  for (Generator& g : pr.generators) {
    if (g.freedom != Freedom::kFree) continue;
    g.pos.x = std::clamp(g.pos.x, -g.limit, g.limit);
    g.pos.y = std::clamp(g.pos.y, -g.limit, g.limit);
  }
}

void project_to_constraints(Problem& pr, bool nonnegative) {
  for (Generator& g : pr.generators) {
    if (g.freedom == Freedom::kFree || g.freedom == Freedom::kSlideX)
      g.pos.x = std::clamp(g.pos.x, -g.limit, g.limit);
    if (g.freedom == Freedom::kFree || g.freedom == Freedom::kSlideY)
      g.pos.y = std::clamp(g.pos.y, -g.limit, g.limit);
  }
  for (const auto& group : pr.weight_groups) {
    double sum = 0;
    for (int i : group) {
      if (nonnegative) pr.weights[i] = std::max(0.0, pr.weights[i]);
      sum += pr.weights[i];
    }
    if (std::abs(sum) < 1e-12) {
      for (int i : group) pr.weights[i] = 1.0 / group.size();
    } else {
      for (int i : group) pr.weights[i] /= sum;
    }
  }
}

}  // namespace aapat

#include "aapat/core/pattern_edit.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string_view>

#include "aapat/core/geometry.h"

namespace aapat {
namespace {

// Clamped to the closed pixel; within kBorderSnap of a border, on it.
double placed(double v) {
  v = std::clamp(v, -0.5, 0.5);
  if (0.5 - v <= kBorderSnap) return 0.5;
  if (v + 0.5 <= kBorderSnap) return -0.5;
  return v;
}

bool has_border_sample(const Pattern& p) {
  for (const auto& set : p.sets)
    for (const Vec2& s : set)
      if (on_border(s)) return true;
  return false;
}

// Which samples every kernel reads, by set and index.
bool same_reads(const Pattern& a, const Pattern& b) {
  if (a.footprint != b.footprint || a.set_count() != b.set_count()) return false;
  for (int k = 0; k < a.set_count(); ++k) {
    const auto ra = kernel_samples(a, k), rb = kernel_samples(b, k);
    if (ra.size() != rb.size()) return false;
    for (size_t i = 0; i < ra.size(); ++i)
      if (ra[i].set != rb[i].set || ra[i].index != rb[i].index) return false;
  }
  return true;
}

void check_kernel_index(const Pattern& p, int kernel, int index) {
  if (kernel < 0 || kernel >= p.set_count())
    throw Error(fmt::format("kernel {} does not exist: the pattern has {} kernels (0 to {})",
                            kernel, p.set_count(), p.set_count() - 1));
  const int n = static_cast<int>(p.weights[kernel].size());
  if (index < 0 || index >= n)
    throw Error(
        fmt::format("weight {} of kernel {} does not exist: it has {} weights", index, kernel, n));
}

// An edited pattern is no longer what its name and provenance say: it is
// named "NAME-edited" and remembers only where it came from.
void mark_edited(Pattern& q, const Pattern& original) {
  constexpr std::string_view kSuffix = "-edited";
  const bool already = q.name.size() >= kSuffix.size() &&
                       q.name.compare(q.name.size() - kSuffix.size(), kSuffix.size(), kSuffix) == 0;
  if (already) return;
  q.name = original.name.empty() ? "edited" : original.name + std::string(kSuffix);
  q.description = original.name.empty() ? "edited by hand" : "edited by hand from " + original.name;
  q.provenance = {{"edited-from", original.name}};
}

// Lists the border sample `v` of set `set` in every neighbour whose closed
// square holds it (in a 1x1 tile the pixel is its own neighbour).
void share(Pattern& q, int set, Vec2 v) {
  const int tx = set % q.tile_w, ty = set / q.tile_w;
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      const Vec2 local{v.x - dx, v.y - dy};
      if ((dx == 0 && dy == 0) || std::abs(local.x) > 0.5 + kSameSampleEps ||
          std::abs(local.y) > 0.5 + kSameSampleEps)
        continue;
      const int s = set_index(q, tx + dx, ty + dy);
      const Vec2 exact{std::clamp(local.x, -0.5, 0.5), std::clamp(local.y, -0.5, 0.5)};
      const bool listed = std::any_of(q.sets[s].begin(), q.sets[s].end(),
                                      [&](Vec2 w) { return same_point(w, exact); });
      if (!listed) q.sets[s].push_back(exact);
    }
  }
}

}  // namespace

Pattern move_sample(const Pattern& p, int set, int index, Vec2 to, int lattice) {
  if (set < 0 || set >= p.set_count())
    throw Error(fmt::format("set {} does not exist: the pattern has {} sets (0 to {})", set,
                            p.set_count(), p.set_count() - 1));
  if (index < 0 || index >= static_cast<int>(p.sets[set].size()))
    throw Error(fmt::format("sample {} of set {} does not exist: it has {} samples", index, set,
                            p.sets[set].size()));
  if (!std::isfinite(to.x) || !std::isfinite(to.y))
    throw Error(fmt::format("position ({}, {}) is not a pair of finite numbers", to.x, to.y));
  if (lattice < 0 || lattice > 4096)
    throw Error(fmt::format("lattice: {} steps is out of range 0..4096", lattice));
  if (lattice > 0)
    to = {std::round(to.x * lattice) / lattice, std::round(to.y * lattice) / lattice};
  to = {placed(to.x), placed(to.y)};
  const auto moved = sample_key(p, set, p.sets[set][index]);

  // Every copy of the moved sample goes; the dragged one is replaced in place.
  Pattern q = p;
  for (int k = 0; k < p.set_count(); ++k) {
    std::vector<Vec2> kept;
    for (int i = 0; i < static_cast<int>(p.sets[k].size()); ++i) {
      if (k == set && i == index)
        kept.push_back(to);
      else if (sample_key(p, k, p.sets[k][i]) != moved)
        kept.push_back(p.sets[k][i]);
    }
    q.sets[k] = std::move(kept);
  }

  // On a border it is shared: every neighbour whose closed square holds it
  // lists it. A footprint that gains its '+' shares the samples already on
  // borders too (a plain pattern may keep samples on its closed pixel).
  const bool on_edge = on_border(to);
  if (on_edge) {
    if (!q.footprint.plus) {
      q.footprint.plus = true;
      for (int k = 0; k < q.set_count(); ++k) {
        const std::vector<Vec2> own = q.sets[k];
        for (const Vec2& v : own)
          if (on_border(v)) share(q, k, v);
      }
    }
    share(q, set, to);
  } else if (!has_border_sample(q)) {
    q.footprint.plus = false;  // nothing left to share
  }

  if (!same_reads(p, q)) {
    for (int k = 0; k < q.set_count(); ++k) {
      const size_t reads = kernel_samples(q, k).size();
      q.weights[k].assign(reads, 1.0 / static_cast<double>(reads));
    }
  }
  mark_edited(q, p);
  validate(q);
  return q;
}

Pattern set_weight(const Pattern& p, int kernel, int index, double value) {
  check_kernel_index(p, kernel, index);
  if (!std::isfinite(value))
    throw Error(
        fmt::format("weight {} of kernel {}: {} is not a finite number", index, kernel, value));
  if (std::abs(value) > kMaxWeightMagnitude)
    throw Error(fmt::format("weight {} of kernel {}: {} exceeds the limit of ±{}", index, kernel,
                            value, kMaxWeightMagnitude));
  Pattern q = p;
  std::vector<double>& w = q.weights[kernel];
  if (w.size() == 1) {
    if (value != 1) throw Error(fmt::format("kernel {} reads one sample: its weight is 1", kernel));
    return p;
  }
  double others = 0;
  for (size_t i = 0; i < w.size(); ++i)
    if (static_cast<int>(i) != index) others += w[i];
  for (size_t i = 0; i < w.size(); ++i) {
    if (static_cast<int>(i) == index) continue;
    w[i] = std::abs(others) > 1e-12 ? w[i] * (1 - value) / others
                                    : (1 - value) / static_cast<double>(w.size() - 1);
  }
  w[index] = value;
  mark_edited(q, p);
  validate(q);
  return q;
}

}  // namespace aapat

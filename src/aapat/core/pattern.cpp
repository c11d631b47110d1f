#include "aapat/core/pattern.h"

#include <fmt/format.h>

#include <cmath>
#include <set>

namespace aapat {
namespace {

constexpr double kWeightSumTolerance = 1e-6;

bool on(double v, double target) {
  return std::abs(v - target) <= kSameSampleEps;
}

// The first and last pixel offset of a footprint relative to the kernel's
// pixel, and where its output point sits relative to that pixel's centre.
int first_offset(const Footprint& f) {
  return f.size == 1 ? 0 : 1 - f.size / 2;
}
double output_offset(const Footprint& f) {
  return f.size == 1 ? 0.0 : 0.5;
}

std::string direction(int dx, int dy) {
  const char* v = dy > 0 ? "top" : dy < 0 ? "bottom" : "";
  const char* h = dx > 0 ? "right" : dx < 0 ? "left" : "";
  if (dx != 0 && dy != 0) return fmt::format("{}-{} corner", v, h);
  return fmt::format("{} edge", dx != 0 ? h : v);
}

}  // namespace

bool on_border(Vec2 v) {
  return on(std::abs(v.x), 0.5) || on(std::abs(v.y), 0.5);
}

std::string Footprint::text() const {
  const std::string base = size == 1 ? "1" : fmt::format("{}x{}", size, size);
  return plus ? base + "+" : base;
}

Footprint parse_footprint(std::string_view text) {
  Footprint f;
  f.plus = text.ends_with('+');
  const std::string_view base = f.plus ? text.substr(0, text.size() - 1) : text;
  if (base == "1")
    f.size = 1;
  else if (base == "2x2" || base == "4")
    f.size = 2;
  else if (base == "4x4" || base == "16")
    f.size = 4;
  else
    throw Error(fmt::format(
        "footprint: '{}' is not one of 1, 1+, 2x2, 2x2+, 4x4, 4x4+ (or r = 4, 16 with optional +)",
        text));
  return f;
}

std::vector<KernelSample> kernel_samples(const Pattern& p, int kernel) {
  const Footprint& f = p.footprint;
  const int kx = kernel % p.tile_w, ky = kernel / p.tile_w;
  std::vector<KernelSample> out;
  if (f.size == 1) {
    const auto& set = p.sets[kernel];
    for (int i = 0; i < static_cast<int>(set.size()); ++i) out.push_back({set[i], kernel, i});
    return out;
  }
  const int first = first_offset(f);
  const double o = output_offset(f);
  // Only a sample on its pixel's border can be met twice: compare those alone.
  std::vector<Vec2> border;
  for (int j = first; j < first + f.size; ++j) {
    for (int i = first; i < first + f.size; ++i) {
      const int s = set_index(p, kx + i, ky + j);
      const auto& set = p.sets[s];
      for (int n = 0; n < static_cast<int>(set.size()); ++n) {
        const Vec2 pos{i + set[n].x - o, j + set[n].y - o};
        if (on_border(set[n])) {
          bool seen = false;
          for (const Vec2& b : border) seen = seen || same_point(b, pos);
          if (seen) continue;
          border.push_back(pos);
        }
        out.push_back({pos, s, n});
      }
    }
  }
  return out;
}

Kernel make_kernel(const std::vector<Vec2>& positions, const std::vector<double>& weights) {
  Kernel k;
  double sum = 0;
  for (double w : weights) sum += w;
  for (size_t i = 0; i < positions.size(); ++i) {
    k.x.push_back(positions[i].x);
    k.y.push_back(positions[i].y);
    k.w.push_back(weights[i] / sum);
  }
  return k;
}

Kernel make_kernel(const Pattern& p, int kernel) {
  std::vector<Vec2> positions;
  for (const auto& s : kernel_samples(p, kernel)) positions.push_back(s.pos);
  return make_kernel(positions, p.weights[kernel]);
}

int set_index(const Pattern& p, int x, int y) {
  const int tx = ((x % p.tile_w) + p.tile_w) % p.tile_w,
            ty = ((y % p.tile_h) + p.tile_h) % p.tile_h;
  return ty * p.tile_w + tx;
}

std::pair<long long, long long> sample_key(const Pattern& p, int set, Vec2 s) {
  auto reduce = [](double v, int period) {
    const long long m = static_cast<long long>(period) * 10'000'000LL;
    return ((std::llround(v * 1e7) % m) + m) % m;
  };
  return {reduce(set % p.tile_w + s.x, p.tile_w), reduce(set / p.tile_w + s.y, p.tile_h)};
}

double samples_per_pixel(const Pattern& p) {
  // Count the orbits of the samples under the tile's translations.
  std::set<std::pair<long long, long long>> unique;
  for (int k = 0; k < p.set_count(); ++k)
    for (const Vec2& s : p.sets[k]) unique.insert(sample_key(p, k, s));
  return static_cast<double>(unique.size()) / p.set_count();
}

std::string format_cost(double n) {
  return fmt::format("{}", std::round(n * 1e6) / 1e6);
}

std::string family(const Pattern& p) {
  return fmt::format("P({},{}{},{})", p.set_count(), p.footprint.pixels(),
                     p.footprint.plus ? "+" : "", format_cost(samples_per_pixel(p)));
}

std::string site_name(Vec2 p) {
  const char* v = on(p.y, 0.5) ? "top" : on(p.y, -0.5) ? "bottom" : nullptr;
  const char* h = on(p.x, 0.5) ? "right" : on(p.x, -0.5) ? "left" : nullptr;
  if (v && h) return fmt::format("{}-{}", v, h);
  if (v) return v;
  if (h) return h;
  return "inside";
}

void validate(const Pattern& p) {
  if (p.name.empty()) throw Error("name: empty: a pattern needs a name");
  if (p.tile_w < 1 || p.tile_h < 1 || p.tile_w > kMaxTileSide || p.tile_h > kMaxTileSide)
    throw Error(fmt::format("tile: {}x{} is not a tile size: each side must be 1 to {} pixels",
                            p.tile_w, p.tile_h, kMaxTileSide));
  if (static_cast<int>(p.sets.size()) != p.set_count())
    throw Error(fmt::format("sets: a {}x{} tile needs {} sets, got {}", p.tile_w, p.tile_h,
                            p.set_count(), p.sets.size()));
  size_t total = 0;
  for (const auto& set : p.sets) total += set.size();
  if (total > kMaxPatternSamples)
    throw Error(fmt::format("sets: {} samples in all exceed the limit of {} per pattern", total,
                            kMaxPatternSamples));
  for (size_t k = 0; k < p.sets.size(); ++k) {
    const auto& set = p.sets[k];
    if (set.empty())
      throw Error(fmt::format("sets[{}]: empty: every pixel needs at least one sample", k));
    if (set.size() > kMaxSamplesPerSet)
      throw Error(fmt::format("sets[{}]: {} samples exceed the limit of {} per pixel", k,
                              set.size(), kMaxSamplesPerSet));
    for (size_t i = 0; i < set.size(); ++i) {
      const Vec2 s = set[i];
      if (!std::isfinite(s.x))
        throw Error(fmt::format("sets[{}][{}]: x is not a finite number", k, i));
      if (!std::isfinite(s.y))
        throw Error(fmt::format("sets[{}][{}]: y is not a finite number", k, i));
      if (std::abs(s.x) > 0.5 + kSameSampleEps || std::abs(s.y) > 0.5 + kSameSampleEps)
        throw Error(fmt::format(
            "sets[{}][{}]: ({:.6g}, {:.6g}) lies outside the pixel [-0.5, 0.5] x [-0.5, 0.5]", k, i,
            s.x, s.y));
      for (size_t j = 0; j < i; ++j)
        if (same_point(set[j], s))
          throw Error(fmt::format("sets[{}][{}]: same position as sets[{}][{}] ({:.6g}, {:.6g})", k,
                                  i, k, j, s.x, s.y));
    }
  }
  if (p.footprint.plus) {
    // A border sample is one physical sample: every pixel touching it lists it.
    for (int k = 0; k < p.set_count(); ++k) {
      const int tx = k % p.tile_w, ty = k / p.tile_w;
      for (size_t i = 0; i < p.sets[k].size(); ++i) {
        const Vec2 s = p.sets[k][i];
        const int sx = on(s.x, 0.5) ? 1 : on(s.x, -0.5) ? -1 : 0;
        const int sy = on(s.y, 0.5) ? 1 : on(s.y, -0.5) ? -1 : 0;
        std::vector<std::pair<int, int>> neighbours;
        if (sx != 0) neighbours.emplace_back(sx, 0);
        if (sy != 0) neighbours.emplace_back(0, sy);
        if (sx != 0 && sy != 0) neighbours.emplace_back(sx, sy);
        for (const auto& [dx, dy] : neighbours) {
          const int n = set_index(p, tx + dx, ty + dy);
          const Vec2 there{s.x - dx, s.y - dy};
          bool found = false;
          for (const Vec2& q : p.sets[n]) found = found || same_point(q, there);
          if (!found)
            throw Error(fmt::format(
                "sets[{}][{}]: border sample ({:.6g}, {:.6g}) is not shared: set {}, across the "
                "{}, has no sample at ({:.6g}, {:.6g})",
                k, i, s.x, s.y, n, direction(dx, dy), there.x, there.y));
        }
      }
    }
  }
  if (static_cast<int>(p.weights.size()) != p.set_count())
    throw Error(fmt::format("kernels: a {}x{} tile has {} kernels (one per pixel), got {}",
                            p.tile_w, p.tile_h, p.set_count(), p.weights.size()));
  for (int k = 0; k < p.set_count(); ++k) {
    const auto& w = p.weights[k];
    const size_t reads = kernel_samples(p, k).size();
    if (w.size() != reads)
      throw Error(fmt::format("kernels[{}]: the kernel reads {} samples but has {} weights", k,
                              reads, w.size()));
    double sum = 0;
    for (size_t i = 0; i < w.size(); ++i) {
      if (!std::isfinite(w[i]))
        throw Error(fmt::format("kernels[{}][{}]: weight is not a finite number", k, i));
      if (std::abs(w[i]) > kMaxWeightMagnitude)
        throw Error(fmt::format("kernels[{}][{}]: weight {} is out of range [-{}, {}]", k, i, w[i],
                                kMaxWeightMagnitude, kMaxWeightMagnitude));
      sum += w[i];
    }
    if (std::abs(sum - 1.0) > kWeightSumTolerance)
      throw Error(fmt::format("kernels[{}]: weights sum to {:.9g} instead of 1 (tolerance {})", k,
                              sum, kWeightSumTolerance));
  }
}

Pattern single_pixel_pattern(std::string name, std::vector<Vec2> samples,
                             std::vector<double> weights, Footprint footprint) {
  Pattern p;
  p.name = std::move(name);
  p.footprint = footprint;
  p.sets = {std::move(samples)};
  p.weights = {std::move(weights)};
  return p;
}

Pattern mirrored_tile_pattern(std::string name, std::vector<Vec2> base,
                              std::vector<double> weights) {
  Pattern p;
  p.name = std::move(name);
  p.tile_w = p.tile_h = 2;
  p.footprint = {1, true};
  for (int ty = 0; ty < 2; ++ty) {
    for (int tx = 0; tx < 2; ++tx) {
      std::vector<Vec2> set;
      for (Vec2 s : base) set.push_back({tx ? -s.x : s.x, ty ? -s.y : s.y});
      p.sets.push_back(set);
      p.weights.push_back(weights);
    }
  }
  return p;
}

}  // namespace aapat

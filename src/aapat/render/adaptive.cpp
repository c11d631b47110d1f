#include "aapat/render/adaptive.h"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "aapat/core/interrupt.h"
#include "aapat/generate/point_generators.h"
#include "aapat/render/color_render.h"
#include "aapat/render/surface.h"

namespace aapat {
namespace {

// A sample's value: a grey scene's in value[0], a colour scene's in all
// three (the criteria then judge each channel, refining where any one asks).
struct Taken {
  double x, y;
  Rgb value;
  int primitive;
};

// A sample in the pixel's estimate: its square's area over the square's samples.
struct Weighted {
  double x, y;
  Rgb value;
  double weight;
};

Rgb value_at(const Scene& scene, Vec2 p, bool colour) {
  return colour ? shade_colour(scene, p) : Rgb{shade(scene, p), 0, 0};
}

// splitmix64: the refinement's positions from (seed, pixel, square, index)
// alone, so any order of pixels and any thread count draws the same.
uint64_t mix(uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}
double uniform(uint64_t key) {
  return static_cast<double>(mix(key) >> 11) * 0x1.0p-53;
}

struct Square {
  double x0, y0, size;  // lower-left corner and side, in pixels
  int depth;
  int64_t cx, cy;  // the square's place on its depth's grid (for the random keys)
};

class Refiner {
 public:
  Refiner(const Scene& scene, const AdaptiveSettings& s)
      : scene_(scene),
        s_(s),
        textured_(has_texture(scene)),
        colour_(is_colour(scene)),
        channels_(colour_ ? 3 : 1) {}

  // Refines pixel (a, b) from its first samples; `neighbours` holds the
  // first samples of its 3 x 3 neighbourhood (itself included).
  void pixel(int a, int b, std::vector<Taken> first, double neighbourhood_contrast,
             std::vector<Weighted>& out, int& evaluations) const {
    out.clear();
    total_ = static_cast<int>(first.size());
    a_ = a;
    b_ = b;
    evaluations_ = 0;
    const Square root{a - 0.5, b - 0.5, 1.0, 0, 0, 0};
    const bool refine = s_.criterion == RefinementCriterion::neighbours
                            ? neighbourhood_contrast > s_.threshold
                            : disagree(first);
    square(root, std::move(first), refine, out);
    evaluations = evaluations_;
  }

 private:
  bool disagree(const std::vector<Taken>& samples) const {
    if (samples.size() < 2) return false;
    if (s_.criterion == RefinementCriterion::primitive)
      for (const Taken& t : samples)
        if (t.primitive != samples[0].primitive) return true;
    for (size_t c = 0; c < channels_; ++c)
      if (channel_disagrees(samples, c)) return true;
    return false;
  }

  bool channel_disagrees(const std::vector<Taken>& samples, size_t c) const {
    double lo = samples[0].value[c], hi = lo, sum = 0, sum_sq = 0;
    for (const Taken& t : samples) {
      lo = std::min(lo, t.value[c]);
      hi = std::max(hi, t.value[c]);
      sum += t.value[c];
      sum_sq += t.value[c] * t.value[c];
    }
    const double n = static_cast<double>(samples.size());
    switch (s_.criterion) {
      case RefinementCriterion::variance:
        return std::max(0.0, (sum_sq - sum * sum / n) / (n - 1)) > s_.threshold;
      case RefinementCriterion::primitive:
        // One primitive (checked above); on a textured one, texture regions
        // that differ by more than the threshold.
        return textured_ && hi - lo > s_.threshold;
      case RefinementCriterion::contrast:
      case RefinementCriterion::neighbours:  // inside the pixel: contrast
        return hi - lo > s_.threshold;
    }
    return false;
  }

  Taken take(double x, double y) const {
    ++evaluations_;
    const Vec2 p{x, y};
    return {x, y, value_at(scene_, p, colour_),
            s_.criterion == RefinementCriterion::primitive ? primitive_at(scene_, p) : 0};
  }

  void leaf(const Square& q, const std::vector<Taken>& samples, std::vector<Weighted>& out) const {
    const double weight = q.size * q.size / static_cast<double>(samples.size());
    for (const Taken& t : samples) out.push_back({t.x, t.y, t.value, weight});
  }

  void square(const Square& q, std::vector<Taken> samples, bool refine,
              std::vector<Weighted>& out) const {
    if (!refine || q.depth >= s_.max_depth) return leaf(q, samples, out);
    const double half = q.size / 2, mid_x = q.x0 + half, mid_y = q.y0 + half;
    std::vector<Taken> child[4];
    for (const Taken& t : samples)
      child[(t.x >= mid_x ? 1 : 0) + (t.y >= mid_y ? 2 : 0)].push_back(t);
    int needed = 0;
    for (const auto& c : child) needed += std::max(0, s_.per_square - static_cast<int>(c.size()));
    if (total_ + needed > s_.max_samples) return leaf(q, samples, out);  // the budget is spent
    total_ += needed;
    for (int k = 0; k < 4; ++k) {
      const Square c{q.x0 + (k & 1) * half, q.y0 + (k >> 1) * half, half,
                     q.depth + 1,           2 * q.cx + (k & 1),     2 * q.cy + (k >> 1)};
      for (int n = static_cast<int>(child[k].size()), i = 0; n < s_.per_square; ++n, ++i) {
        // Jittered in the square, keyed by everything that names this sample.
        uint64_t key =
            mix(s_.initial.seed) ^ mix(static_cast<uint64_t>(a_) * 0x9e3779b97f4a7c15ull);
        key = mix(key ^ static_cast<uint64_t>(b_)) ^
              mix(static_cast<uint64_t>(c.depth) << 48 ^ static_cast<uint64_t>(c.cx) << 24 ^
                  static_cast<uint64_t>(c.cy));
        key = mix(key + static_cast<uint64_t>(i));
        child[k].push_back(
            take(c.x0 + uniform(key) * half, c.y0 + uniform(key ^ 0x5bd1e995) * half));
      }
      const bool again = disagree(child[k]);
      square(c, std::move(child[k]), again, out);
    }
  }

  const Scene& scene_;
  const AdaptiveSettings& s_;
  bool textured_, colour_;
  size_t channels_;
  // Per pixel (a Refiner is used by one thread at a time).
  mutable int total_ = 0, a_ = 0, b_ = 0, evaluations_ = 0;
};

}  // namespace

RefinementCriterion parse_refinement_criterion(std::string_view text) {
  if (text == "contrast") return RefinementCriterion::contrast;
  if (text == "variance") return RefinementCriterion::variance;
  if (text == "neighbours" || text == "neighbors") return RefinementCriterion::neighbours;
  if (text == "primitive" || text == "shape-id") return RefinementCriterion::primitive;
  throw ParameterError("adaptive", fmt::format(" '{}': use contrast, variance, neighbours or "
                                               "primitive (shape-id)",
                                               text));
}

std::string_view refinement_criterion_name(RefinementCriterion criterion) {
  switch (criterion) {
    case RefinementCriterion::contrast:
      return "contrast";
    case RefinementCriterion::variance:
      return "variance";
    case RefinementCriterion::neighbours:
      return "neighbours";
    case RefinementCriterion::primitive:
      return "primitive";
  }
  return "contrast";
}

void validate(const AdaptiveSettings& s) {
  const int first = s.initial.pattern ? static_cast<int>(s.initial.pattern->sets.front().size())
                                      : s.initial.samples;
  if (s.initial.pattern && s.initial.pattern->footprint.plus)
    throw ParameterError("adaptive",
                         ": the initial pattern shares samples between pixels; give "
                         "one whose samples each belong to one pixel");
  if (first < 1 || first > 5)
    throw ParameterError("adaptive", fmt::format(": the initial phase takes 1 to 5 samples per "
                                                 "pixel, not {}",
                                                 first));
  const double top = s.criterion == RefinementCriterion::variance ? 0.25 : 1.0;
  if (!(s.threshold >= 0 && s.threshold <= top))
    throw ParameterError("threshold",
                         fmt::format(" {}: expected a number in [0, {}]", s.threshold, top));
  if (s.max_depth < 1 || s.max_depth > 8)
    throw ParameterError("max-depth", fmt::format(" {}: expected 1 to 8", s.max_depth));
  if (s.per_square < 1 || s.per_square > 16)
    throw ParameterError("per-square", fmt::format(" {}: expected 1 to 16", s.per_square));
  if (s.max_samples < first || s.max_samples > 4096)
    throw ParameterError(
        "max-samples",
        fmt::format(" {}: expected {} (the initial samples) to 4096", s.max_samples, first));
}

AdaptiveImage render_adaptive(const Scene& scene, int width, int height, const AdaptiveSettings& s,
                              const std::optional<Filter>& filter) {
  validate(s);
  if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide)
    throw ParameterError(
        "size", fmt::format(": {}x{} is out of range 1..{}", width, height, kMaxImageSide));
  // The pixels a filter reaches beyond the image are refined too.
  const int m = filter ? static_cast<int>(std::ceil(filter->radius())) : 0;
  const int rw = width + 2 * m, rh = height + 2 * m;
  auto index = [&](int a, int b) { return static_cast<size_t>(b + m) * rw + (a + m); };
  const PointGenerator generator =
      s.initial.pattern ? PointGenerator{} : make_point_generator(s.initial.generator);
  const bool colour = is_colour(scene);
  const auto nc = static_cast<size_t>(scene_channels(scene));

  // Phase 1: every pixel's first samples.
  std::vector<std::vector<Taken>> first(static_cast<size_t>(rw) * rh);
  tbb::parallel_for(-m, height + m, [&](int b) {
    throw_if_interrupted();
    for (int a = -m; a < width + m; ++a) {
      std::vector<Vec2> at;
      if (s.initial.pattern) {
        const Pattern& p = *s.initial.pattern;
        at = p.sets[set_index(p, a, b)];
      } else {
        at = pixel_points(generator, s.initial.samples, s.initial.seed, a, b);
      }
      auto& out = first[index(a, b)];
      for (const Vec2& v : at) {
        const Vec2 q{a + v.x, b + v.y};
        out.push_back({q.x, q.y, value_at(scene, q, colour),
                       s.criterion == RefinementCriterion::primitive ? primitive_at(scene, q) : 0});
      }
    }
  });

  // Phase 2: refinement, every first sample kept.
  std::vector<std::vector<Weighted>> kept(first.size());
  std::vector<int> evaluations(first.size());
  tbb::parallel_for(-m, height + m, [&](int b) {
    throw_if_interrupted();
    const Refiner refiner(scene, s);
    for (int a = -m; a < width + m; ++a) {
      double contrast = 0;  // the largest channel's
      for (size_t c = 0; c < nc; ++c) {
        double lo = INFINITY, hi = -INFINITY;
        for (int db = -1; db <= 1; ++db)
          for (int da = -1; da <= 1; ++da) {
            if (a + da < -m || a + da >= width + m || b + db < -m || b + db >= height + m) continue;
            for (const Taken& t : first[index(a + da, b + db)])
              lo = std::min(lo, t.value[c]), hi = std::max(hi, t.value[c]);
          }
        contrast = c == 0 ? hi - lo : std::max(contrast, hi - lo);
      }
      int made = 0;
      refiner.pixel(a, b, first[index(a, b)], contrast, kept[index(a, b)], made);
      evaluations[index(a, b)] = made + static_cast<int>(first[index(a, b)].size());
    }
  });

  // Phase 3: reconstruction.
  AdaptiveImage r;
  r.image = Image{width, height, 0.0, std::vector<double>(static_cast<size_t>(width) * height * nc),
                  static_cast<int>(nc)};
  r.samples.resize(static_cast<size_t>(width) * height);
  tbb::parallel_for(0, height, [&](int j) {
    for (int i = 0; i < width; ++i) {
      Rgb sum{0, 0, 0};
      double weight = 0;
      if (!filter) {
        for (const Weighted& w : kept[index(i, j)]) {
          for (size_t c = 0; c < nc; ++c) sum[c] += w.weight * w.value[c];
          weight += w.weight;
        }
      } else {
        for (int b = j - m; b <= j + m; ++b)
          for (int a = i - m; a <= i + m; ++a)
            for (const Weighted& w : kept[index(a, b)]) {
              const double h = filter->value(w.x - i) * filter->value(w.y - j) * w.weight;
              for (size_t c = 0; c < nc; ++c) sum[c] += h * w.value[c];
              weight += h;
            }
      }
      for (size_t c = 0; c < nc; ++c)
        r.image.values[(static_cast<size_t>(j) * width + i) * nc + c] =
            weight != 0 ? sum[c] / weight : 0.0;
      r.samples[static_cast<size_t>(j) * width + i] = static_cast<int>(kept[index(i, j)].size());
    }
  });
  size_t refined = 0;
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      r.evaluations += static_cast<uint64_t>(evaluations[index(i, j)]);
      r.average_samples += r.samples[static_cast<size_t>(j) * width + i];
      refined += kept[index(i, j)].size() > first[index(i, j)].size();
    }
  r.average_samples /= double(width) * height;
  r.refined_fraction = double(refined) / (double(width) * height);
  return r;
}

}  // namespace aapat

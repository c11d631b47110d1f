#include "aapat/render/renderer.h"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>

#include "aapat/core/interrupt.h"
#include "aapat/generate/point_generators.h"
#include "aapat/render/color_render.h"
#include "aapat/render/pixel_point_table.h"
#include "aapat/render/pixel_splat.h"
#include "aapat/render/surface.h"

namespace aapat {
namespace {

// A sample's value: a grey scene's in value[0], a colour scene's in all three.
struct Sample {
  double x, y;
  Rgb value;
};

// What rendering counted: texture lookups and shading evaluations.
struct Counts {
  std::atomic<uint64_t> lookups{0}, shadings{0};
};

// The samples pixel (a, b) owns and their values under the sampling's
// shading. A shared border sample belongs to the pixel that lists it at -1/2.
class PixelSampler {
 public:
  PixelSampler(const Scene& scene, const Sampling& s)
      : scene_(scene),
        s_(s),
        generator_(s.pattern ? PointGenerator{} : make_point_generator(s.generator)),
        footprint_(1 / std::sqrt(s.pattern ? samples_per_pixel(*s.pattern) : double(s.samples))),
        plain_(s.shading.exact() && !has_texture(scene)),
        colour_(is_colour(scene)) {}

  // A generator's points for the pixels [x0, x1) x [y0, y1), drawn once for
  // every render that shares them (render/pixel_point_table.h).
  void share_points(int x0, int y0, int x1, int y1) {
    if (!s_.pattern)
      table_ = shared_pixel_points(s_.generator, s_.samples, s_.seed, x0, y0, x1, y1);
  }

  // `counts`, when given, gains the lookups and shadings (callers count each
  // image pixel once, though blocks draw their neighbours' samples too).
  void pixel(int a, int b, std::vector<Sample>& out, Counts* counts) const {
    out.clear();
    if (s_.pattern) {
      const Pattern& p = *s_.pattern;
      for (const Vec2& v : p.sets[set_index(p, a, b)]) {
        if (p.footprint.plus && (v.x > 0.5 - kSameSampleEps || v.y > 0.5 - kSameSampleEps))
          continue;
        out.push_back({a + v.x, b + v.y, {}});
      }
    } else if (table_ && table_->covers(a, b)) {
      for (const Vec2& v : table_->points(a, b)) out.push_back({a + v.x, b + v.y, {}});
    } else {
      for (const Vec2& v : pixel_points(generator_, s_.samples, s_.seed, a, b))
        out.push_back({a + v.x, b + v.y, {}});
    }
    const Shading& sh = s_.shading;
    if (plain_ && !colour_) {  // no texture to look up: the scene's grey at every sample
      thread_local std::vector<Vec2> points;
      thread_local std::vector<double> greys;
      points.resize(out.size());
      greys.resize(out.size());
      for (size_t k = 0; k < out.size(); ++k) points[k] = {out[k].x, out[k].y};
      shade_points(scene_, points.data(), points.size(), greys.data());
      for (size_t k = 0; k < out.size(); ++k) out[k].value = {greys[k], 0, 0};
      if (counts) counts->shadings += out.size();
      return;
    }
    if (plain_) {  // no texture to look up: the scene's colour at every sample
      for (Sample& smp : out) smp.value = value({smp.x, smp.y});
      if (counts) counts->shadings += out.size();
      return;
    }
    uint64_t shadings = 0;
    int lookups = 0;
    if (sh.mode == ShadingMode::supersample) {
      for (Sample& smp : out)
        smp.value = primitive_value(primitive_at(scene_, {smp.x, smp.y}), {smp.x, smp.y},
                                    sh.texture, footprint_, &lookups);
      shadings = out.size();
    } else {
      // Coverage per sample; one shading per primitive the pixel's samples see.
      thread_local std::vector<int> primitives_;
      primitives_.resize(out.size());
      for (size_t k = 0; k < out.size(); ++k)
        primitives_[k] = primitive_at(scene_, {out[k].x, out[k].y});
      for (size_t k = 0; k < out.size(); ++k) {
        if (k > 0 && std::find(primitives_.begin(), primitives_.begin() + static_cast<long>(k),
                               primitives_[k]) != primitives_.begin() + static_cast<long>(k))
          continue;  // shaded already
        Vec2 at{double(a), double(b)};
        if (sh.point == ShadingPoint::centroid) {
          Vec2 sum{0, 0};
          int covered = 0;
          for (size_t q = k; q < out.size(); ++q)
            if (primitives_[q] == primitives_[k]) sum.x += out[q].x, sum.y += out[q].y, ++covered;
          at = {sum.x / covered, sum.y / covered};
        }
        const Rgb value = primitive_value(primitives_[k], at, sh.texture, 1, &lookups);
        ++shadings;
        for (size_t q = k; q < out.size(); ++q)
          if (primitives_[q] == primitives_[k]) out[q].value = value;
      }
    }
    if (counts) {
      counts->lookups += static_cast<uint64_t>(lookups);
      counts->shadings += shadings;
    }
  }

 private:
  Rgb value(Vec2 p) const {
    if (colour_) return shade_colour(scene_, p);
    return {shade(scene_, p), 0, 0};
  }
  Rgb primitive_value(int primitive, Vec2 p, const TextureFilter& filter, double footprint,
                      int* lookups) const {
    if (colour_) return shade_primitive_colour(scene_, primitive, p, filter, footprint, lookups);
    return {shade_primitive(scene_, primitive, p, filter, footprint, lookups), 0, 0};
  }

  const Scene& scene_;
  const Sampling& s_;
  PointGenerator generator_;
  std::shared_ptr<const PixelPointTable> table_;
  double footprint_;
  bool plain_, colour_;
};

// The pattern's kernels read samples of several pixels; with a shading other
// than plain supersampling, each sample's value is its owning pixel's. The
// pixels' samples are kept for the rows one output row reads (its own and
// `reach` on each side), in slots reused from pixel to pixel.
class OwnedSampleCache {
 public:
  OwnedSampleCache(const PixelSampler& sampler, int row, int width, int reach, Counts& counts)
      : sampler_(sampler),
        row_(row),
        width_(width),
        reach_(reach + 1),  // a +1/2 border sample may belong to the pixel before
        stride_(width + 2 * reach_),
        slots_(static_cast<size_t>(stride_) * (2 * reach_ + 1)),
        filled_(slots_.size(), false),
        counts_(counts) {}

  const Rgb& value(Vec2 q) {
    // The pixel that holds q inside [-1/2, 1/2); a pattern that is not of a
    // sharing family may own a sample on its +1/2 border instead.
    const int a0 = static_cast<int>(std::floor(q.x + 0.5 + kSameSampleEps));
    const int b0 = static_cast<int>(std::floor(q.y + 0.5 + kSameSampleEps));
    for (const auto& [a, b] : {std::pair{a0, b0}, {a0 - 1, b0}, {a0, b0 - 1}, {a0 - 1, b0 - 1}}) {
      const std::vector<Sample>& samples = pixel(a, b);
      for (const Sample& s : samples)
        if (std::abs(s.x - q.x) <= 1e-7 && std::abs(s.y - q.y) <= 1e-7) return s.value;
    }
    throw Error(
        fmt::format("render: no pixel owns a sample at ({}, {}); please report it", q.x, q.y));
  }

 private:
  const std::vector<Sample>& pixel(int a, int b) {
    const int i = a + reach_, j = b - row_ + reach_;
    if (i < 0 || i >= stride_ || j < 0 || j > 2 * reach_)
      throw Error(
          fmt::format("render: pixel ({}, {}) is outside the kernel's reach; please "
                      "report it",
                      a, b));
    const size_t slot = static_cast<size_t>(j) * stride_ + i;
    if (!filled_[slot]) {
      const bool counted = b == row_ && a >= 0 && a < width_;  // each image pixel once
      sampler_.pixel(a, b, slots_[slot], counted ? &counts_ : nullptr);
      filled_[slot] = true;
    }
    return slots_[slot];
  }

  const PixelSampler& sampler_;
  int row_, width_, reach_, stride_;
  std::vector<std::vector<Sample>> slots_;
  std::vector<bool> filled_;
  Counts& counts_;
};

}  // namespace

ShadingMode parse_shading_mode(std::string_view text) {
  if (text == "supersample") return ShadingMode::supersample;
  if (text == "multisample") return ShadingMode::multisample;
  throw ParameterError("mode", fmt::format(" '{}': use supersample or multisample", text));
}

std::string_view shading_mode_name(ShadingMode mode) {
  return mode == ShadingMode::supersample ? "supersample" : "multisample";
}

ShadingPoint parse_shading_point(std::string_view text) {
  if (text == "centre" || text == "center") return ShadingPoint::centre;
  if (text == "centroid") return ShadingPoint::centroid;
  throw ParameterError("shading-point", fmt::format(" '{}': use centre or centroid", text));
}

std::string_view shading_point_name(ShadingPoint point) {
  return point == ShadingPoint::centre ? "centre" : "centroid";
}

namespace {

// Rows [row_begin, row_end) of the image (all of them with a pattern's own
// kernels); the image returned holds those rows alone.
Image render_band(const Scene& scene, int width, int height, const Sampling& s,
                  const std::optional<Filter>& filter, RenderStats* stats, double offset,
                  int row_begin, int row_end) {
  if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide)
    throw ParameterError(
        "size", fmt::format(": {}x{} is out of range 1..{}", width, height, kMaxImageSide));
  if (!s.pattern && s.generator.empty()) throw Error("render: give a pattern or a generator");
  if (!s.pattern && (s.samples < 1 || s.samples > kMaxSamplesPerPixel))
    throw ParameterError(
        "samples", fmt::format(" {}: expected 1 to {} per pixel", s.samples, kMaxSamplesPerPixel));
  if (!filter && !s.pattern) throw Error("render: a per-pixel generator needs a filter");
  if (row_begin < 0 || row_begin % kRenderBlockRows != 0 || row_end <= row_begin ||
      row_end > height || (!filter && (row_begin != 0 || row_end != height)))
    throw Error(fmt::format("render: rows {} to {} of {} are not a band of whole blocks", row_begin,
                            row_end, height));
  const int rows = row_end - row_begin;
  const int n = scene_channels(scene);  // 1 grey, 3 colour
  const auto nc = static_cast<size_t>(n);
  Image img{width, rows, 0.0, std::vector<double>(static_cast<size_t>(width) * rows * nc), n};
  PixelSampler sampler(scene, s);
  Counts counts;
  const bool plain = s.shading.exact() && !has_texture(scene);  // nothing to count but samples

  if (!filter) {
    // The pattern's own kernels: output pixel (i, j) uses kernel (i mod w, j mod h),
    // reconstructed at the kernel's output point (half a pixel off for even footprints).
    const Pattern& p = *s.pattern;
    img.offset = p.footprint.size == 1 ? 0.0 : 0.5;
    std::vector<Kernel> kernels;
    int reach = 0;  // pixels a kernel reaches from its output pixel
    for (int k = 0; k < p.set_count(); ++k) {
      kernels.push_back(make_kernel(p, k));
      for (int r = 0; r < kernels.back().size(); ++r)
        reach = std::max({reach, static_cast<int>(std::ceil(std::abs(kernels.back().x[r]) + 1)),
                          static_cast<int>(std::ceil(std::abs(kernels.back().y[r]) + 1))});
    }
    tbb::parallel_for(0, height, [&](int j) {
      throw_if_interrupted();
      OwnedSampleCache owned(sampler, j, width, reach, counts);
      for (int i = 0; i < width; ++i) {
        const Kernel& k = kernels[set_index(p, i, j)];
        Rgb v{0, 0, 0};
        for (int r = 0; r < k.size(); ++r) {
          const Vec2 q{i + img.offset + k.x[r], j + img.offset + k.y[r]};
          if (n == 1) {
            v[0] += k.w[r] * (plain ? shade(scene, q) : owned.value(q)[0]);
          } else {
            const Rgb c = plain ? shade_colour(scene, q) : owned.value(q);
            for (size_t ch = 0; ch < 3; ++ch) v[ch] += k.w[r] * c[ch];
          }
        }
        for (size_t ch = 0; ch < nc; ++ch)
          img.values[(static_cast<size_t>(j) * width + i) * nc + ch] = v[ch];
      }
    });
  } else {
    // Blocks of output rows; every sample of the pixels the filter reaches is
    // drawn once per block, each pixel's samples weighed into the output
    // pixels within the filter's radius (PixelSplat), and those sums added up
    // pixel by pixel in row order: each output pixel's value is the same
    // whatever the blocks. The sums are normalized at the end.
    img.offset = offset;
    const int reach = static_cast<int>(std::floor(filter->radius() + 0.5)) + (offset != 0 ? 1 : 0);
    sampler.share_points(-reach, row_begin - reach, width + reach, row_end + reach);
    // Each block draws `reach` rows of pixels above and below its own: the
    // taller the block, the fewer drawn twice (a 2-pixel radius: 12 rows for
    // 8, 36 for 32).
    constexpr int kBlock = 4 * kRenderBlockRows;
    tbb::parallel_for(0, (rows + kBlock - 1) / kBlock, [&](int block) {
      throw_if_interrupted();
      const int j0 = row_begin + block * kBlock, j1 = std::min(row_end, j0 + kBlock);
      std::vector<double> sum(static_cast<size_t>(j1 - j0) * width * nc, 0.0),
          weight(static_cast<size_t>(j1 - j0) * width, 0.0);
      std::vector<Sample> samples;
      PixelSplat splat(*filter, reach, offset, n);
      for (int b = j0 - reach; b < j1 + reach; ++b)
        for (int a = -reach; a < width + reach; ++a) {
          const bool counted = b >= j0 && b < j1 && a >= 0 && a < width;
          sampler.pixel(a, b, samples, counted ? &counts : nullptr);
          const int i_lo = std::max(0, a - reach), i_hi = std::min(width - 1, a + reach);
          const int j_lo = std::max(j0, b - reach), j_hi = std::min(j1 - 1, b + reach);
          if (i_lo > i_hi || j_lo > j_hi) continue;
          splat.clear();
          for (const Sample& smp : samples) splat.add(smp.x, smp.y, smp.value);
          splat.weigh(a, b);
          for (int j = j_lo; j <= j_hi; ++j) {
            double* srow = &sum[static_cast<size_t>(j - j0) * width * nc];
            double* wrow = &weight[static_cast<size_t>(j - j0) * width];
            for (int i = i_lo; i <= i_hi; ++i) {
              for (size_t ch = 0; ch < nc; ++ch)
                srow[static_cast<size_t>(i) * nc + ch] +=
                    splat.sum(i - a, j - b, static_cast<int>(ch));
              wrow[i] += splat.weight(i - a, j - b);
            }
          }
        }
      for (int j = j0; j < j1; ++j)
        for (int i = 0; i < width; ++i) {
          const size_t k = static_cast<size_t>(j - j0) * width + i;
          for (size_t ch = 0; ch < nc; ++ch)
            img.values[(static_cast<size_t>(j - row_begin) * width + i) * nc + ch] =
                weight[k] != 0 ? sum[k * nc + ch] / weight[k] : 0.0;
        }
    });
  }
  if (stats) {
    stats->samples_per_pixel = s.pattern ? samples_per_pixel(*s.pattern) : s.samples;
    const double pixels = double(width) * height;
    stats->lookups_per_pixel = double(counts.lookups) / pixels;
    // Exact supersampling shades every sample it owns once.
    stats->shadings_per_pixel = plain ? stats->samples_per_pixel : double(counts.shadings) / pixels;
  }
  return img;
}

}  // namespace

Image render(const Scene& scene, int width, int height, const Sampling& s,
             const std::optional<Filter>& filter, RenderStats* stats, double offset) {
  return render_band(scene, width, height, s, filter, stats, offset, 0, height);
}

Image render_rows(const Scene& scene, int width, int height, const Sampling& s,
                  const Filter& filter, double offset, int row_begin, int row_end) {
  return render_band(scene, width, height, s, filter, nullptr, offset, row_begin, row_end);
}

}  // namespace aapat

#include "aapat/render/renderer.h"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <cmath>

#include "aapat/generate/point_generators.h"

namespace aapat {
namespace {

struct Sample {
  double x, y, value;
};

// The samples pixel (a, b) owns, in image coordinates, with the scene's value.
void pixel_samples(const Scene& scene, const Sampling& s, const PointGenerator& generator, int a,
                   int b, std::vector<Sample>& out) {
  if (s.pattern) {
    const Pattern& p = *s.pattern;
    for (const Vec2& v : p.sets[set_index(p, a, b)]) {
      // A shared border sample belongs to the pixel that lists it at -1/2.
      if (p.footprint.plus && (v.x > 0.5 - kSameSampleEps || v.y > 0.5 - kSameSampleEps)) continue;
      const Vec2 w{a + v.x, b + v.y};
      out.push_back({w.x, w.y, shade(scene, w)});
    }
    return;
  }
  for (const Vec2& v : pixel_points(generator, s.samples, s.seed, a, b)) {
    const Vec2 w{a + v.x, b + v.y};
    out.push_back({w.x, w.y, shade(scene, w)});
  }
}

}  // namespace

Image render(const Scene& scene, int width, int height, const Sampling& s,
             const std::optional<Filter>& filter, RenderStats* stats, double offset) {
  if (width < 1 || height < 1 || width > 16384 || height > 16384)
    throw ParameterError("size", fmt::format(": {}x{} is out of range 1..16384", width, height));
  if (!s.pattern && s.generator.empty()) throw Error("render: give a pattern or a generator");
  if (!filter && !s.pattern) throw Error("render: a per-pixel generator needs a filter");
  Image img{width, height, 0.0, std::vector<double>(static_cast<size_t>(width) * height)};

  if (!filter) {
    // The pattern's own kernels: output pixel (i, j) uses kernel (i mod w, j mod h),
    // reconstructed at the kernel's output point (half a pixel off for even footprints).
    const Pattern& p = *s.pattern;
    img.offset = p.footprint.size == 1 ? 0.0 : 0.5;
    std::vector<Kernel> kernels;
    for (int k = 0; k < p.set_count(); ++k) kernels.push_back(make_kernel(p, k));
    tbb::parallel_for(0, height, [&](int j) {
      for (int i = 0; i < width; ++i) {
        const Kernel& k = kernels[set_index(p, i, j)];
        double v = 0;
        for (int r = 0; r < k.size(); ++r)
          v += k.w[r] * shade(scene, {i + img.offset + k.x[r], j + img.offset + k.y[r]});
        img.values[static_cast<size_t>(j) * width + i] = v;
      }
    });
  } else {
    // Blocks of output rows; every sample of the pixels the filter reaches is
    // drawn once per block and scattered into the output pixels within the
    // filter's radius with weight h(dx) h(dy); the sums are normalized at the end.
    img.offset = offset;
    const PointGenerator generator =
        s.pattern ? PointGenerator{} : make_point_generator(s.generator);
    const int reach = static_cast<int>(std::floor(filter->radius() + 0.5)) + (offset != 0 ? 1 : 0);
    constexpr int kBlock = 8;
    tbb::parallel_for(0, (height + kBlock - 1) / kBlock, [&](int block) {
      const int j0 = block * kBlock, j1 = std::min(height, j0 + kBlock);
      std::vector<double> sum(static_cast<size_t>(j1 - j0) * width, 0.0), weight(sum.size(), 0.0);
      std::vector<Sample> samples;
      std::vector<double> hx(2 * reach + 1), hy(2 * reach + 1);
      for (int b = j0 - reach; b < j1 + reach; ++b)
        for (int a = -reach; a < width + reach; ++a) {
          samples.clear();
          pixel_samples(scene, s, generator, a, b, samples);
          const int i_lo = std::max(0, a - reach), i_hi = std::min(width - 1, a + reach);
          const int j_lo = std::max(j0, b - reach), j_hi = std::min(j1 - 1, b + reach);
          if (i_lo > i_hi || j_lo > j_hi) continue;
          for (const Sample& smp : samples) {
            for (int i = i_lo; i <= i_hi; ++i) hx[i - i_lo] = filter->value(smp.x - i - offset);
            for (int j = j_lo; j <= j_hi; ++j) hy[j - j_lo] = filter->value(smp.y - j - offset);
            for (int j = j_lo; j <= j_hi; ++j) {
              if (hy[j - j_lo] == 0) continue;
              double* srow = &sum[static_cast<size_t>(j - j0) * width];
              double* wrow = &weight[static_cast<size_t>(j - j0) * width];
              for (int i = i_lo; i <= i_hi; ++i) {
                const double w = hx[i - i_lo] * hy[j - j_lo];
                srow[i] += w * smp.value;
                wrow[i] += w;
              }
            }
          }
        }
      for (int j = j0; j < j1; ++j)
        for (int i = 0; i < width; ++i) {
          const size_t k = static_cast<size_t>(j - j0) * width + i;
          img.values[static_cast<size_t>(j) * width + i] =
              weight[k] != 0 ? sum[k] / weight[k] : 0.0;
        }
    });
  }
  if (stats) stats->samples_per_pixel = s.pattern ? samples_per_pixel(*s.pattern) : s.samples;
  return img;
}

}  // namespace aapat

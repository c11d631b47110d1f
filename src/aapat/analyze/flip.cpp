#include "aapat/analyze/flip.h"

#include <fmt/format.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "aapat/analyze/flip_model.h"
#include "aapat/core/geometry.h"
#include "aapat/core/interrupt.h"

namespace aapat {
namespace {

namespace fm = flip_model;

// One image's half of FLIP, per pixel: its CSF-filtered colour as
// Hunt-adjusted CIELab (steps 2, 3) and the edge and point strength of its
// luminance (step 4). Written for a band of rows at a time into `out`, so
// that the intermediate planes are a few rows tall and reused: a 1920x1080
// pair once touched 30 full-size planes, and on this kind of machine the
// page faults of fresh memory cost more than the arithmetic.
struct HalfPlanes {
  float *l, *a, *b, *edge, *point;  // each `width` wide, the band's rows
};

struct Filters {
  fm::CsfFilters csf;
  fm::FeatureFilters feature;
  int halo() const { return std::max(csf.y.radius, feature.g.radius); }
};

// Scratch rows of one band: the opponent channels, their row-filtered
// versions and the luminance's, for the band's rows and a halo above and
// below (the column filters' reach).
struct BandScratch {
  std::vector<float> y, cx, cz, y1, cx1, cz1, cz2, gx, dx, ddx, col, padded;
  void resize(size_t n, int w, int halo) {
    for (auto* v : {&y, &cx, &cz, &y1, &cx1, &cz1, &cz2, &gx, &dx, &ddx}) v->resize(n);
    col.resize(static_cast<size_t>(8) * w);
    padded.resize(static_cast<size_t>(w + 2 * halo));
  }
};

// out[i] = sum_k taps[k] in[i + k - r] with the edge pixel repeated.
void filter_row(const float* row, int w, const fm::Taps& taps, float* padded, float* out) {
  const int r = taps.radius;
  for (int i = 0; i < w + 2 * r; ++i) padded[i] = row[std::clamp(i - r, 0, w - 1)];
  // Tap by tap over the whole row, so that the inner loop vectorizes.
  std::fill(out, out + w, 0.0f);
  for (int k = 0; k <= 2 * r; ++k) {
    const float tk = taps.w[static_cast<size_t>(k)];
    const float* in_k = padded + k;
    for (int i = 0; i < w; ++i) out[i] += tk * in_k[i];
  }
}

// The same along y for output row j, whose neighbours are rows of the band
// plane `in` starting at image row `first`: whole rows accumulated, so the
// inner loop runs along memory.
void filter_column(const std::vector<float>& in, int w, int h, int first, int j,
                   const fm::Taps& taps, float* out) {
  std::fill(out, out + w, 0.0f);
  for (int k = -taps.radius; k <= taps.radius; ++k) {
    const float t = taps.w[static_cast<size_t>(k + taps.radius)];
    const int row = std::clamp(j + k, 0, h - 1) - first;
    const float* src = in.data() + static_cast<size_t>(row) * w;
    for (int i = 0; i < w; ++i) out[i] += t * src[i];
  }
}

// Rows [j0, j1) of one image's half into `out` (row j0 first).
void half_band(const ColorImage& img, const Filters& f, int j0, int j1, BandScratch& s,
               const HalfPlanes& out) {
  const int w = img.width, h = img.height, halo = f.halo();
  const int first = std::max(0, j0 - halo), last = std::min(h, j1 + halo);
  s.resize(static_cast<size_t>(last - first) * w, w, halo);
  float* padded = s.padded.data();
  for (int j = first; j < last; ++j) {
    throw_if_interrupted();
    const size_t o = static_cast<size_t>(j - first) * w;
    const float* c = &img.rgb[3 * static_cast<size_t>(j) * w];
    for (int i = 0; i < w; ++i, c += 3) {
      const fm::Vec3f v = fm::xyz_to_ycxcz(fm::rgb_to_xyz(
          fm::Vec3f{srgb_to_linear(c[0]), srgb_to_linear(c[1]), srgb_to_linear(c[2])}));
      s.y[o + i] = v.x, s.cx[o + i] = v.y, s.cz[o + i] = v.z;
    }
    filter_row(&s.y[o], w, f.csf.y, padded, &s.y1[o]);
    filter_row(&s.cx[o], w, f.csf.cx, padded, &s.cx1[o]);
    filter_row(&s.cz[o], w, f.csf.cz1, padded, &s.cz1[o]);
    filter_row(&s.cz[o], w, f.csf.cz2, padded, &s.cz2[o]);
    // The luminance (Y + 16) / 116, relative in [0, 1], for the features;
    // y1 is done with s.y's row, so the row becomes the luminance.
    for (int i = 0; i < w; ++i) s.y[o + i] = (s.y[o + i] + 16.0f) / 116.0f;
    filter_row(&s.y[o], w, f.feature.g, padded, &s.gx[o]);
    filter_row(&s.y[o], w, f.feature.dg, padded, &s.dx[o]);
    filter_row(&s.y[o], w, f.feature.ddg, padded, &s.ddx[o]);
  }
  float* col = s.col.data();
  float *y = col, *cx = col + w, *c1 = col + 2 * w, *c2 = col + 3 * w;
  float *dxy = col + 4 * w, *ddxy = col + 5 * w, *dyx = col + 6 * w, *ddyx = col + 7 * w;
  for (int j = j0; j < j1; ++j) {
    filter_column(s.y1, w, h, first, j, f.csf.y, y);
    filter_column(s.cx1, w, h, first, j, f.csf.cx, cx);
    filter_column(s.cz1, w, h, first, j, f.csf.cz1, c1);
    filter_column(s.cz2, w, h, first, j, f.csf.cz2, c2);
    filter_column(s.dx, w, h, first, j, f.feature.g, dxy);    // d/dx, smoothed along y
    filter_column(s.ddx, w, h, first, j, f.feature.g, ddxy);  // d2/dx2, smoothed along y
    filter_column(s.gx, w, h, first, j, f.feature.dg, dyx);   // d/dy of the x-smoothed image
    filter_column(s.gx, w, h, first, j, f.feature.ddg, ddyx);
    const size_t o = static_cast<size_t>(j - j0) * w;
    for (int i = 0; i < w; ++i) {
      fm::Vec3f rgb = fm::xyz_to_rgb(fm::ycxcz_to_xyz(fm::Vec3f{y[i], cx[i], c1[i] + c2[i]}));
      rgb = {std::clamp(rgb.x, 0.0f, 1.0f), std::clamp(rgb.y, 0.0f, 1.0f),
             std::clamp(rgb.z, 0.0f, 1.0f)};
      const fm::Vec3f v = fm::hunt(fm::xyz_to_lab(fm::rgb_to_xyz(rgb)));
      out.l[o + i] = v.x, out.a[o + i] = v.y, out.b[o + i] = v.z;
      out.edge[o + i] = std::hypot(dxy[i], dyx[i]);
      out.point[o + i] = std::hypot(ddxy[i], ddyx[i]);
    }
  }
}

// Rows per band: tall enough that the halo (about 20 rows at 67 ppd) is a
// small part of the work, short enough that a band's scratch stays in cache
// and every core gets bands.
constexpr int kBandRows = 64;

template <class Body>
void for_each_band(int h, Body body) {
  const int bands = (h + kBandRows - 1) / kBandRows;
  tbb::parallel_for(0, bands, [&](int b) {
    const int j0 = b * kBandRows;
    body(j0, std::min(h, j0 + kBandRows));
  });
}

template <class Reference>
void check_sizes(const Reference& reference, const ColorImage& test) {
  if (reference.width != test.width || reference.height != test.height)
    throw Error(
        fmt::format("FLIP: the reference is {}x{} pixels and the test {}x{}; they must match",
                    reference.width, reference.height, test.width, test.height));
}

void check_ppd(double ppd) {
  if (!(ppd >= kMinPixelsPerDegree && ppd <= kMaxPixelsPerDegree))
    throw ParameterError("ppd", fmt::format(" {}: expected {} to {} pixels per degree", ppd,
                                            kMinPixelsPerDegree, kMaxPixelsPerDegree));
}

void summarize(FlipResult& r) {
  const size_t n = r.map.size();
  double sum = 0;
  r.min = 1, r.max = 0;
  r.histogram.assign(kFlipHistogramBuckets, 0);
  for (float v : r.map) {
    sum += v;
    r.min = std::min(r.min, static_cast<double>(v));
    r.max = std::max(r.max, static_cast<double>(v));
    ++r.histogram[std::min(static_cast<int>(v * kFlipHistogramBuckets), kFlipHistogramBuckets - 1)];
  }
  r.mean = sum / static_cast<double>(n);
  // Weighted percentiles, exactly: sorted, the value at which the running
  // sum of errors passes the fraction of their total.
  std::vector<float> sorted = r.map;
  tbb::parallel_sort(sorted.begin(), sorted.end());
  const std::array<double, 3> fractions = {0.25, 0.5, 0.75};
  std::array<double, 3> values{};
  double running = 0;
  size_t next = 0;
  for (float v : sorted) {
    running += v;
    while (next < 3 && running >= fractions[next] * sum) values[next++] = v;
  }
  while (next < 3) values[next++] = sorted.back();
  r.weighted_q1 = values[0], r.weighted_median = values[1], r.weighted_q3 = values[2];
}

}  // namespace

double pixels_per_degree(double distance, double pixels, double width) {
  return distance * (pixels / width) * (kPi / 180.0);
}

double default_pixels_per_degree() {
  return pixels_per_degree(0.7, 3840, 0.7);
}

FlipReference prepare_flip_reference(const ColorImage& reference, double ppd) {
  check_ppd(ppd);
  if (reference.pixels() == 0) throw Error("FLIP: the images are empty");
  const size_t n = reference.pixels();
  FlipReference r{reference.width, reference.height, ppd, {}, {}, {}, {}, {}};
  for (auto* v : {&r.l, &r.a, &r.b, &r.edge, &r.point}) v->resize(n);
  const Filters f{fm::csf_filters(ppd), fm::feature_filters(ppd)};
  const int w = reference.width;
  tbb::enumerable_thread_specific<BandScratch> scratch;
  for_each_band(reference.height, [&](int j0, int j1) {
    BandScratch& s = scratch.local();
    const size_t o = static_cast<size_t>(j0) * w;
    half_band(reference, f, j0, j1, s, {&r.l[o], &r.a[o], &r.b[o], &r.edge[o], &r.point[o]});
  });
  return r;
}

FlipResult flip(const FlipReference& reference, const ColorImage& test) {
  check_sizes(reference, test);
  const int w = test.width, h = test.height;
  const Filters f{fm::csf_filters(reference.ppd), fm::feature_filters(reference.ppd)};
  const float cmax = fm::max_color_distance(), knee = fm::kPc * cmax;
  FlipResult r{w, h, std::vector<float>(test.pixels()), 0, 0, 0, 0, 0, 0, {}};
  tbb::enumerable_thread_specific<BandScratch> scratch;
  tbb::enumerable_thread_specific<std::vector<float>> band_planes;
  for_each_band(h, [&](int j0, int j1) {
    BandScratch& s = scratch.local();
    const size_t m = static_cast<size_t>(j1 - j0) * w, o = static_cast<size_t>(j0) * w;
    std::vector<float>& planes = band_planes.local();
    planes.resize(5 * m);
    const HalfPlanes t{&planes[0], &planes[m], &planes[2 * m], &planes[3 * m], &planes[4 * m]};
    half_band(test, f, j0, j1, s, t);
    for (size_t q = 0; q < m; ++q) {
      const size_t p = o + q;
      float color = std::pow(fm::hyab(fm::Vec3f{reference.l[p], reference.a[p], reference.b[p]},
                                      fm::Vec3f{t.l[q], t.a[q], t.b[q]}),
                             fm::kQc);
      color = fm::remapped_color(color, knee, cmax);
      const float feature =
          fm::feature_difference(reference.edge[p] - t.edge[q], reference.point[p] - t.point[q]);
      r.map[p] = std::pow(color, 1 - feature);
    }
  });
  summarize(r);
  return r;
}

FlipResult flip(const ColorImage& reference, const ColorImage& test, double ppd) {
  check_ppd(ppd);
  check_sizes(reference, test);
  return flip(prepare_flip_reference(reference, ppd), test);
}

}  // namespace aapat

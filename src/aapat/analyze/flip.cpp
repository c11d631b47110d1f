#include "aapat/analyze/flip.h"

#include <fmt/format.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "aapat/core/geometry.h"
#include "aapat/core/interrupt.h"

namespace aapat {
namespace {

// The paper's constants: colour pipeline exponent qc, remapping knee pc
// (of the largest distance) and pt (the error it maps to); the feature
// filter's width w in degrees and exponent qf.
constexpr float kQc = 0.7f, kPc = 0.4f, kPt = 0.95f, kW = 0.082f, kQf = 0.5f;

// The contrast sensitivity functions, each a * sqrt(pi / b) exp(-pi^2 x^2 / b)
// with x in degrees: Y and Cx one Gaussian, Cz the sum of two (paper Sec. 4.1).
constexpr float kAy = 1, kBy = 0.0047f, kAcx = 1, kBcx = 0.0053f;
constexpr float kAcz1 = 34.1f, kBcz1 = 0.04f, kAcz2 = 13.5f, kBcz2 = 0.025f;

// D65 white (color_image.h) and its inverse, as the paper's code rounds them.
constexpr std::array<float, 3> kWhite = {float(kD65White[0]), float(kD65White[1]),
                                         float(kD65White[2])};
constexpr std::array<float, 3> kInvWhite = {1.052156925f, 1.0f, 0.918357670f};

struct Vec3f {
  float x, y, z;
};

Vec3f rgb_to_xyz(Vec3f c) {
  return {(10135552.0f / 24577794.0f) * c.x + (8788810.0f / 24577794.0f) * c.y +
              (4435075.0f / 24577794.0f) * c.z,
          (2613072.0f / 12288897.0f) * c.x + (8788810.0f / 12288897.0f) * c.y +
              (887015.0f / 12288897.0f) * c.z,
          (1425312.0f / 73733382.0f) * c.x + (8788810.0f / 73733382.0f) * c.y +
              (70074185.0f / 73733382.0f) * c.z};
}

Vec3f xyz_to_rgb(Vec3f c) {
  const std::array<float, 3> rgb = xyz_to_linear_rgb(c.x, c.y, c.z);
  return {rgb[0], rgb[1], rgb[2]};
}

// YyCxCz: CIELab with the cube root left out, so that it is linear in XYZ.
Vec3f xyz_to_ycxcz(Vec3f c) {
  const float x = c.x * kInvWhite[0], y = c.y * kInvWhite[1], z = c.z * kInvWhite[2];
  return {116.0f * y - 16.0f, 500.0f * (x - y), 200.0f * (y - z)};
}

Vec3f ycxcz_to_xyz(Vec3f c) {
  const float y = (c.x + 16.0f) / 116.0f;
  return {(y + c.y / 500.0f) * kWhite[0], y * kWhite[1], (y - c.z / 200.0f) * kWhite[2]};
}

Vec3f xyz_to_lab(Vec3f c) {
  constexpr float delta = 6.0f / 29.0f, delta3 = delta * delta * delta;
  auto f = [&](float t) {
    return t > delta3 ? std::cbrt(t) : t / (3.0f * delta * delta) + 4.0f / 29.0f;
  };
  const float fx = f(c.x * kInvWhite[0]), fy = f(c.y * kInvWhite[1]), fz = f(c.z * kInvWhite[2]);
  return {116.0f * fy - 16.0f, 500.0f * (fx - fy), 200.0f * (fy - fz)};
}

// The Hunt effect: chroma looks weaker in the dark, so a and b scale with L.
Vec3f hunt(Vec3f lab) {
  return {lab.x, 0.01f * lab.x * lab.y, 0.01f * lab.x * lab.z};
}

float hyab(Vec3f a, Vec3f b) {
  return std::abs(a.x - b.x) + std::hypot(a.y - b.y, a.z - b.z);
}

// The largest colour distance, green to blue, raised to qc. Computed at run
// time from an opaque 1: from constants the compiler may fold cbrtf correctly
// rounded, where glibc's cbrtf is 1 ulp lower for green's Y, so every FLIP
// value depended on whether this function was inlined (it was, once the
// layer compiled as one unity batch).
float max_color_distance() {
  volatile float one = 1.0f;
  const Vec3f green = hunt(xyz_to_lab(rgb_to_xyz({0, one, 0})));
  const Vec3f blue = hunt(xyz_to_lab(rgb_to_xyz({0, 0, one})));
  return std::pow(hyab(green, blue), kQc);
}

// A 1D filter with taps at offsets -radius .. radius.
struct Taps {
  int radius = 0;
  std::vector<float> w;
};

// The CSF filters sampled at 1/ppd degree steps out to three standard
// deviations of the widest: Y and Cx normalized to sum 1; Cz's two
// Gaussians as square roots of their 2D weights (so that g1(x) g1(y) +
// g2(x) g2(y) is the 2D sum), normalized together.
struct CsfFilters {
  Taps y, cx, cz1, cz2;
};

CsfFilters csf_filters(double ppd) {
  const float pi2 = static_cast<float>(kPi * kPi);
  const float widest = std::max({kBy, kBcx, kBcz1, kBcz2});
  const int r = static_cast<int>(std::ceil(3.0f * std::sqrt(widest / (2.0f * pi2)) * ppd));
  CsfFilters f{{r, {}}, {r, {}}, {r, {}}, {r, {}}};
  auto gauss = [&](float x2, float a, float b) {
    return a * std::sqrt(static_cast<float>(kPi) / b) * std::exp(-pi2 * x2 / b);
  };
  float sy = 0, scx = 0, s1 = 0, s2 = 0;
  for (int k = -r; k <= r; ++k) {
    const float x = static_cast<float>(k) / static_cast<float>(ppd), x2 = x * x;
    f.y.w.push_back(gauss(x2, kAy, kBy));
    f.cx.w.push_back(gauss(x2, kAcx, kBcx));
    f.cz1.w.push_back(std::sqrt(kAcz1 * std::sqrt(static_cast<float>(kPi) / kBcz1)) *
                      std::exp(-pi2 * x2 / kBcz1));
    f.cz2.w.push_back(std::sqrt(kAcz2 * std::sqrt(static_cast<float>(kPi) / kBcz2)) *
                      std::exp(-pi2 * x2 / kBcz2));
    sy += f.y.w.back(), scx += f.cx.w.back(), s1 += f.cz1.w.back(), s2 += f.cz2.w.back();
  }
  const float cz = 1.0f / std::sqrt(s1 * s1 + s2 * s2);
  for (size_t k = 0; k < f.y.w.size(); ++k) {
    f.y.w[k] /= sy;
    f.cx.w[k] /= scx;
    f.cz1.w[k] *= cz;
    f.cz2.w[k] *= cz;
  }
  return f;
}

// The feature filters: a Gaussian of 0.5 w ppd pixels (sum 1), its first
// and second derivatives (positive and negative lobes each of sum 1).
struct FeatureFilters {
  Taps g, dg, ddg;
};

FeatureFilters feature_filters(double ppd) {
  const float sd = 0.5f * kW * static_cast<float>(ppd);
  const int r = static_cast<int>(std::ceil(3.0f * sd));
  FeatureFilters f{{r, {}}, {r, {}}, {r, {}}};
  float sg = 0, dpos = 0, dneg = 0, ddpos = 0, ddneg = 0;
  for (int k = -r; k <= r; ++k) {
    const float x = static_cast<float>(k);
    const float g = std::exp(-x * x / (2 * sd * sd)), dg = -x * g,
                ddg = (x * x / (sd * sd) - 1) * g;
    f.g.w.push_back(g);
    f.dg.w.push_back(dg);
    f.ddg.w.push_back(ddg);
    sg += g;
    (dg > 0 ? dpos : dneg) += std::abs(dg);
    (ddg > 0 ? ddpos : ddneg) += std::abs(ddg);
  }
  for (size_t k = 0; k < f.g.w.size(); ++k) {
    f.g.w[k] /= sg;
    f.dg.w[k] /= f.dg.w[k] > 0 ? dpos : dneg;
    f.ddg.w[k] /= f.ddg.w[k] > 0 ? ddpos : ddneg;
  }
  return f;
}

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
  CsfFilters csf;
  FeatureFilters feature;
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
void filter_row(const float* row, int w, const Taps& taps, float* padded, float* out) {
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
void filter_column(const std::vector<float>& in, int w, int h, int first, int j, const Taps& taps,
                   float* out) {
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
      const Vec3f v = xyz_to_ycxcz(
          rgb_to_xyz({srgb_to_linear(c[0]), srgb_to_linear(c[1]), srgb_to_linear(c[2])}));
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
      Vec3f rgb = xyz_to_rgb(ycxcz_to_xyz({y[i], cx[i], c1[i] + c2[i]}));
      rgb = {std::clamp(rgb.x, 0.0f, 1.0f), std::clamp(rgb.y, 0.0f, 1.0f),
             std::clamp(rgb.z, 0.0f, 1.0f)};
      const Vec3f v = hunt(xyz_to_lab(rgb_to_xyz(rgb)));
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
  const Filters f{csf_filters(ppd), feature_filters(ppd)};
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
  const Filters f{csf_filters(reference.ppd), feature_filters(reference.ppd)};
  const float cmax = max_color_distance(), knee = kPc * cmax;
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
      float color = std::pow(
          hyab({reference.l[p], reference.a[p], reference.b[p]}, {t.l[q], t.a[q], t.b[q]}), kQc);
      // Distances below the knee map to [0, pt], the rest to (pt, 1].
      color = color < knee ? color * kPt / knee : kPt + (color - knee) / (cmax - knee) * (1 - kPt);
      const float feature = std::pow(std::max(std::abs(reference.edge[p] - t.edge[q]),
                                              std::abs(reference.point[p] - t.point[q])) /
                                         std::sqrt(2.0f),
                                     kQf);
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

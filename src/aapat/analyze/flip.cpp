#include "aapat/analyze/flip.h"

#include <fmt/format.h>
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

using Plane = std::vector<float>;  // width * height, rows from the top

// Row filters along x with the edge pixel repeated: out[p][i] = sum_k
// taps[p][k] in[i + k - r]. `taps` share one radius.
void filter_rows(const Plane& in, int w, int h, const std::vector<const Taps*>& taps,
                 const std::vector<Plane*>& out) {
  const int r = taps[0]->radius;
  tbb::parallel_for(0, h, [&](int j) {
    throw_if_interrupted();
    std::vector<float> padded(static_cast<size_t>(w + 2 * r));
    const float* row = in.data() + static_cast<size_t>(j) * w;
    for (int i = 0; i < w + 2 * r; ++i) padded[i] = row[std::clamp(i - r, 0, w - 1)];
    for (size_t p = 0; p < taps.size(); ++p) {
      float* o = out[p]->data() + static_cast<size_t>(j) * w;
      const float* t = taps[p]->w.data();
      // Tap by tap over the whole row, so that the inner loop vectorizes.
      std::fill(o, o + w, 0.0f);
      for (int k = 0; k <= 2 * r; ++k) {
        const float tk = t[k];
        const float* in_k = padded.data() + k;
        for (int i = 0; i < w; ++i) o[i] += tk * in_k[i];
      }
    }
  });
}

// The same along y, one output row at a time: whole rows accumulated, so
// the inner loop runs along memory.
void filter_column(const Plane& in, int w, int h, int j, const Taps& taps, float* out) {
  std::fill(out, out + w, 0.0f);
  for (int k = -taps.radius; k <= taps.radius; ++k) {
    const float t = taps.w[static_cast<size_t>(k + taps.radius)];
    const float* row = in.data() + static_cast<size_t>(std::clamp(j + k, 0, h - 1)) * w;
    for (int i = 0; i < w; ++i) out[i] += t * row[i];
  }
}

// An image in YyCxCz, one plane per channel.
struct Opponent {
  Plane y, cx, cz;
};

Opponent to_opponent(const ColorImage& img) {
  const size_t n = img.pixels();
  Opponent o{Plane(n), Plane(n), Plane(n)};
  tbb::parallel_for(size_t{0}, n, [&](size_t p) {
    throw_if_interrupted();
    const float* c = &img.rgb[3 * p];
    const Vec3f v = xyz_to_ycxcz(
        rgb_to_xyz({srgb_to_linear(c[0]), srgb_to_linear(c[1]), srgb_to_linear(c[2])}));
    o.y[p] = v.x, o.cx[p] = v.y, o.cz[p] = v.z;
  });
  return o;
}

// Step 2 and 3 for one image: the CSF-filtered colour of each pixel as
// Hunt-adjusted CIELab. Returned as three planes (L, a, b).
Opponent filtered_lab(const Opponent& o, int w, int h, const CsfFilters& f) {
  const size_t n = static_cast<size_t>(w) * h;
  Plane y1(n), cx1(n), cz1(n), cz2(n);
  filter_rows(o.y, w, h, {&f.y}, {&y1});
  filter_rows(o.cx, w, h, {&f.cx}, {&cx1});
  filter_rows(o.cz, w, h, {&f.cz1, &f.cz2}, {&cz1, &cz2});
  Opponent lab{Plane(n), Plane(n), Plane(n)};
  tbb::parallel_for(0, h, [&](int j) {
    throw_if_interrupted();
    std::vector<float> y(w), cx(w), c1(w), c2(w);
    filter_column(y1, w, h, j, f.y, y.data());
    filter_column(cx1, w, h, j, f.cx, cx.data());
    filter_column(cz1, w, h, j, f.cz1, c1.data());
    filter_column(cz2, w, h, j, f.cz2, c2.data());
    for (int i = 0; i < w; ++i) {
      Vec3f rgb = xyz_to_rgb(ycxcz_to_xyz({y[i], cx[i], c1[i] + c2[i]}));
      rgb = {std::clamp(rgb.x, 0.0f, 1.0f), std::clamp(rgb.y, 0.0f, 1.0f),
             std::clamp(rgb.z, 0.0f, 1.0f)};
      const Vec3f v = hunt(xyz_to_lab(rgb_to_xyz(rgb)));
      const size_t p = static_cast<size_t>(j) * w + i;
      lab.y[p] = v.x, lab.cx[p] = v.y, lab.cz[p] = v.z;
    }
  });
  return lab;
}

// Step 4 for one image: edge and point strength of the luminance, as planes.
std::pair<Plane, Plane> features(const Plane& ycxcz_y, int w, int h, const FeatureFilters& f) {
  const size_t n = static_cast<size_t>(w) * h;
  Plane lum(n);  // (Y + 16) / 116: relative luminance in [0, 1]
  for (size_t p = 0; p < n; ++p) lum[p] = (ycxcz_y[p] + 16.0f) / 116.0f;
  Plane gx(n), dx(n), ddx(n);
  filter_rows(lum, w, h, {&f.g, &f.dg, &f.ddg}, {&gx, &dx, &ddx});
  Plane edge(n), point(n);
  tbb::parallel_for(0, h, [&](int j) {
    throw_if_interrupted();
    std::vector<float> dxy(w), ddxy(w), dyx(w), ddyx(w);
    filter_column(dx, w, h, j, f.g, dxy.data());    // d/dx, smoothed along y
    filter_column(ddx, w, h, j, f.g, ddxy.data());  // d2/dx2, smoothed along y
    filter_column(gx, w, h, j, f.dg, dyx.data());   // d/dy of the x-smoothed image
    filter_column(gx, w, h, j, f.ddg, ddyx.data());
    for (int i = 0; i < w; ++i) {
      const size_t p = static_cast<size_t>(j) * w + i;
      edge[p] = std::hypot(dxy[i], dyx[i]);
      point[p] = std::hypot(ddxy[i], ddyx[i]);
    }
  });
  return {std::move(edge), std::move(point)};
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

FlipResult flip(const ColorImage& reference, const ColorImage& test, double ppd) {
  if (!(ppd >= kMinPixelsPerDegree && ppd <= kMaxPixelsPerDegree))
    throw ParameterError("ppd", fmt::format(" {}: expected {} to {} pixels per degree", ppd,
                                            kMinPixelsPerDegree, kMaxPixelsPerDegree));
  if (reference.width != test.width || reference.height != test.height)
    throw Error(
        fmt::format("FLIP: the reference is {}x{} pixels and the test {}x{}; they must match",
                    reference.width, reference.height, test.width, test.height));
  if (reference.pixels() == 0) throw Error("FLIP: the images are empty");
  const int w = reference.width, h = reference.height;
  const size_t n = reference.pixels();
  const Opponent ref = to_opponent(reference), tst = to_opponent(test);

  const CsfFilters csf = csf_filters(ppd);
  const Opponent ref_lab = filtered_lab(ref, w, h, csf), tst_lab = filtered_lab(tst, w, h, csf);
  const FeatureFilters ff = feature_filters(ppd);
  // (Plain names, not structured bindings: clang 14's lambdas cannot capture those.)
  const std::pair<Plane, Plane> ref_features = features(ref.y, w, h, ff);
  const std::pair<Plane, Plane> tst_features = features(tst.y, w, h, ff);
  const Plane &ref_edge = ref_features.first, &ref_point = ref_features.second;
  const Plane &tst_edge = tst_features.first, &tst_point = tst_features.second;

  const float cmax = max_color_distance(), knee = kPc * cmax;
  FlipResult r{w, h, std::vector<float>(n), 0, 0, 0, 0, 0, 0, {}};
  tbb::parallel_for(size_t{0}, n, [&](size_t p) {
    throw_if_interrupted();
    float color = std::pow(hyab({ref_lab.y[p], ref_lab.cx[p], ref_lab.cz[p]},
                                {tst_lab.y[p], tst_lab.cx[p], tst_lab.cz[p]}),
                           kQc);
    // Distances below the knee map to [0, pt], the rest to (pt, 1].
    color = color < knee ? color * kPt / knee : kPt + (color - knee) / (cmax - knee) * (1 - kPt);
    const float feature = std::pow(
        std::max(std::abs(ref_edge[p] - tst_edge[p]), std::abs(ref_point[p] - tst_point[p])) /
            std::sqrt(2.0f),
        kQf);
    r.map[p] = std::pow(color, 1 - feature);
  });
  summarize(r);
  return r;
}

}  // namespace aapat

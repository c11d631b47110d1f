#include "aapat/analyze/flip_gradient.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "aapat/analyze/flip_model.h"
#include "aapat/core/geometry.h"

namespace aapat {
namespace {

namespace fm = flip_model;
using Vec3d = fm::Vec3<double>;

double dot(Vec3d a, Vec3d b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

// A plane of values, rows from the top.
template <class T>
struct PlaneOf {
  int w = 0, h = 0;
  std::vector<T> v;
  PlaneOf(int width, int height) : w(width), h(height), v(static_cast<size_t>(width) * height) {}
  T& at(int i, int j) { return v[static_cast<size_t>(j) * w + i]; }
  T at(int i, int j) const { return v[static_cast<size_t>(j) * w + i]; }
};
using Plane = PlaneOf<double>;

// The forward pass in float with flip.cpp's order of operations (each sum
// from 0.0f, taps in order), so that the values and the map are flip()'s to
// the bit: a difference that is 0 there is 0 here, and the powers below 1,
// whose slopes are unbounded near 0, are taken where flip() takes them. In
// double it is the same function without float's rounding, which finite
// differences at small steps can check the gradient against.
template <class T>
PlaneOf<T> filter_forward(const PlaneOf<T>& in, const fm::Taps& t, bool along_y) {
  PlaneOf<T> out(in.w, in.h);
  for (int j = 0; j < in.h; ++j)
    for (int i = 0; i < in.w; ++i) {
      T s = 0;
      for (int k = -t.radius; k <= t.radius; ++k) {
        const T tap = t.w[static_cast<size_t>(k + t.radius)];
        s += along_y ? tap * in.at(i, std::clamp(j + k, 0, in.h - 1))
                     : tap * in.at(std::clamp(i + k, 0, in.w - 1), j);
      }
      out.at(i, j) = s;
    }
  return out;
}
template <class T>
PlaneOf<T> separable_forward(const PlaneOf<T>& in, const fm::Taps& x, const fm::Taps& y) {
  return filter_forward(filter_forward(in, x, false), y, true);
}

// The transpose of the filter out(i, j) = sum_k t[k] in(clamp(i + k - r), j)
// along x (or y): each output's gradient handed back to the inputs it read,
// the clamped border's repeats all to the border pixel.
Plane filter_transposed(const Plane& g, const fm::Taps& t, bool along_y) {
  Plane out(g.w, g.h);
  for (int j = 0; j < g.h; ++j)
    for (int i = 0; i < g.w; ++i)
      for (int k = -t.radius; k <= t.radius; ++k) {
        const double d = t.w[static_cast<size_t>(k + t.radius)] * g.at(i, j);
        if (along_y)
          out.at(i, std::clamp(j + k, 0, g.h - 1)) += d;
        else
          out.at(std::clamp(i + k, 0, g.w - 1), j) += d;
      }
  return out;
}

// The separable filters are applied along x, then along y.
Plane separable_transposed(const Plane& g, const fm::Taps& x, const fm::Taps& y) {
  return filter_transposed(filter_transposed(g, y, true), x, false);
}

void add(Plane& to, const Plane& from) {
  for (size_t k = 0; k < to.v.size(); ++k) to.v[k] += from.v[k];
}

template <class T>
T srgb_decode(T c) {
  if constexpr (std::is_same_v<T, float>)
    return srgb_to_linear(c);
  else
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

double srgb_to_linear_slope(double c) {
  return c <= 0.04045 ? 1 / 12.92 : 2.4 / 1.055 * std::pow((c + 0.055) / 1.055, 1.4);
}

// CIELab's f' (fm::lab_f).
double lab_f_slope(double t) {
  constexpr double d = fm::kLabDelta;
  return t > double(fm::kLabDelta3) ? 1 / (3 * std::cbrt(t) * std::cbrt(t)) : 1 / (3 * d * d);
}

double sign(double v) {
  return v > 0 ? 1 : v < 0 ? -1 : 0;
}

// The columns of an affine map's matrix: f(e_k) - f(0).
template <class F>
std::array<Vec3d, 3> columns(F f) {
  const Vec3d o = f(Vec3d{0, 0, 0});
  std::array<Vec3d, 3> c{};
  const Vec3d e[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int k = 0; k < 3; ++k) {
    const Vec3d v = f(e[k]);
    c[static_cast<size_t>(k)] = {v.x - o.x, v.y - o.y, v.z - o.z};
  }
  return c;
}

// g . (dF/dx): the gradient handed back through an affine map of columns c.
Vec3d transposed(const std::array<Vec3d, 3>& c, Vec3d g) {
  return {dot(c[0], g), dot(c[1], g), dot(c[2], g)};
}

// FLIP's mean of the test values `rgb` (w x h, three per pixel) against the
// reference, computed in T, and with `gradient` its gradient.
template <class T>
FlipGradient run(const FlipReference& reference, int w, int h, const std::vector<T>& rgb,
                 bool gradient) {
  using V = fm::Vec3<T>;
  const size_t pixels = static_cast<size_t>(w) * static_cast<size_t>(h);
  const fm::CsfFilters csf = fm::csf_filters(reference.ppd);
  const fm::FeatureFilters feature = fm::feature_filters(reference.ppd);
  // The linear maps at either end of the filters.
  const auto to_opponent = columns([](Vec3d c) { return fm::xyz_to_ycxcz(fm::rgb_to_xyz(c)); });
  const auto from_opponent = columns([](Vec3d c) { return fm::xyz_to_rgb(fm::ycxcz_to_xyz(c)); });
  const auto rgb_to_xyz = columns([](Vec3d c) { return fm::rgb_to_xyz(c); });

  // Forward: the opponent channels, the luminance and their filtered planes.
  PlaneOf<T> y(w, h), cx(w, h), cz(w, h), lum(w, h);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const T* c = &rgb[3 * (static_cast<size_t>(j) * w + i)];
      const V v = fm::xyz_to_ycxcz(
          fm::rgb_to_xyz(V{srgb_decode(c[0]), srgb_decode(c[1]), srgb_decode(c[2])}));
      y.at(i, j) = v.x, cx.at(i, j) = v.y, cz.at(i, j) = v.z;
      lum.at(i, j) = (v.x + T(16)) / T(116);
    }
  const auto yf = separable_forward(y, csf.y, csf.y), cxf = separable_forward(cx, csf.cx, csf.cx);
  const auto cz1 = separable_forward(cz, csf.cz1, csf.cz1),
             cz2 = separable_forward(cz, csf.cz2, csf.cz2);
  const auto dxy = separable_forward(lum, feature.dg, feature.g),
             dyx = separable_forward(lum, feature.g, feature.dg);
  const auto ddxy = separable_forward(lum, feature.ddg, feature.g),
             ddyx = separable_forward(lum, feature.g, feature.ddg);

  // Per pixel, FLIP's value as flip() computes it (float) and its gradient
  // back to the filtered planes (double).
  const T cmax_f = fm::max_color_distance(), knee_f = T(fm::kPc) * cmax_f;
  const double cmax = cmax_f, knee = knee_f;
  const double qc = fm::kQc, qf = fm::kQf, pt = fm::kPt;
  const double g_pixel = 1.0 / static_cast<double>(pixels);
  double sum = 0;
  Plane g_yf(w, h), g_cxf(w, h), g_czf(w, h), g_dxy(w, h), g_dyx(w, h), g_ddxy(w, h), g_ddyx(w, h);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const size_t p = static_cast<size_t>(j) * w + i;
      const V rgb = fm::xyz_to_rgb(
          fm::ycxcz_to_xyz(V{yf.at(i, j), cxf.at(i, j), cz1.at(i, j) + cz2.at(i, j)}));
      const V rgbc = {std::clamp(rgb.x, T(0), T(1)), std::clamp(rgb.y, T(0), T(1)),
                      std::clamp(rgb.z, T(0), T(1))};
      const V v = fm::hunt(fm::xyz_to_lab(fm::rgb_to_xyz(rgbc)));
      const V ref = {reference.l[p], reference.a[p], reference.b[p]};
      const T c0_f = std::pow(fm::hyab(ref, v), T(fm::kQc));
      const T color_f = fm::remapped_color(c0_f, knee_f, cmax_f);
      const T edge = std::hypot(dxy.at(i, j), dyx.at(i, j)),
              point = std::hypot(ddxy.at(i, j), ddyx.at(i, j));
      const T de = edge - reference.edge[p], dp = point - reference.point[p];
      const T feat_f = fm::feature_difference(de, dp);
      sum += std::pow(color_f, 1 - feat_f);
      if (!gradient) continue;
      // The gradient, from flip()'s values.
      const double color = color_f, feat = feat_f, c0 = c0_f;
      if (color <= 0) continue;  // FLIP is 0 and flat in every direction that keeps it so
      // FLIP = color ^ (1 - feat).
      const double g_color = g_pixel * (1 - feat) * std::pow(color, -feat);
      const double g_feat = -g_pixel * std::log(color) * std::pow(color, 1 - feat);
      // The colour term, back to Hunt-adjusted Lab.
      const double dl = double(v.x) - ref.x, da = double(v.y) - ref.y, db = double(v.z) - ref.z;
      const double chroma = std::hypot(da, db);
      const double g_c0 = g_color * (c0 < knee ? pt / knee : (1 - pt) / (cmax - knee));
      const double g_dist = g_c0 * qc * c0 / (std::abs(dl) + chroma);  // qc d^(qc - 1)
      const double g_hl = g_dist * sign(dl);
      const double g_ha = chroma > 0 ? g_dist * da / chroma : 0;
      const double g_hb = chroma > 0 ? g_dist * db / chroma : 0;
      // Hunt: (L, 0.01 L a, 0.01 L b), from Lab before it.
      const Vec3d xyz = fm::rgb_to_xyz(Vec3d{rgbc.x, rgbc.y, rgbc.z});
      const Vec3d t = {xyz.x * fm::kInvWhite[0], xyz.y * fm::kInvWhite[1],
                       xyz.z * fm::kInvWhite[2]};
      const Vec3d lab = fm::xyz_to_lab(xyz);
      const double hunt = double(0.01f);
      const double g_l = g_hl + hunt * lab.y * g_ha + hunt * lab.z * g_hb;
      const double g_a = hunt * lab.x * g_ha, g_b = hunt * lab.x * g_hb;
      // Lab from f(X), f(Y), f(Z).
      const double g_fx = 500 * g_a, g_fy = 116 * g_l - 500 * g_a + 200 * g_b, g_fz = -200 * g_b;
      const Vec3d g_xyz = {g_fx * lab_f_slope(t.x) * fm::kInvWhite[0],
                           g_fy * lab_f_slope(t.y) * fm::kInvWhite[1],
                           g_fz * lab_f_slope(t.z) * fm::kInvWhite[2]};
      Vec3d g_rgb = transposed(rgb_to_xyz, g_xyz);
      // The gamut clamp passes the gradient inside [0, 1] only.
      if (rgb.x < 0 || rgb.x > 1) g_rgb.x = 0;
      if (rgb.y < 0 || rgb.y > 1) g_rgb.y = 0;
      if (rgb.z < 0 || rgb.z > 1) g_rgb.z = 0;
      const Vec3d g_opp = transposed(from_opponent, g_rgb);
      g_yf.at(i, j) = g_opp.x, g_cxf.at(i, j) = g_opp.y, g_czf.at(i, j) = g_opp.z;
      // The feature term: (max(|de|, |dp|) / sqrt 2) ^ qf, each a magnitude.
      const double m = std::max(std::abs(de), std::abs(dp));
      if (m <= 0) continue;
      const double g_m = g_feat * qf * feat / m;  // qf (m / sqrt 2)^(qf - 1) / sqrt 2
      const bool on_edge = std::abs(de) >= std::abs(dp);
      const double g_mag = g_m * sign(on_edge ? de : dp);
      const double a = on_edge ? dxy.at(i, j) : ddxy.at(i, j),
                   b = on_edge ? dyx.at(i, j) : ddyx.at(i, j);
      const double mag = on_edge ? edge : point;
      if (mag <= 0) continue;
      (on_edge ? g_dxy : g_ddxy).at(i, j) = g_mag * a / mag;
      (on_edge ? g_dyx : g_ddyx).at(i, j) = g_mag * b / mag;
    }
  FlipGradient out;
  out.mean = sum / static_cast<double>(pixels);
  if (!gradient) return out;

  // Back through the filters to the opponent channels and the luminance.
  Plane g_y = separable_transposed(g_yf, csf.y, csf.y);
  const Plane g_cx = separable_transposed(g_cxf, csf.cx, csf.cx);
  Plane g_cz = separable_transposed(g_czf, csf.cz1, csf.cz1);
  add(g_cz, separable_transposed(g_czf, csf.cz2, csf.cz2));
  Plane g_lum = separable_transposed(g_dxy, feature.dg, feature.g);
  add(g_lum, separable_transposed(g_dyx, feature.g, feature.dg));
  add(g_lum, separable_transposed(g_ddxy, feature.ddg, feature.g));
  add(g_lum, separable_transposed(g_ddyx, feature.g, feature.ddg));

  // To linear RGB, then through the sRGB transfer to the test's values.
  out.d_rgb.assign(rgb.size(), 0.0);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const Vec3d g_opp = {g_y.at(i, j) + g_lum.at(i, j) / 116, g_cx.at(i, j), g_cz.at(i, j)};
      const Vec3d g_lin = transposed(to_opponent, g_opp);
      const size_t k = 3 * (static_cast<size_t>(j) * w + i);
      out.d_rgb[k] = g_lin.x * srgb_to_linear_slope(rgb[k]);
      out.d_rgb[k + 1] = g_lin.y * srgb_to_linear_slope(rgb[k + 1]);
      out.d_rgb[k + 2] = g_lin.z * srgb_to_linear_slope(rgb[k + 2]);
    }
  return out;
}

void check_gradient_size(int w, int h) {
  if (static_cast<size_t>(w) * static_cast<size_t>(h) > kMaxFlipGradientPixels)
    throw ParameterError("size", fmt::format(": FLIP's gradient of {}x{} pixels is past the "
                                             "limit of {} (about 250 bytes a pixel)",
                                             w, h, kMaxFlipGradientPixels));
}

}  // namespace

FlipGradient flip_gradient(const FlipReference& reference, const ColorImage& test) {
  check_gradient_size(test.width, test.height);
  if (reference.width != test.width || reference.height != test.height || test.pixels() == 0)
    return {flip(reference, test).mean, {}};  // throws, naming the sizes
  return run(reference, test.width, test.height, test.rgb, true);
}

FlipGradient flip_gradient_in_double(const FlipReference& reference, const std::vector<double>& rgb,
                                     bool gradient) {
  check_gradient_size(reference.width, reference.height);
  const size_t pixels = static_cast<size_t>(reference.width) * reference.height;
  if (pixels == 0 || rgb.size() != 3 * pixels)
    throw Error(fmt::format("FLIP: {} test values for a {}x{} reference; expected three per pixel",
                            rgb.size(), reference.width, reference.height));
  return run(reference, reference.width, reference.height, rgb, gradient);
}

}  // namespace aapat

#include "aapat/analyze/flip_model.h"

#include <algorithm>
#include <cmath>

#include "aapat/core/geometry.h"

namespace aapat::flip_model {
namespace {

// The contrast sensitivity functions, each a * sqrt(pi / b) exp(-pi^2 x^2 / b)
// with x in degrees: Y and Cx one Gaussian, Cz the sum of two (paper Sec. 4.1).
constexpr float kAy = 1, kBy = 0.0047f, kAcx = 1, kBcx = 0.0053f;
constexpr float kAcz1 = 34.1f, kBcz1 = 0.04f, kAcz2 = 13.5f, kBcz2 = 0.025f;

}  // namespace

// The largest colour distance, green to blue, raised to qc. Computed at run
// time from an opaque 1: from constants the compiler may fold cbrtf correctly
// rounded, where glibc's cbrtf is 1 ulp lower for green's Y, so every FLIP
// value depended on whether this function was inlined (it was, once the
// layer compiled as one unity batch).
float max_color_distance() {
  volatile float one = 1.0f;
  const Vec3f green = hunt(xyz_to_lab(rgb_to_xyz(Vec3f{0, one, 0})));
  const Vec3f blue = hunt(xyz_to_lab(rgb_to_xyz(Vec3f{0, 0, one})));
  return std::pow(hyab(green, blue), kQc);
}

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

}  // namespace aapat::flip_model

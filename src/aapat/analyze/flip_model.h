// FLIP's model, the pieces that its value (analyze/flip.h) and its gradient
// (analyze/flip_gradient.h) share: the paper's constants, the colour
// conversions and the contrast sensitivity and feature filters. The
// conversions are templates so that the value computes in float, as the
// paper's code does, and the gradient in double.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "aapat/analyze/color_image.h"

namespace aapat::flip_model {

// The paper's constants: colour pipeline exponent qc, remapping knee pc
// (of the largest distance) and pt (the error it maps to); the feature
// filter's width w in degrees and exponent qf.
inline constexpr float kQc = 0.7f, kPc = 0.4f, kPt = 0.95f, kW = 0.082f, kQf = 0.5f;

// D65 white (color_image.h) and its inverse, as the paper's code rounds them.
inline constexpr std::array<float, 3> kWhite = {float(kD65White[0]), float(kD65White[1]),
                                                float(kD65White[2])};
inline constexpr std::array<float, 3> kInvWhite = {1.052156925f, 1.0f, 0.918357670f};

template <class T>
struct Vec3 {
  T x, y, z;
};
using Vec3f = Vec3<float>;

// Linear sRGB to XYZ (D65); the matrix's entries as exact fractions.
template <class T>
Vec3<T> rgb_to_xyz(Vec3<T> c) {
  return {T(10135552.0f / 24577794.0f) * c.x + T(8788810.0f / 24577794.0f) * c.y +
              T(4435075.0f / 24577794.0f) * c.z,
          T(2613072.0f / 12288897.0f) * c.x + T(8788810.0f / 12288897.0f) * c.y +
              T(887015.0f / 12288897.0f) * c.z,
          T(1425312.0f / 73733382.0f) * c.x + T(8788810.0f / 73733382.0f) * c.y +
              T(70074185.0f / 73733382.0f) * c.z};
}

template <class T>
Vec3<T> xyz_to_rgb(Vec3<T> c) {
  const std::array<T, 3> rgb = xyz_to_linear_rgb(c.x, c.y, c.z);
  return {rgb[0], rgb[1], rgb[2]};
}

// YyCxCz: CIELab with the cube root left out, so that it is linear in XYZ.
template <class T>
Vec3<T> xyz_to_ycxcz(Vec3<T> c) {
  const T x = c.x * T(kInvWhite[0]), y = c.y * T(kInvWhite[1]), z = c.z * T(kInvWhite[2]);
  return {T(116) * y - T(16), T(500) * (x - y), T(200) * (y - z)};
}

template <class T>
Vec3<T> ycxcz_to_xyz(Vec3<T> c) {
  const T y = (c.x + T(16)) / T(116);
  return {(y + c.y / T(500)) * T(kWhite[0]), y * T(kWhite[1]), (y - c.z / T(200)) * T(kWhite[2])};
}

// CIELab's f: the cube root above (6/29)^3, a line below.
inline constexpr float kLabDelta = 6.0f / 29.0f, kLabDelta3 = kLabDelta * kLabDelta * kLabDelta;
template <class T>
T lab_f(T t) {
  return t > T(kLabDelta3) ? std::cbrt(t) : t / (T(3) * T(kLabDelta) * T(kLabDelta)) + T(4) / T(29);
}

template <class T>
Vec3<T> xyz_to_lab(Vec3<T> c) {
  const T fx = lab_f(c.x * T(kInvWhite[0])), fy = lab_f(c.y * T(kInvWhite[1])),
          fz = lab_f(c.z * T(kInvWhite[2]));
  return {T(116) * fy - T(16), T(500) * (fx - fy), T(200) * (fy - fz)};
}

// The Hunt effect: chroma looks weaker in the dark, so a and b scale with L.
template <class T>
Vec3<T> hunt(Vec3<T> lab) {
  return {lab.x, T(0.01f) * lab.x * lab.y, T(0.01f) * lab.x * lab.z};
}

template <class T>
T hyab(Vec3<T> a, Vec3<T> b) {
  return std::abs(a.x - b.x) + std::hypot(a.y - b.y, a.z - b.z);
}

// The largest colour distance, green to blue, raised to qc (flip_model.cpp
// says why it is computed at run time).
float max_color_distance();

// Step 3's end: the HyAB distance raised to qc (c0), remapped to [0, 1]:
// below the knee (pc of the largest, `cmax`) to [0, pt], the rest to (pt, 1].
template <class T>
T remapped_color(T c0, T knee, T cmax) {
  return c0 < knee ? c0 * T(kPt) / knee : T(kPt) + (c0 - knee) / (cmax - knee) * (1 - T(kPt));
}

// Step 4's end: the larger difference of the edge and point strengths (de,
// dp: test minus reference, or the other way), over sqrt 2, raised to qf.
template <class T>
T feature_difference(T de, T dp) {
  return std::pow(std::max(std::abs(de), std::abs(dp)) / std::sqrt(T(2)), T(kQf));
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
CsfFilters csf_filters(double ppd);

// The feature filters: a Gaussian of 0.5 w ppd pixels (sum 1), its first
// and second derivatives (positive and negative lobes each of sum 1).
struct FeatureFilters {
  Taps g, dg, ddg;
};
FeatureFilters feature_filters(double ppd);

}  // namespace aapat::flip_model

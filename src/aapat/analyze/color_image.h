// A colour image as files and displays hold it: sRGB-encoded values in
// [0, 1], three per pixel (red, green, blue), rows from the top. A grey
// image has R = G = B.
#pragma once

#include <array>
#include <cmath>
#include <vector>

namespace aapat {

struct ColorImage {
  int width = 0, height = 0;
  std::vector<float> rgb;  // 3 * width * height
  size_t pixels() const { return static_cast<size_t>(width) * static_cast<size_t>(height); }
};

// The sRGB transfer function (IEC 61966-2-1) and its inverse.
inline float srgb_to_linear(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}
inline float linear_to_srgb(float c) {
  return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

// The D65 white point in XYZ (Y = 1), for CIELab and its relatives.
inline constexpr std::array<double, 3> kD65White = {0.950428545, 1.0, 1.088900371};

// CIE XYZ (D65) to linear sRGB, in the precision of T (FLIP computes in
// float, the FLIP map's colour scale in double); may leave [0, 1].
template <class T>
std::array<T, 3> xyz_to_linear_rgb(T x, T y, T z) {
  return {T(3.241003275) * x - T(1.537398934) * y - T(0.498615861) * z,
          T(-0.969224334) * x + T(1.875930071) * y + T(0.041554224) * z,
          T(0.055639423) * x - T(0.204011202) * y + T(1.057148933) * z};
}

}  // namespace aapat

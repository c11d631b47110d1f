// A texture as a shader reads it, for the tests' transcriptions of engine
// shaders: W x H texels of a value type T (double, or std::array<double, N>),
// uv in [0, 1] with texel (i, j)'s centre at ((i + 1/2) / W, (j + 1/2) / H),
// clamp-to-edge addressing. Independent of the library's history samplers,
// which the transcriptions are compared against.
#pragma once

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <vector>

namespace aapat::testing {

template <typename T>
struct GpuTexture {
  int W = 0, H = 0;
  std::vector<T> texels;  // row by row
  // An exact load (imageLoad, texelFetch), coordinates clamped.
  T load(int x, int y) const {
    return texels[static_cast<size_t>(std::clamp(y, 0, H - 1) * W + std::clamp(x, 0, W - 1))];
  }
  // A nearest sampler.
  T nearest(double u, double v) const {
    return load(static_cast<int>(std::floor(u * W)), static_cast<int>(std::floor(v * H)));
  }
  // A linear (bilinear) sampler.
  T linear(double u, double v) const {
    const double tx = u * W - 0.5, ty = v * H - 0.5;
    const int x0 = static_cast<int>(std::floor(tx)), y0 = static_cast<int>(std::floor(ty));
    const double fx = tx - x0, fy = ty - y0;
    T r{};
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) {
        const T c = load(x0 + i, y0 + j);
        const double w = (i ? fx : 1 - fx) * (j ? fy : 1 - fy);
        if constexpr (std::is_same_v<T, double>) {
          r += w * c;
        } else {
          for (size_t k = 0; k < r.size(); ++k) r[k] += w * c[k];
        }
      }
    return r;
  }
};

}  // namespace aapat::testing

// One render frame at ratio 1 with one sample per pixel, as the engines'
// native TAAs read it (ue4_main_pass.h, godot_taa.h, bevy_taa.h): the
// 3x3 samples around a pixel, coordinates clamped to the image (UE's
// clamped loads, Godot's clamped tile, Bevy's clamp-to-edge sampler).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>

namespace aapat {

// `channels` (3, RGB, or 1, grey) values per pixel, row by row.
struct SampleFrame {
  int width = 0, height = 0, channels = 1;
  const double* values = nullptr;
};

using FrameRgb = std::array<double, 3>;

// The 3x3 around (x, y) row by row from the smaller coordinate (the pixel
// at 4), as RGB: grey is read as R = G = B.
inline std::array<FrameRgb, 9> neighbourhood_3x3(const SampleFrame& f, int x, int y) {
  std::array<FrameRgb, 9> n{};
  for (int i = 0; i < 9; ++i) {
    const int sx = std::clamp(x + i % 3 - 1, 0, f.width - 1),
              sy = std::clamp(y + i / 3 - 1, 0, f.height - 1);
    const double* v =
        &f.values[(static_cast<size_t>(sy) * f.width + sx) * static_cast<size_t>(f.channels)];
    n[static_cast<size_t>(i)] =
        f.channels == 3 ? FrameRgb{v[0], v[1], v[2]} : FrameRgb{v[0], v[0], v[0]};
  }
  return n;
}

}  // namespace aapat

#include "aapat/io/flip_map.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "aapat/analyze/color_image.h"
#include "aapat/core/geometry.h"
#include "aapat/io/bitmap_font.h"

namespace aapat {

std::array<uint8_t, 3> flip_color(double v) {
  v = std::clamp(std::isfinite(v) ? v : 1.0, 0.0, 1.0);
  // CIELab (D65) to XYZ to linear sRGB to sRGB; colours outside the gamut
  // are clamped per channel (the chroma is chosen so that few are).
  const double lightness = 10 + 85 * v, chroma = 38, hue = radians(300 - 210 * v);
  const double a = chroma * std::cos(hue), b = chroma * std::sin(hue);
  const double fy = (lightness + 16) / 116, fx = fy + a / 500, fz = fy - b / 200;
  auto inverse = [](double t) {
    return t > 6.0 / 29 ? t * t * t : 3 * (6.0 / 29) * (6.0 / 29) * (t - 4.0 / 29);
  };
  const std::array<double, 3> rgb = xyz_to_linear_rgb(
      kD65White[0] * inverse(fx), kD65White[1] * inverse(fy), kD65White[2] * inverse(fz));
  std::array<uint8_t, 3> out{};
  for (int c = 0; c < 3; ++c)
    out[c] = static_cast<uint8_t>(
        std::lround(255 * linear_to_srgb(static_cast<float>(std::clamp(rgb[c], 0.0, 1.0)))));
  return out;
}

RgbRaster flip_map_with_scale(const std::vector<float>& map, int width, int height) {
  // The map in 1024 steps, each colour computed once.
  constexpr int kSteps = 1024;
  std::array<std::array<uint8_t, 3>, kSteps> lut;
  for (int k = 0; k < kSteps; ++k) lut[k] = flip_color(static_cast<double>(k) / (kSteps - 1));
  auto color = [&](float v) {
    return lut[static_cast<size_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * (kSteps - 1)))];
  };
  // The legend: a bar the width of the map (at least 64 pixels), then the
  // labels 0, 0.5 and 1 in a row of text under it.
  const int bar = 10, gap = 3, text = kGlyphHeight + 2;
  const int w = std::max(width, 64), h = height + gap + bar + gap + text;
  RgbRaster out{w, h, std::vector<uint8_t>(static_cast<size_t>(w) * h * 3, 0)};
  auto put = [&](int x, int y, std::array<uint8_t, 3> c) {
    std::copy(c.begin(), c.end(), out.pixels.begin() + 3 * (static_cast<size_t>(y) * w + x));
  };
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) put(i, j, color(map[static_cast<size_t>(j) * width + i]));
  for (int j = height + gap; j < height + gap + bar; ++j)
    for (int i = 0; i < w; ++i) put(i, j, flip_color(static_cast<double>(i) / (w - 1)));
  GreyRaster labels(w, text, 0);
  draw_text(labels, 0, 1, "0", 1, 255);
  draw_text(labels, (w - text_width("0.5", 1)) / 2, 1, "0.5", 1, 255);
  draw_text(labels, w - text_width("1", 1), 1, "1", 1, 255);
  for (int j = 0; j < text; ++j)
    for (int i = 0; i < w; ++i) {
      const uint8_t g = labels.pixels[static_cast<size_t>(j) * w + i];
      put(i, height + gap + bar + gap + j, {g, g, g});
    }
  return out;
}

}  // namespace aapat

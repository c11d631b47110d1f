#include "io/pattern_svg.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "io/xml.h"

namespace aapat {

std::string pattern_svg(const Pattern& p) {
  constexpr double kScale = 160;   // SVG units per pixel
  constexpr double kMargin = 0.3;  // pixels of space around the drawing
  constexpr double kCaption = 40;
  const Footprint& f = p.footprint;
  const int first = f.size == 1 ? 0 : 1 - f.size / 2;
  // Pixels shown: the tile and kernel 0's footprint.
  const int x0 = std::min(0, first), y0 = std::min(0, first);
  const int x1 = std::max(p.tile_w, first + f.size), y1 = std::max(p.tile_h, first + f.size);
  const double width = std::max(560.0, (x1 - x0 + 2 * kMargin) * kScale);
  const double height = (y1 - y0 + 2 * kMargin) * kScale + kCaption;
  // World (pixel centres at integers, y up) to SVG (y down).
  auto sx = [&](double x) { return (x - (x0 - 0.5) + kMargin) * kScale; };
  auto sy = [&](double y) { return (y1 - 0.5 - y + kMargin) * kScale; };

  std::string svg = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{:.0f}\" height=\"{:.0f}\" "
      "viewBox=\"0 0 {:.0f} {:.0f}\" font-family=\"sans-serif\">\n"
      "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n",
      width, height, width, height);
  // Kernel 0's footprint, shaded.
  const double o = f.size == 1 ? 0.0 : 0.5;
  svg += fmt::format(
      "<rect x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" height=\"{:.2f}\" fill=\"#dde8f6\"/>\n",
      sx(first - 0.5), sy(first + f.size - 0.5), f.size * kScale, f.size * kScale);
  // Pixel grid; the tile's pixels drawn darker than the neighbours shown.
  for (int j = y0; j < y1; ++j)
    for (int i = x0; i < x1; ++i) {
      const bool in_tile = i >= 0 && j >= 0 && i < p.tile_w && j < p.tile_h;
      svg += fmt::format(
          "<rect x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" height=\"{:.2f}\" fill=\"none\" "
          "stroke=\"{}\" stroke-width=\"{}\"/>\n",
          sx(i - 0.5), sy(j + 0.5), kScale, kScale, in_tile ? "#333" : "#bbb", in_tile ? 2 : 1);
    }
  // Every physical sample of the pixels shown, as a small dot.
  for (int j = y0; j < y1; ++j)
    for (int i = x0; i < x1; ++i) {
      const int tx = ((i % p.tile_w) + p.tile_w) % p.tile_w;
      const int ty = ((j % p.tile_h) + p.tile_h) % p.tile_h;
      for (const Vec2& s : p.sets[ty * p.tile_w + tx])
        svg += fmt::format("<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"3\" fill=\"#555\"/>\n",
                           sx(i + s.x), sy(j + s.y));
    }
  // Kernel 0's weights: disc area proportional to |weight|.
  const auto samples = kernel_samples(p, 0);
  for (size_t i = 0; i < samples.size(); ++i) {
    const double w = p.weights[0][i];
    const double r = 0.22 * std::sqrt(std::abs(w)) * kScale;
    const Vec2 pos{samples[i].pos.x + o, samples[i].pos.y + o};
    svg += w >= 0
               ? fmt::format(
                     "<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"{:.2f}\" fill=\"#1f5fa8\" "
                     "fill-opacity=\"0.75\"><title>w = {:.6g}</title></circle>\n",
                     sx(pos.x), sy(pos.y), r, w)
               : fmt::format(
                     "<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"{:.2f}\" fill=\"none\" "
                     "stroke=\"#c0392b\" stroke-width=\"2\"><title>w = {:.6g}</title></circle>\n",
                     sx(pos.x), sy(pos.y), r, w);
  }
  svg += fmt::format(
      "<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"14\">{} {}: n = {}; disc areas are kernel 0's "
      "weights</text>\n</svg>\n",
      8.0, height - 14, xml_escape(p.name), family(p), format_cost(samples_per_pixel(p)));
  return svg;
}

}  // namespace aapat

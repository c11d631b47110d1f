#include "aapat/io/pattern_svg.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "aapat/io/xml.h"

namespace aapat {
namespace {

// A sample of weight w at SVG point (cx, cy): a disc whose area is
// proportional to |w| (a red ring when w < 0); `pixel` is the pixel's size.
std::string weight_disc(double cx, double cy, double w, double pixel) {
  const double r = 0.22 * std::sqrt(std::abs(w)) * pixel;
  if (w >= 0)
    return fmt::format(
        "<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"{:.2f}\" fill=\"#1f5fa8\" fill-opacity=\"0.75\">"
        "<title>w = {:.6g}</title></circle>\n",
        cx, cy, r, w);
  return fmt::format(
      "<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"{:.2f}\" fill=\"none\" stroke=\"#c0392b\" "
      "stroke-width=\"2\"><title>w = {:.6g}</title></circle>\n",
      cx, cy, r, w);
}

}  // namespace

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
    const Vec2 pos{samples[i].pos.x + o, samples[i].pos.y + o};
    svg += weight_disc(sx(pos.x), sy(pos.y), w, kScale);
  }
  svg += fmt::format(
      "<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"14\">{} {}: n = {}; disc areas are kernel 0's "
      "weights</text>\n</svg>\n",
      8.0, height - 14, xml_escape(p.name), family(p), format_cost(samples_per_pixel(p)));
  return svg;
}

std::string gallery_svg(const std::vector<GalleryItem>& items, int columns,
                        const std::string& title) {
  constexpr double kPixel = 110, kCell = 190, kCaption = 46, kTop = 36;
  columns = std::max(1, columns);
  const int rows = (static_cast<int>(items.size()) + columns - 1) / columns;
  const double width = columns * kCell, height = kTop + rows * (kCell + kCaption);
  std::string svg = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0:.0f}\" height=\"{1:.0f}\" "
      "viewBox=\"0 0 {0:.0f} {1:.0f}\" font-family=\"sans-serif\" font-size=\"12\">\n"
      "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      "<text x=\"10\" y=\"24\" font-size=\"15\">{2}</text>\n",
      std::max(width, 420.0), height, xml_escape(title));
  for (size_t i = 0; i < items.size(); ++i) {
    const Pattern& p = items[i].pattern;
    const double cx = (i % columns + 0.5) * kCell;
    const double cy = kTop + (i / columns) * (kCell + kCaption) + kCell / 2;
    svg += fmt::format(
        "<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{}\" height=\"{}\" fill=\"#f4f7fb\" "
        "stroke=\"#333\" stroke-width=\"1.5\"/>\n",
        cx - kPixel / 2, cy - kPixel / 2, kPixel, kPixel);
    // Kernel 0 of a one-pixel footprint reads its own set, in set order.
    const auto samples = kernel_samples(p, 0);
    const double o = p.footprint.size == 1 ? 0.0 : 0.5;
    for (size_t k = 0; k < samples.size(); ++k)
      svg += weight_disc(cx + (samples[k].pos.x + o) * kPixel, cy - (samples[k].pos.y + o) * kPixel,
                         p.weights[0][k], kPixel);
    svg += fmt::format(
        "<text x=\"{0:.1f}\" y=\"{1:.1f}\" text-anchor=\"middle\">{2}</text>\n"
        "<text x=\"{0:.1f}\" y=\"{3:.1f}\" text-anchor=\"middle\" fill=\"#555\">{4}</text>\n",
        cx, cy + kCell / 2 + 6, xml_escape(items[i].caption), cy + kCell / 2 + 22,
        xml_escape(items[i].detail));
  }
  return svg + "</svg>\n";
}

}  // namespace aapat

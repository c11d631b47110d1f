#include "aapat/io/contact_sheet.h"

#include <fmt/format.h>

#include <algorithm>

#include "aapat/core/geometry.h"

namespace aapat {
namespace {

constexpr int kMargin = 10, kLabelScale = 2, kCaptionScale = 1, kBlack = 0, kFrame = 128;

}  // namespace

SheetRaster compose_sheet(const ContactSheet& s) {
  const size_t rows = s.row_labels.size(), cols = s.column_labels.size();
  if (rows == 0 || cols == 0 || s.cells.size() != rows * cols || s.zoom < 1 || s.zoom > 64)
    throw Error(fmt::format("contact sheet: {} cells for {} rows x {} columns (zoom {})",
                            s.cells.size(), rows, cols, s.zoom));
  bool colour = false;
  for (const SheetCell& c : s.cells) {
    if ((c.channels != 1 && c.channels != 3) ||
        c.pixels.size() != static_cast<size_t>(c.width) * c.height * c.channels)
      throw Error(fmt::format("contact sheet: a {}x{} cell of {} channel(s) holds {} bytes",
                              c.width, c.height, c.channels, c.pixels.size()));
    colour = colour || c.channels == 3;
  }
  int cell_w = 0, cell_h = 0;
  for (const SheetCell& c : s.cells) {
    cell_w = std::max({cell_w, c.width * s.zoom, text_width(c.caption, kCaptionScale)});
    cell_h = std::max(cell_h, c.height * s.zoom);
  }
  int label_w = 0;
  for (const auto& l : s.row_labels) label_w = std::max(label_w, text_width(l, kLabelScale));
  for (const auto& l : s.column_labels) cell_w = std::max(cell_w, text_width(l, kLabelScale));
  const int line = kGlyphHeight * kLabelScale, caption = kGlyphHeight * kCaptionScale;
  const int title_h = s.title.empty() ? 0 : line + kMargin;
  const int x0 = kMargin + label_w + kMargin, y0 = kMargin + title_h + line + kMargin;
  const int pitch_x = cell_w + kMargin, pitch_y = cell_h + 4 + caption + kMargin;
  const int width = std::max(x0 + static_cast<int>(cols) * pitch_x,
                             2 * kMargin + text_width(s.title, kLabelScale));
  GreyRaster r(width, y0 + static_cast<int>(rows) * pitch_y, 255);
  // A colour cell's pixels, kept apart until the grey layout is done.
  std::vector<std::pair<size_t, size_t>> colour_pixels;  // raster index, cell byte
  if (!s.title.empty()) draw_text(r, kMargin, kMargin, s.title, kLabelScale, kBlack);
  for (size_t c = 0; c < cols; ++c)
    draw_text(r, x0 + static_cast<int>(c) * pitch_x, kMargin + title_h, s.column_labels[c],
              kLabelScale, kBlack);
  for (size_t row = 0; row < rows; ++row) {
    const int y = y0 + static_cast<int>(row) * pitch_y;
    draw_text(r, kMargin, y + (cell_h - line) / 2, s.row_labels[row], kLabelScale, kBlack);
    for (size_t c = 0; c < cols; ++c) {
      const SheetCell& cell = s.cells[row * cols + c];
      const int x = x0 + static_cast<int>(c) * pitch_x;
      const int w = cell.width * s.zoom, h = cell.height * s.zoom;
      for (int py = -1; py <= h; ++py)  // a one-pixel frame, then the image
        for (int px = -1; px <= w; ++px) {
          const bool frame = px < 0 || py < 0 || px == w || py == h;
          const size_t at = frame ? 0
                                  : (static_cast<size_t>(py / s.zoom) * cell.width + px / s.zoom) *
                                        static_cast<size_t>(cell.channels);
          r.set(x + px, y + py, frame ? kFrame : cell.pixels[at]);
          if (!frame && cell.channels == 3 && x + px < r.width && y + py < r.height)
            colour_pixels.emplace_back(static_cast<size_t>(y + py) * r.width + (x + px),
                                       ((row * cols + c) << 32) | at);
        }
      draw_text(r, x, y + cell_h + 4, cell.caption, kCaptionScale, kBlack);
    }
  }
  SheetRaster out{r.width, r.height, colour ? 3 : 1, std::move(r.pixels)};
  if (!colour) return out;
  std::vector<uint8_t> rgb(out.pixels.size() * 3);
  for (size_t k = 0; k < out.pixels.size(); ++k)
    rgb[3 * k] = rgb[3 * k + 1] = rgb[3 * k + 2] = out.pixels[k];
  for (const auto& [index, source] : colour_pixels) {
    const SheetCell& cell = s.cells[source >> 32];
    const size_t at = source & 0xffffffffu;
    for (size_t ch = 0; ch < 3; ++ch) rgb[3 * index + ch] = cell.pixels[at + ch];
  }
  out.pixels = std::move(rgb);
  return out;
}

}  // namespace aapat

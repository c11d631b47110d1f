// A contact sheet: images in a labelled grid (rows x columns) with a caption
// under each, drawn into one grey raster (Goss & Wu Figs. 9-20 side by side),
// or an RGB one when a cell is in colour (a mesh scene's renderings).
#pragma once

#include <string>
#include <vector>

#include "aapat/io/bitmap_font.h"

namespace aapat {

inline constexpr int kMaxSheetZoom = 16;

struct SheetCell {
  int width = 0, height = 0;
  std::vector<uint8_t> pixels;  // rows top-down, `channels` bytes a pixel
  std::string caption;          // one line under the image
  int channels = 1;             // 1 grey, 3 RGB
};

struct ContactSheet {
  std::string title;
  std::vector<std::string> row_labels, column_labels;
  std::vector<SheetCell> cells;  // row by row
  int zoom = 1;                  // each image pixel drawn as zoom x zoom, 1 to kMaxSheetZoom
};

struct SheetRaster {
  int width = 0, height = 0, channels = 1;  // 3 when any cell is RGB
  std::vector<uint8_t> pixels;              // rows top-down
};
SheetRaster compose_sheet(const ContactSheet& sheet);

}  // namespace aapat

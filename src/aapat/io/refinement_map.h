// The refinement map of an adaptive rendering: samples per pixel as grey,
// log scaled from the fewest (black) to the most (white), and the same with a
// legend bar under it labelled with the counts, as one raster for a PNG.
#pragma once

#include <cstdint>
#include <vector>

#include "aapat/io/bitmap_font.h"

namespace aapat {

// Rows top-down (the map's rows run from the bottom); `lo`..`hi` the counts
// black and white stand for.
std::vector<uint8_t> refinement_map_pixels(const std::vector<int>& samples, int width, int height,
                                           int lo, int hi);
// The map scaled to its own fewest and most, with the legend.
GreyRaster refinement_map_with_legend(const std::vector<int>& samples, int width, int height);

}  // namespace aapat

// An SVG drawing of a pattern in the manner of Hasselgren et al. Fig. 3: the
// pixel grid of the tile, every physical sample as a dot, and the first
// kernel's samples as discs whose area is proportional to their weight
// (negative weights as red rings).
#pragma once

#include <string>
#include <vector>

#include "aapat/core/pattern.h"

namespace aapat {

std::string pattern_svg(const Pattern& p);

// Several patterns side by side, each its kernel 0's pixel with the samples
// as weight discs and two lines of caption (Hasselgren et al. Fig. 3).
struct GalleryItem {
  Pattern pattern;
  std::string caption, detail;
};
std::string gallery_svg(const std::vector<GalleryItem>& items, int columns,
                        const std::string& title);

}  // namespace aapat

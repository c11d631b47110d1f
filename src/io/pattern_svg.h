// An SVG drawing of a pattern in the manner of Hasselgren et al. Fig. 3: the
// pixel grid of the tile, every physical sample as a dot, and the first
// kernel's samples as discs whose area is proportional to their weight
// (negative weights as red rings).
#pragma once

#include <string>

#include "core/pattern.h"

namespace aapat {

std::string pattern_svg(const Pattern& p);

}  // namespace aapat

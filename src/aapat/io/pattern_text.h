// Laine's pattern text (.xyw): one line "x y weight" per sample of a
// one-pixel pattern, P(1,1,n), coordinates in pixels from the pixel centre ([-1/2, 1/2]), '#'
// comments. The format the Laine-Aila optimizer's patterns are usually exchanged in: positions and
// the resolve weights, nothing else.
#pragma once

#include <string>
#include <string_view>

#include "aapat/core/pattern.h"

namespace aapat {

// Error for a pattern with more than one set (a tile) or a kernel that reads
// beyond the pixel's own samples (footprints larger than one pixel).
std::string pattern_to_text(const Pattern& p);
Pattern pattern_from_text(std::string_view text, std::string_view source);

}  // namespace aapat

// Patterns over time: a sequence is K frame patterns used in turn, frame t
// rendered with pattern t mod K. A TAA or upscaler jitter is a one-sample
// pattern P(1,1,1) moved from frame to frame; an alternating MSAA scheme has
// several samples per frame; any frame may be a tile with shared borders, as
// long as every frame has the same tile and footprint (the same family), so
// that an accumulation of frames reads the same layout of pixels.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "aapat/core/pattern.h"

namespace aapat {

inline constexpr int kMaxSequenceFrames = 1024;

struct Sequence {
  std::string name, description;
  std::vector<Pattern> frames;
  std::vector<std::pair<std::string, std::string>> provenance;
  int period() const { return static_cast<int>(frames.size()); }
};

// Throws Error naming the problem: no frames, more than kMaxSequenceFrames, a
// frame that is not a valid pattern (validate(Pattern)), frames whose tiles
// or footprints disagree.
void validate(const Sequence& s);

// A one-sample frame: the jitter (x, y) in pixel units, in [-1/2, 1/2].
Pattern jitter_frame(Vec2 offset, std::string name);

// Every sample of every frame in time order (frame 0's first): the points the
// accumulation sees, for prefixes, discrepancy and spectra.
std::vector<Vec2> samples_in_order(const Sequence& s);

}  // namespace aapat

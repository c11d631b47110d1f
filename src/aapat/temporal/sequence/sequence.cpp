#include "aapat/temporal/sequence/sequence.h"

#include <fmt/format.h>

#include <cmath>

namespace aapat {

void validate(const Sequence& s) {
  if (s.frames.empty()) throw Error(fmt::format("sequence {}: it has no frames", s.name));
  if (s.period() > kMaxSequenceFrames)
    throw Error(fmt::format("sequence {}: {} frames exceed the limit of {}", s.name, s.period(),
                            kMaxSequenceFrames));
  const Pattern& first = s.frames.front();
  for (int f = 0; f < s.period(); ++f) {
    const Pattern& p = s.frames[static_cast<size_t>(f)];
    try {
      validate(p);
    } catch (const Error& e) {
      throw Error(fmt::format("sequence {}: frame {}: {}", s.name, f, e.what()));
    }
    if (p.tile_w != first.tile_w || p.tile_h != first.tile_h || !(p.footprint == first.footprint))
      throw Error(fmt::format(
          "sequence {}: frame {} is a {}x{} tile with footprint {}, frame 0 a {}x{} tile with "
          "footprint {}: every frame must have the same tile and footprint",
          s.name, f, p.tile_w, p.tile_h, p.footprint.text(), first.tile_w, first.tile_h,
          first.footprint.text()));
  }
}

Pattern jitter_frame(Vec2 offset, std::string name) {
  return single_pixel_pattern(std::move(name), {offset}, {1.0});
}

std::vector<Vec2> samples_in_order(const Sequence& s) {
  std::vector<Vec2> out;
  for (const Pattern& p : s.frames)
    for (const auto& set : p.sets) out.insert(out.end(), set.begin(), set.end());
  return out;
}

}  // namespace aapat

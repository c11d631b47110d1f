// Grey textures: an image of texels in [0, 1] that repeats over the plane of
// its texture coordinates. A texture is a function of (s, t) in texel units:
// texel (i, j) covers [i, i+1) x [j, j+1), row 0 at the bottom (t up), and
// its exact (unfiltered) value at a point is the texel that holds it, what
// a reference renders. Procedural textures are rasterized once at a chosen
// size; a PNG file is read by io/texture_file.h.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "aapat/core/geometry.h"
#include "aapat/core/spec.h"

namespace aapat {

inline constexpr int kMaxTextureSide = 8192;

struct Texture {
  std::string name;  // the spec or file it came from (reports)
  int width = 0, height = 0;
  std::vector<double> texels;  // row j from the bottom, then column i

  // Texel (i, j), repeating in both directions.
  double at(int i, int j) const;
  // The exact value at (s, t) in texel units: the texel that holds the point.
  double exact(double s, double t) const;
  // A 64-bit hash of the size and the texels' bits: the reference cache's key.
  uint64_t content_hash() const;
};

// Checks the size (1 to kMaxTextureSide per side) and that every texel is
// finite and in [0, 1]; `what` names the texture in errors.
void validate(const Texture& t, std::string_view what);

// `checker:cells=8,size=256`, `stripes:cells=16,size=256`,
// `zoneplate:size=512`, `noise:size=256,seed=1` (text-like strokes).
using TextureRegistry = Registry<Texture>;
const TextureRegistry& texture_registry();
Texture make_texture(std::string_view spec);

}  // namespace aapat

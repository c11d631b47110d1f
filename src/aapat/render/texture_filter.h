// Texture filtering as the CS4620 lecture describes it: a mipmap pyramid
// built once per texture (each level's texel the average of its 2 x 2
// children, or a Gaussian-prefiltered variant), the level of detail from the
// pixel's Jacobian d(s, t)/d(x, y) by either of the lecture's formulas, and
// the lookups hardware offers: nearest texel, bilinear in the finest level,
// nearest level (point), bilinear in one level, trilinear between two levels,
// and anisotropic (several trilinear probes along the footprint's major
// axis). Texture coordinates are in texels of level 0 (texture.h); the
// texture repeats.
#pragma once

#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

#include "aapat/render/texture.h"

namespace aapat {

enum class MipmapKind {
  box,       // each texel the mean of its 2 x 2 children (the lecture's "average")
  gaussian,  // the finer level blurred by the binomial [1 3 3 1] / 8 (a Gaussian of
             // sigma 0.87 texel), centred between the children, then halved
};

// Level 0 is the texture; each next level half the size (rounded up) down
// to 1 x 1. Odd sizes: a texel averages the children that exist.
struct Mipmap {
  std::vector<Texture> levels;
};
Mipmap build_mipmap(const Texture& texture, MipmapKind kind);

// d(s, t)/dx and d(s, t)/dy in texels of level 0 per pixel.
struct TextureJacobian {
  double dsdx = 0, dtdx = 0, dsdy = 0, dtdy = 0;
};

// The lecture's two formulas for the level:
//   max: log2 max(|ds/dx|, |dt/dx|, |ds/dy|, |dt/dy|),
//   root-sum-squares: log2 sqrt(ds/dx^2 + dt/dx^2 + ds/dy^2 + dt/dy^2).
enum class LodFormula { max, root_sum_squares };
// The level of detail, unclamped (below 0: magnified; -infinity for a
// footprint of no size).
double level_of_detail(const TextureJacobian& j, LodFormula formula);

enum class TextureLookup { nearest, bilinear, mip_nearest, mip_bilinear, trilinear, aniso };

// A named texture filter: `nearest`, `bilinear`, `mip-nearest`,
// `mip-bilinear`, `trilinear`, `aniso:probes=8`, with the level formula and
// the pyramid it reads.
struct TextureFilter {
  TextureLookup lookup = TextureLookup::nearest;
  int probes = 8;  // aniso: the most trilinear probes along the major axis
  LodFormula lod = LodFormula::max;
  MipmapKind mipmap = MipmapKind::box;
  std::string name = "nearest";
  // The lookup reads only level 0 at the point itself: the exact texel.
  bool exact() const { return lookup == TextureLookup::nearest; }
};
using TextureFilterRegistry = Registry<TextureFilter>;
const TextureFilterRegistry& texture_filter_registry();
TextureFilter make_texture_filter(std::string_view spec, LodFormula lod = LodFormula::max,
                                  MipmapKind mipmap = MipmapKind::box);
LodFormula parse_lod_formula(std::string_view text);  // "max" or "root-sum-squares"
MipmapKind parse_mipmap_kind(std::string_view text);  // "box" or "gaussian"

// A texture with its pyramids, shared by every sample: the box pyramid built
// with it, the Gaussian one on first use (most renderings never ask for it,
// and a model's large textures would pay for it three times, once a channel).
struct TexturedSurface {
  Texture texture;
  Mipmap box;
  explicit TexturedSurface(Texture t);
  const Mipmap& pyramid(MipmapKind kind) const;

 private:
  mutable std::once_flag gaussian_built_;
  mutable Mipmap gaussian_;
};

// The filtered value at (s, t) with the footprint `j`; `probes`, when given,
// gains the number of lookups made (1, or the anisotropic probes).
double filtered_value(const TexturedSurface& surface, const TextureFilter& filter, double s,
                      double t, const TextureJacobian& j, int* probes = nullptr);

// Bilinear interpolation in one level at level-0 coordinates (s, t), and
// trilinear at a fractional level: the building blocks, exposed for tests.
double bilinear(const Mipmap& m, int level, double s, double t);
double trilinear(const Mipmap& m, double level, double s, double t);

}  // namespace aapat

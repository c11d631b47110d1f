// The supersampling renderer: samples an analytic scene with any pattern and
// reconstructs each output pixel, in parallel over rows (oneTBB, the result
// independent of the thread count).
//
// Sampling: a pattern tiled over the image (its s sets; a shared border
// sample is one sample, owned by the pixel that holds it at -1/2), or a
// per-pixel generator (each pixel its own points from (seed, x, y)).
// Reconstruction: the pattern's own kernel weights, or a reference filter
// h(dx) h(dy) at the sample offsets, normalized by the weights' sum (Goss &
// Wu's normalized discrete filter).
//
// Shading (the CS4620 lecture's supersampling against multisampling):
// supersampling evaluates the scene at every sample; multisampling takes
// only coverage (the primitive, render/surface.h) at every sample and shades
// each primitive once per pixel, at the pixel centre or the centroid of the
// samples it covers, copying the value to those samples. Textures are read
// through a texture filter (render/texture_filter.h); supersampling's
// lookups see a footprint of 1 / sqrt(samples per pixel) pixel.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "aapat/core/filter.h"
#include "aapat/core/pattern.h"
#include "aapat/render/scene.h"
#include "aapat/render/texture_filter.h"

namespace aapat {

struct Image {
  int width = 0, height = 0;
  double offset = 0;           // output pixel (i, j) is the value at (i + offset, j + offset)
  std::vector<double> values;  // row j (from the bottom) then column i, then channel
  int channels = 1;            // 1: grey; 3: R, G, B (a mesh scene, render/color_render.h)
  double at(int i, int j) const { return values[static_cast<size_t>(j) * width + i]; }
  size_t pixels() const { return static_cast<size_t>(width) * static_cast<size_t>(height); }
};

enum class ShadingMode { supersample, multisample };
enum class ShadingPoint { centre, centroid };
struct Shading {
  ShadingMode mode = ShadingMode::supersample;
  ShadingPoint point = ShadingPoint::centre;  // multisampling's
  TextureFilter texture;                      // nearest: the exact texel
  // Supersampling the exact texels: every sample is shade(scene, p).
  bool exact() const { return mode == ShadingMode::supersample && texture.exact(); }
};
ShadingMode parse_shading_mode(std::string_view text);    // supersample, multisample
ShadingPoint parse_shading_point(std::string_view text);  // centre (center), centroid
// The names the parsers read (the reports' names): "supersample", "centre", ...
std::string_view shading_mode_name(ShadingMode mode);
std::string_view shading_point_name(ShadingPoint point);

struct Sampling {
  std::optional<Pattern> pattern;  // tiled over the image, or
  std::string generator;           // per-pixel generator spec, with
  int samples = 16;                //   samples per pixel
  uint64_t seed = 1;
  Shading shading;
};

struct RenderStats {
  double samples_per_pixel = 0;   // distinct scene samples taken per pixel
  double lookups_per_pixel = 0;   // texture lookups (anisotropic probes counted) per pixel
  double shadings_per_pixel = 0;  // shading evaluations per pixel (multisampling: per primitive)
};

// filter empty: the pattern's own kernel weights (a pattern is required).
// With a filter, output pixel (i, j) is reconstructed at (i + offset, j + offset),
// so that a reference can match a rendering shifted by an even footprint.
Image render(const Scene& scene, int width, int height, const Sampling& sampling,
             const std::optional<Filter>& filter, RenderStats* stats = nullptr, double offset = 0);

// render_rows' bands start at a multiple of this many rows (with a filter
// the rows are rendered in blocks of four times as many; an output pixel's
// value does not depend on the blocks).
inline constexpr int kRenderBlockRows = 8;
// The largest image side render takes (pixels), and the most samples per pixel
// of a pattern, a generator or a reference.
inline constexpr int kMaxImageSide = 16384;
inline constexpr int kMaxSamplesPerPixel = 65536;
// Rows [row_begin, row_end) of render(scene, width, height, sampling, filter,
// nullptr, offset), bit for bit, as an image of those rows alone; row_begin
// is a multiple of kRenderBlockRows. A reference renders in such bands, each
// a work item (render/reference.h).
Image render_rows(const Scene& scene, int width, int height, const Sampling& sampling,
                  const Filter& filter, double offset, int row_begin, int row_end);

}  // namespace aapat

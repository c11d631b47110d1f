// Renderings measured against their dense reference, as `aapat render` and
// `aapat.render` make them: one scene with one sampling and filter, or a
// contact sheet of samplings (rows) by filters (columns) with the error
// figures of every cell; either supersampled or multisampled, through a
// texture filter, or refined adaptively.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "aapat/render/adaptive.h"
#include "aapat/render/image_error.h"
#include "aapat/render/reference.h"
#include "aapat/study/progress.h"

namespace aapat {

// The scene seen through a view: rotated by `rotate_deg` and scaled about the
// image centre, then moved by `translation` pixels; refused when not finite
// or out of range.
Scene view_scene(Scene scene, int width, int height, double rotate_deg, double scale,
                 Vec2 translation);

struct RenderFigures {
  ImageError error;
  std::optional<double> ssim;  // for images at least one SSIM window wide and high
  double flip = 0;             // the mean FLIP (render/image_flip.h)
};
RenderFigures measure(const Image& image, const Image& reference);

// A sampling named as a sheet row names it: GENERATOR@N (a per-pixel
// generator with N samples) or a catalog pattern / pattern file.
Sampling parse_sampling(const std::string& row, uint64_t seed);

// How a rendering shades and refines, set by `+KEY=VALUE` options after a
// sheet row or column (`msaa-4+mode=multisample+texture-filter=trilinear`):
// mode, shading-point, texture-filter, lod, mipmap; adaptive (a criterion),
// threshold, max-depth, max-samples, per-square; show (image or map); label
// (the sheet's name for it).
struct RenderOptions {
  std::string mode = "supersample", shading_point = "centre", texture_filter = "nearest",
              lod = "max", mipmap = "box";
  std::string adaptive;  // empty: no refinement; else the criterion
  double threshold = 0.1;
  int max_depth = 3, max_samples = 64, per_square = 2;
  bool show_map = false;  // a sheet cell shows the refinement map
  std::string label;      // the sheet's label for the row or column (default: its text)
  // Sets KEY from VALUE; `where` names the row or column in errors.
  void set(const std::string& key, const std::string& value, const std::string& where);
  Shading shading() const;
  // The adaptive settings for an initial sampling, when adaptive is set.
  std::optional<AdaptiveSettings> adaptive_settings(const Sampling& initial) const;
};
// "BASE+KEY=VALUE+..." into BASE and the options it sets on `options`.
std::string split_options(const std::string& text, RenderOptions& options);

struct RenderSettings {
  int width = 256, height = 256;
  Sampling sampling;             // its shading: supersampling or multisampling, texture filter
  std::optional<Filter> filter;  // none: the pattern's own weights
  std::optional<AdaptiveSettings> adaptive;  // refine from `sampling` (render/adaptive.h)
  bool measure = false;                      // render the reference and compare
  ReferenceSettings reference;
};
struct RenderResult {
  Image image;
  RenderStats stats;
  std::optional<AdaptiveImage> adaptive;  // the refinement map and its counts
  std::optional<Image> reference;         // when measured
  std::optional<RenderFigures> figures;
};
// The one check of a single rendering's settings, whatever face built them:
// ParameterError("size") for a side outside [1, kMaxImageSide], Error unless
// exactly one of a pattern and a generator is given, ParameterError
// ("generator") for per-pixel points without a filter (they have no weights).
// render_study calls it before any work.
void validate(const RenderSettings& settings);
RenderResult render_study(const Scene& scene, const RenderSettings& settings,
                          const ReferenceSource& references = render_reference);

struct RenderGridSettings {
  int width = 192, height = 128;
  std::vector<std::string> rows{"regular@4",  "n-queens@4",  "jittered@4",
                                "regular@16", "n-queens@16", "jittered@16"};
  std::vector<std::string> columns{"box", "tent", "gaussian-half"};  // or "weights"
  uint64_t seed = 1;
  ReferenceSettings reference;
};
struct RenderGridCell {
  std::string row, column;
  Sampling sampling;
  Image image;
  RenderStats stats;
  RenderFigures figures;
  std::optional<AdaptiveImage> adaptive;
  bool show_map = false;  // the sheet shows the refinement map (uniform: a constant one)
};
std::vector<RenderGridCell> render_grid(const Scene& scene, const RenderGridSettings& settings,
                                        const ReferenceSource& references = render_reference,
                                        const StudyProgress& progress = {});

}  // namespace aapat

// Renderings measured against their dense reference, as `aapat render` and
// `aapat.render` make them: one scene with one sampling and filter, or a
// contact sheet of samplings (rows) by filters (columns) with the error
// figures of every cell.
#pragma once

#include <optional>
#include <string>
#include <vector>

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
};
RenderFigures measure(const Image& image, const Image& reference);

// A sampling named as a sheet row names it: GENERATOR@N (a per-pixel
// generator with N samples) or a catalog pattern / pattern file.
Sampling parse_sampling(const std::string& row, uint64_t seed);

struct RenderSettings {
  int width = 256, height = 256;
  Sampling sampling;
  std::optional<Filter> filter;  // none: the pattern's own weights
  bool measure = false;          // render the reference and compare
  ReferenceSettings reference;
};
struct RenderResult {
  Image image;
  RenderStats stats;
  std::optional<Image> reference;  // when measured
  std::optional<RenderFigures> figures;
};
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
};
std::vector<RenderGridCell> render_grid(const Scene& scene, const RenderGridSettings& settings,
                                        const ReferenceSource& references = render_reference,
                                        const StudyProgress& progress = {});

}  // namespace aapat

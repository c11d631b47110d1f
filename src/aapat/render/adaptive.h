// Adaptive refinement (Pelikan's slides: an initial phase, a refinement
// criterion, a refinement phase that reuses every sample; the recursion of
// Whitted's refinement): every pixel starts with a few samples; a pixel
// whose samples disagree is split into four squares, each given new
// samples until it holds `per_square`, and each square whose samples still
// disagree is split again, down to `max_depth` or until the pixel's budget
// is spent. Every sample taken stays in the pixel's estimate, weighted by the
// area of the square it ended in over that square's samples, so the
// estimate integrates the pixel, not the places that were refined.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "aapat/core/filter.h"
#include "aapat/render/renderer.h"

namespace aapat {

enum class RefinementCriterion {
  contrast,    // max - min of the square's sample values > threshold
  variance,    // their variance > threshold
  neighbours,  // contrast of the pixel's and its 8 neighbours' first samples > threshold
               // (the pixel's decision; its squares then refine by contrast)
  primitive,   // the samples see different primitives (shapes, sky and ground), or on a
               // textured primitive texture regions whose values differ by > threshold
};
RefinementCriterion parse_refinement_criterion(std::string_view text);
// The name the parser reads: "contrast", "variance", "neighbours", "primitive".
std::string_view refinement_criterion_name(RefinementCriterion criterion);

struct AdaptiveSettings {
  Sampling initial;  // 1 to 5 samples per pixel, from a generator or a pattern that shares none
  RefinementCriterion criterion = RefinementCriterion::contrast;
  double threshold = 0.1;
  int max_depth = 3;     // squares down to 2^-max_depth pixel
  int max_samples = 64;  // per pixel, the initial ones included
  int per_square = 2;    // samples a new square holds
};
// Throws ParameterError naming the setting out of range.
void validate(const AdaptiveSettings& s);

struct AdaptiveImage {
  Image image;
  std::vector<int> samples;  // per pixel, row j from the bottom: the refinement map
  double average_samples = 0;
  uint64_t evaluations = 0;     // scene evaluations, counted where they are made
  double refined_fraction = 0;  // pixels with more than their initial samples
};

// filter empty: each pixel the area-weighted mean of its squares (the box
// filter); else the filter over every sample, each weighted by its square's
// area over the square's samples.
AdaptiveImage render_adaptive(const Scene& scene, int width, int height,
                              const AdaptiveSettings& settings,
                              const std::optional<Filter>& filter);

}  // namespace aapat

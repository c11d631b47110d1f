// The search for a jitter sequence under motion (`aapat optimize --sequence
// K --taa PRESET`): one-sample frames minimizing the pan model's steady mean
// E2 (pan_model.h) averaged over a set of velocities, still (0,0) among
// them by default, under an engine preset's reconstruction, history sampler
// and steady blend at its ratio.
//
// Why not the still objective: a still optimum scatters samples so that
// every window of frames covers the pixel, but under a pan each frame d
// frames old sits d v further on, so the jitter a pixel accumulates is the
// sequence scrambled by the motion, and the still optimum loses to
// Halton(2,3) there (docs/temporal.md, "Under motion").
//
// A compass search: from the start (Halton(2,3) from index 1 unless given),
// each frame in turn tries a step in x and in y both ways and keeps the
// first that lowers the objective; a sweep that keeps none halves the step,
// down to min_step. Each try moves one frame (pan_objective.h's incremental
// evaluation). The start's value is never exceeded, and the result is the
// same at any thread count.
#pragma once

#include <string>
#include <vector>

#include "aapat/core/metric.h"
#include "aapat/temporal/engine/engine_taa_settings.h"
#include "aapat/temporal/sequence/sequence.h"
#include "aapat/work/work_items.h"

namespace aapat {

// Sweeps per step size at most (each keeps at least one step, or the size halves).
inline constexpr int kMaxPanSweeps = 1000;

struct PanSequenceSearch {
  EngineTaa taa;                 // its ratio, reconstruction, history and blend
  std::vector<Vec2> velocities;  // display pixels per frame; empty: kPanVelocities
  Sequence start;                // one-sample frames, the search's length
  double step = 1.0 / 16, min_step = 1.0 / 256;
  double jitter_bound = 0.5;  // every coordinate within +-bound (below 1/2: inside the pixel)
};

struct PanSequenceSearchResult {
  Sequence best;
  double start_value = 0, value = 0;         // the objective of the start and the result
  std::vector<Vec2> velocities;              // as evaluated
  std::vector<double> start_values, values;  // per velocity: the steady mean E2
  int tries = 0, kept = 0;                   // steps tried and kept
  // An upscale's jitter shorter than the upscaler's phase count, for the faces to show.
  std::vector<std::string> warnings;
};

// The start of K frames: `from` (a sequence file, catalog name or generator
// spec), or when empty Halton(2,3) from index 1, the engines' own. Throws
// Error when its length is not K.
Sequence pan_search_start(int frames, const std::string& from);

// Throws Error (ParameterError naming the setting) for a start that is not
// one-sample one-pixel frames, steps outside (0, 1/2] with min_step <= step,
// a bound outside [kMinJitterBound, 1/2], or a velocity out of range.
void validate(const PanSequenceSearch& s);

// progress: (step sizes done, step sizes, "J ...") after each sweep that kept a
// step and as each step size finishes.
PanSequenceSearchResult search_sequence_under_pans(const PanSequenceSearch& search,
                                                   const Metric& metric,
                                                   const ItemsProgress& progress = {});

}  // namespace aapat

// The search for a sequence (`aapat optimize --sequence K`): the positions of
// every sample of K one-pixel frames (one sample each for a TAA or upscaler
// jitter, several for alternating MSAA, whose weights within a frame move
// too unless optimize_weights is off)
// minimizing
//     J = worst (or mean) steady-state E2 + flicker_weight * mean flicker
// under an accumulation model (temporal_metrics.h: the steady frames' E2 and
// the flicker between consecutive ones). In epigraph form, as the pattern
// optimizer's --method slsqp: minimize s + lambda mean_k t_k over the
// positions, s and the t_k, subject to every term of every steady frame's
// E2 <= s and every term of transition k's flicker <= t_k, where a term is
// W E1 (or W F) at
// one angle for the maximum over angles, or the frame's combination over
// angles for an L_p mean. Each term has its analytic gradient: E1^2 by
// core/gradient.h, and the flicker's F = sum_j |R_j| (p_(j+1) - p_(j)) over
// the sorted projections (R_j the running sum of the changes of the
// samples' weights between the frames) by dF/dp_(j) = |R_(j-1)| - |R_j|.
// NLopt's SLSQP solves it.
//
// Multi-start: start 0 is Halton(2, 3) from index 1 (split into frames of
// the samples per frame), the others uniform random from start_rng(seed, i);
// the best J wins, ties to the lower start, so the result is the same at any
// thread count. With an API profile, each frame is then snapped to the
// 1/16-pixel lattice and polished by single lattice steps while J falls.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "aapat/core/filter.h"
#include "aapat/core/hardware_layout.h"
#include "aapat/core/metric.h"
#include "aapat/temporal/model/accumulation.h"
#include "aapat/temporal/sequence/render_scale.h"
#include "aapat/work/work_items.h"

namespace aapat {

// The frames' E2 in J: the worst steady frame, or the mean over the phases
// (which rendered RMSE over many frames follows more closely; docs/temporal.md).
enum class FrameMeasure { worst, mean };
// "worst" or "mean", the one spelling every face takes and reports; throws
// ParameterError naming "frame-measure" for another.
FrameMeasure parse_frame_measure(std::string_view text);
std::string_view frame_measure_name(FrameMeasure m);

// A searched sequence's samples per frame, and in all.
inline constexpr int kMaxSearchSamplesPerFrame = 16, kMaxSearchSamples = 1024;
inline constexpr double kMinJitterBound = 0.01;   // --jitter-bound's and --jitter-radius's smallest
inline constexpr double kMaxJitterRadius = 0.71;  // past the pixel's corner: no constraint

struct SequenceSearch {
  int frames = 8;
  int samples_per_frame = 1;
  Accumulation model;         // no resolve: its weights move with the samples
  double flicker_weight = 3;  // lambda
  FrameMeasure frame_measure = FrameMeasure::worst;
  // With several samples per frame, each frame's weights move too (summing
  // to 1; negative lobes allowed); else they stay equal.
  bool optimize_weights = true;
  int starts = 16;
  uint64_t seed = 1;
  // Every coordinate of every jitter within +-jitter_bound pixels. Below the
  // pixel's 1/2, it trades still error for motion: under an engine's
  // rectification, a tighter jitter gives lower error on moving content
  // (docs/temporal.md, "Under motion").
  double jitter_bound = 0.5;
  // Every jitter within this distance of the pixel centre (SLSQP: one
  // constraint per sample; not with an upscale's Subplex). The clamp wants
  // a small radius, not a small box (docs/temporal.md, "Under motion").
  std::optional<double> jitter_radius;
  int iterations = 4000;                // NLopt evaluations per start
  const ApiProfile* profile = nullptr;  // snap to its lattice
  // Upscaling (temporal/model/upscale_model.h): the frames are one-sample jitters
  // reconstructed by the upscale's filter at its render scale; E2 and flicker
  // are the means over the display phases. The search is then derivative-free
  // (NLopt's Subplex on J; the reconstruction weights move with the samples).
  std::optional<Upscale> upscale;
};

struct SequenceSearchResult {
  Sequence best;
  double objective = 0;                           // J of the result
  double worst_e2 = 0, mean_e2 = 0, flicker = 0;  // flicker: the mean over the transitions
  int best_start = 0;
  double halton_objective = 0;  // J of start 0, the Halton sequence, before the search
  std::optional<double> continuous_objective;  // before snapping, with a profile
  // What the settings allow but an engine would not expect (an upscale's
  // jitter shorter than the upscaler's phase count), for the faces to show.
  std::vector<std::string> warnings;
};

// Throws Error (ParameterError naming the setting) for settings out of range.
void validate(const SequenceSearch& s);

// J of a sequence under the search's model (worst steady E2, mean flicker).
// The mean flicker, not the worst: rendered flicker (the mean change of the
// error over pixels and frames) follows the mean (docs/temporal.md).
struct SequenceObjective {
  double objective = 0, worst_e2 = 0, mean_e2 = 0, flicker = 0;
};
SequenceObjective sequence_objective(const Sequence& s, const SequenceSearch& search,
                                     const Metric& metric);

// progress: (starts done, starts, "best J ...") as each start finishes, one
// call at a time (the command line's bar, Python's callable).
SequenceSearchResult optimize_sequence(const SequenceSearch& search, const Metric& metric,
                                       const ItemsProgress& progress = {});

// The epigraph's constraints (each term minus its bound) at the free
// variables (x, y per sample, frame by frame; then, when the weights move,
// each frame's weights but its last, which is 1 minus the others) with
// every bound 0, and their Jacobian, one row per constraint over those
// variables: for the gradient tests.
void sequence_terms(const SequenceSearch& search, const Metric& metric,
                    const std::vector<double>& variables, std::vector<double>& values,
                    std::vector<double>& jacobian);

}  // namespace aapat

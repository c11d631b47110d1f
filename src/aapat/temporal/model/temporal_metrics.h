// The error of a sequence under an accumulation model, from the image each
// frame shows (accumulation.h turns it into ordinary kernels):
//  - E2 at every frame after a camera cut (the convergence curve), and at
//    every phase in steady state (worst and mean);
//  - flicker: how much the reconstructed edge changes from one steady frame
//    to the next. For an edge of direction theta at offset a the pixel shows
//    ghat_k(a), the weight of frame k's accumulated samples on one side (the
//    step response of the metric). Its change Delta(a) = ghat_k(a) -
//    ghat_{k-1}(a) is a step function that vanishes far from the samples, so
//      F_k(theta) = int |Delta(a)| da
//    is finite and exact: the sum over the sorted projections of |the
//    running sum of signed weights| times the gap to the next projection.
//    It is the mean absolute change of the pixels an edge crosses, which is
//    what a rendered flicker measure averages (the L2 form, int Delta^2,
//    predicted rendered flicker no better; docs/temporal.md). F_k combines
//    over angles like E1 (W(theta) F, the metric's norm) and over kernels by
//    the maximum; flicker is the mean and the worst over the period's
//    transitions k-1 -> k (cyclic). A box window of the whole period shows
//    the same image every frame: flicker 0;
//  - the mean offset of the samples (a non-zero mean shifts the image) and
//    the largest centroid of a steady frame's accumulated kernel;
//  - every prefix of the samples in time order (pixel 0's samples, frame 0
//    first, moved to [0, 1)^2): per-axis stratification (the most samples in
//    one of m equal strata; 1 is N-rooks), the star and L2-star discrepancy.
#pragma once

#include <optional>
#include <vector>

#include "aapat/core/metric.h"
#include "aapat/temporal/model/accumulation.h"
#include "aapat/temporal/sequence/render_scale.h"

namespace aapat {

// Prefixes measured: every one up to this many samples, then the whole period.
inline constexpr int kAllPrefixesUpTo = 256;

struct PrefixMeasure {
  int samples = 0;                   // m, the prefix's length
  int most_in_x = 0, most_in_y = 0;  // the most samples in one of m strata of x, of y
  double star = 0;                   // star discrepancy (exact)
  double l2_star = 0;
};

struct TemporalReport {
  std::vector<double> cut_curve;  // E2 of the image shown at frames 0, 1, ... after a cut
  int settle_frame = 0;           // the first frame from which the curve stays within 1% of the
                                  // steady worst frame (the curve's length if it never does)
  std::vector<double> steady_e2;  // per phase
  double worst_e2 = 0, mean_e2 = 0;
  std::vector<double> flicker;  // per transition into phase k
  double worst_flicker = 0, mean_flicker = 0;
  Vec2 mean_offset;           // the mean sample position over one period
  double worst_centroid = 0;  // the largest |sum w p| of a steady frame's kernel
  std::vector<PrefixMeasure> prefixes;
};

// The curve runs `curve_frames` frames after the cut (0: enough to settle,
// 2 periods for a box, at least until frame 0's weight falls below 1% for
// an EMA, plus a period). With `upscale`, every frame is rendered at the
// render scale and reconstructed into display pixels (upscale_model.h): the
// kernels are the display phases', the model that `optimize --sequence
// --ratio` searches under. Throws Error naming the problem.
TemporalReport evaluate_temporal(const Sequence& s, const Accumulation& a, const Metric& metric,
                                 int curve_frames = 0,
                                 const std::optional<Upscale>& upscale = std::nullopt);

// E2 of a set of kernels (the largest over kernels).
double kernels_e2(const Metric& metric, const std::vector<Kernel>& kernels);
// F(theta) combined over angles for the change from kernel `before` to
// kernel `after` (the flicker of one kernel between two frames).
double kernel_flicker(const Metric& metric, const Kernel& before, const Kernel& after);

// The samples of pixel 0 of every frame in time order, moved to [0, 1)^2:
// the points whose prefixes are measured (and `sequence export --points`
// writes for aapat spectrum and discrepancy).
std::vector<Vec2> sequence_points(const Sequence& s);

// The per-axis stratification and discrepancies of the prefixes of `points`
// (in [0, 1)^2): every prefix up to kAllPrefixesUpTo, then the whole set.
std::vector<PrefixMeasure> prefix_measures(const std::vector<Vec2>& points);

}  // namespace aapat

// The linear model of engine TAA under a steady pan, before rectification
// (engine_taa.h without step 4): what the history does to a jitter when the
// scene moves. Display pixel x at frame t shows
//     H_t(x) = alpha C_t(x) + (1 - alpha) S[H_(t-1)](x - v),
// C_t the frame's reconstruction (upscale_model.h) and S the history
// sampler's 4x4 taps (history_sampling.h) around the point the pixel came
// from. For a pan every pixel's point has the same fraction, so the taps are
// the same every frame, and unrolling the recursion gives an ordinary kernel:
// the samples of the frame d frames old, each reconstructed at the display
// pixels that d tap steps reach (a chain of weights on whole-pixel offsets,
// the taps convolved d times), weighted by the frame's accumulation weight.
// Each sample sits where its content is now: its position then plus d v,
// relative to the pixel's centre.
//
// Sharp samplers (Catmull-Rom, Lanczos-2) keep an old frame's samples
// nearly points, displaced by d v modulo the pixel: the jitter a pixel
// accumulates is then the sequence scrambled by the motion. Bilinear spreads
// each old sample over more pixels every frame (a blur of variance
// f (1 - f) per step and axis, f the fraction).
#pragma once

#include <array>
#include <span>
#include <string_view>
#include <vector>

#include "aapat/core/filter.h"
#include "aapat/core/metric.h"
#include "aapat/core/pattern.h"
#include "aapat/temporal/model/history_sampling.h"
#include "aapat/temporal/model/upscale_model.h"
#include "aapat/temporal/sequence/sequence.h"
#include "aapat/work/work_items.h"

namespace aapat {

// Exact to rounding: the test compares the model with the pipeline to 1e-12.
inline constexpr double kPanChainCut = 1e-15;

struct PanModel {
  Upscale upscale;  // its ratio and reconstruction (over render-pixel distances, as engine_taa.h)
  HistorySampler history = HistorySampler::bilinear;
  Vec2 velocity;  // the scene's motion, display pixels per frame
  // A chain's weights below this are dropped after each step, the rest
  // scaled to keep its sum.
  double chain_cut = kPanChainCut;
};

// The accumulation weights of frames 0, 1, ... frames old in steady state
// under an EMA of current-frame weight alpha: alpha (1 - alpha)^d until it
// falls below `cut` alpha, then one period of frames that carries the rest
// of the series (each frame's repeats summed on it), so that they sum to 1
// and a still scene's kernel is the steady one exactly.
std::vector<double> ema_age_weights(double alpha, int period, double cut = 1e-4);

// The kernel of display pixel `pixel` at the frame that shows sequence
// frame k, the frame d frames older weighing age_weights[d] and showing
// sequence frame k - d (cyclically): positions in display pixels relative
// to the pixel's centre, where each sample's content is now.
Kernel pan_kernel(const Sequence& s, const PanModel& m, const std::vector<double>& age_weights,
                  int k, std::array<int, 2> pixel);

// The whole-pixel offsets a pixel's history reaches after 0, 1, ... ages-1
// steps of the model's history taps, in order, and their weights (chains cut
// at m.chain_cut): age 0 is the pixel itself, weight 1. Throws Error when
// they pass kMaxPanKernelSamples entries in all.
struct PanChainEntry {
  int dx = 0, dy = 0;
  double c = 0;
};
std::vector<std::vector<PanChainEntry>> pan_chains(const PanModel& m, size_t ages);

// E1^2 by the closed form (metric.h) of weights w binned at increasing
// positions p (zero weights skipped): the evaluation's projections.
double binned_e1_squared(std::span<const double> w, std::span<const double> p, const Filter& f);

// `aapat sequence pan`'s velocities when none are given (display pixels per
// frame): still, then slow to fast pans in several directions, none whole
// pixels (a whole-pixel pan keeps every old sample's place in its pixel).
inline constexpr std::array<std::string_view, 5> kPanVelocities{"0,0", "0.37,0.21", "-0.53,1.05",
                                                                "1.33,-0.02", "0.23,-0.61"};
// kPanVelocities parsed: what an evaluation or a search takes when given none.
std::vector<Vec2> default_pan_velocities();

// The fastest pan evaluated, per axis, and the longest sequence (each frame
// is a kernel of up to a few hundred thousand samples per display phase).
inline constexpr double kMaxPanSpeed = 16;
inline constexpr int kMaxPanFrames = 128;
// The most samples one pan kernel may read, each render sample once per
// chain offset that reaches it (a bilinear history at UE4's alpha 0.04 reads
// about 900,000 at the evaluation's cuts panning 0.37, 0.21, which sum into
// 118,000 samples; FSR 2 at 1.5 216,000 into 11,000): a small alpha under a
// blurring history would otherwise grow it without bound.
inline constexpr size_t kMaxPanKernelSamples = 4'000'000;

// Throws ParameterError naming "velocity" unless both components are finite
// and within kMaxPanSpeed.
void check_velocity(Vec2 v);

// "DX,DY" (display pixels per frame), checked by check_velocity.
Vec2 parse_velocity(std::string_view text);

// The steady state of a sequence under the pan, as E2 and flicker are
// defined for the still models (temporal_metrics.h): the mean over the
// period's frames and the render grid's display phases of E2, and of the
// flicker between consecutive frames. Evaluated on projections binned at
// kPanBin pixels (each sample moved by at most half of it), ages kept down
// to kPanAgeCut alpha and chains cut at kPanEvaluationChainCut: an old
// frame under a bilinear history spreads over thousands of pixels' weights,
// more than the metric's exact sums can take per evaluation.
inline constexpr double kPanBin = 1.0 / 64, kPanAgeCut = 1e-3, kPanEvaluationChainCut = 1e-5;
// The bin of a projection: floor(position / kPanBin), exactly (the division
// by a power of two is), without a call into libm (the baseline x86-64
// target has no rounding instruction, and binning is the pan model's hot
// loop). Positions stay far inside a long's range.
inline long pan_bin(double position) {
  const double scaled = position * (1 / kPanBin);
  const auto t = static_cast<long>(scaled);  // toward zero
  return scaled < static_cast<double>(t) ? t - 1 : t;
}
struct PanReport {
  double mean_e2 = 0, flicker = 0;
};
PanReport evaluate_pan(const Sequence& s, PanModel m, double alpha, const Metric& metric);

}  // namespace aapat

// How frames combine into the image shown at frame k, as a weight per past
// frame, so that the shown pixel is an ordinary weighted kernel over all the
// samples those frames took, which the metric evaluates exactly:
//  - box: the mean of the last `window` frames (the period by default);
//  - EMA: history H_k = alpha F_k + (1 - alpha) H_{k-1}, frame k - j weighing
//    alpha (1 - alpha)^j; after a camera cut at frame 0 (H_0 = F_0, so frame 0
//    keeps (1 - alpha)^k), or in steady state, where the frames of one phase
//    of the period sum to alpha (1 - alpha)^d / (1 - (1 - alpha)^K);
//  - optionally each frame first resolved spatially: every sample within the
//    filter's support around the output point (the neighbours' samples
//    too), weighted by h(dx) h(dy) and normalized (a TAA resolve: it reads
//    the neighbours' samples exactly as a wide kernel does, and exactly as
//    the renderer reconstructs with a filter), instead of its pattern's own
//    kernel. A Gaussian of radius 1.5 reads 3x3 pixels.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "aapat/core/filter.h"
#include "aapat/temporal/sequence/sequence.h"

namespace aapat {

enum class AccumulationKind { box, ema };

// The model every face defaults to: an EMA of current-frame weight 0.1.
inline constexpr std::string_view kDefaultAccumulation = "ema";
inline constexpr double kDefaultAlpha = 0.1;

struct Accumulation {
  AccumulationKind kind = AccumulationKind::ema;
  int window = 0;                 // box: the frames averaged (0: the sequence's period)
  double alpha = kDefaultAlpha;   // EMA: the current frame's weight, in (0, 1]
  std::optional<Filter> resolve;  // each frame resolved over its neighbours' samples
};
// A resolve filter reads at most this far from the output point (pixels).
inline constexpr double kMaxResolveRadius = 4;
// Throws ParameterError naming the setting out of range.
void validate(const Accumulation& a);
// The model every face builds: kind "ema" or "box", a resolve filter spec
// ("" for none); validated. Throws ParameterError naming the setting.
Accumulation make_accumulation(std::string_view kind, double alpha, int window,
                               std::string_view resolve);
// "EMA alpha 0.1", "box of 8 frames", "..., gaussian:sigma=0.47,radius=1.5 resolve": for reports.
std::string accumulation_text(const Accumulation& a);

// The weight of frame j = 0..k in the image shown at frame k after a cut at
// frame 0 (they sum to 1).
std::vector<double> weights_after_cut(const Accumulation& a, int period, int k);
// Steady state: the weight of the frames d = 0..period-1 frames back, each
// summed over every earlier period (they sum to 1).
std::vector<double> steady_weights(const Accumulation& a, int period);

// The weight of each phase f = 0..period-1 of the sequence in the image shown
// at frame k (steady: frame k of the period in steady state; else frame k
// after a cut): the weights above summed over the frames of one phase, since
// they took the same samples.
std::vector<double> phase_weights(const Accumulation& a, int period, int k, bool steady);

// The image shown at frame k as kernels, one per tile pixel of the frames
// (positions relative to the output point): the frames' kernels, or their
// resolves, weighted as above. `steady`: frame k of the period in steady
// state; else frame k after a cut.
std::vector<Kernel> accumulated_kernels(const Sequence& s, const Accumulation& a, int k,
                                        bool steady);

}  // namespace aapat

// The pan model's steady mean E2 (pan_model.h's evaluate_pan) averaged over
// several pans, kept up to date as one frame's jitter moves: what the
// sequence search under motion (pan_search.h) evaluates thousands of times.
//
// Every kernel the evaluation takes (a velocity, a display phase pixel, a
// frame of the period) is held as its projections binned at kPanBin, per
// angle: weight and weight times position per bin. A kernel is a sum over
// ages d of the frame d frames old, so moving frame f's jitter changes
// only the ages that show f (about 1/K of them): those are taken out of
// the bins and put back with the new jitter, and each kernel's E2 is read
// from its bins again. A frame's reconstruction is separable (h(dx) h(dy)
// over a grid of render pixels), so each display column and row holds its
// few one-axis weights per frame, and a sample's projection is the sum of
// its chain offset's, its column's and its row's.
//
// The bins are evaluate_pan's (the same grid, each bin's weighted mean
// position), so the value is evaluate_pan's mean E2 to rounding: a test
// compares them to 1e-9.
#pragma once

#include <memory>
#include <vector>

#include "aapat/core/metric.h"
#include "aapat/temporal/model/pan_model.h"

namespace aapat {

// One pan the objective averages over: the model (its velocity 0,0 for a
// still scene) and the blend's current-frame weight there.
struct PanCase {
  PanModel model;
  double alpha = 0.1;
};

// The most memory the bins may take; a finer acuity table, more velocities
// or a longer sequence past it is refused with the size it would need.
inline constexpr size_t kMaxPanObjectiveBytes = size_t{3} << 30;

class PanObjective {
 public:
  // All cases share the ratio and the reconstruction filter. Throws Error
  // (ParameterError naming the setting) for a period outside 1 to
  // kMaxPanFrames, no cases, or bins past kMaxPanObjectiveBytes.
  PanObjective(int period, std::vector<PanCase> cases, const Metric& metric);
  ~PanObjective();
  PanObjective(const PanObjective&) = delete;
  PanObjective& operator=(const PanObjective&) = delete;

  // Every frame's jitter (one sample each, inside the pixel), every kernel
  // rebuilt. Throws Error when the reconstruction gives a frame no weight.
  void set(const std::vector<Vec2>& jitter);
  // Frame f's jitter moved to j; only the ages showing f are rebinned.
  void move(int frame, Vec2 j);
  // The value with frame f at j, the objective left as it was: each kernel
  // rebinned in a copy (cheaper than a move and a move back).
  double try_move(int frame, Vec2 j);

  // The mean over the cases of each one's steady mean E2.
  double value() const;
  // Each case's steady mean E2 (the mean over the period and the display
  // phase pixels), in the order given.
  std::vector<double> case_values() const;
  const std::vector<Vec2>& jitter() const;
  // The bins' memory, for the limit's message and the benchmark.
  size_t bytes() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
  double update(int frame, Vec2 j, bool keep);
  static double mean_of(const std::vector<std::vector<double>>& e2);
};

}  // namespace aapat

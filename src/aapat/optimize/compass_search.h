// A compass search (a coordinate pattern search) for any objective, the
// rendered ones included: the point is blocks of coordinates (a jitter
// frame's x and y); each block in turn tries a step along each of its
// coordinates, plus then minus, and keeps the first try that lowers the
// value; a sweep over every block that keeps none halves the step, down to
// min_step. Derivative-free and monotone: the result's value never exceeds
// the start's, and it is the same at any thread count (the objective's
// evaluations are the only work).
//
// The objective may evaluate a block's move incrementally (the pan model
// rebins only the ages that show a frame): try_move leaves it as it was,
// move keeps the move, and set rebuilds it from scratch, which the search
// does once a sweep, so that incremental sums cannot drift.
#pragma once

#include <functional>
#include <span>
#include <string>
#include <vector>

#include "aapat/work/work_items.h"

namespace aapat {

class CompassObjective {
 public:
  virtual ~CompassObjective() = default;
  // Every coordinate set afresh; returns the value there.
  virtual double set(std::span<const double> x) = 0;
  // The value with block b's coordinates at `to`, the objective left as it was.
  virtual double try_move(size_t block, std::span<const double> to) = 0;
  // Block b's coordinates moved to `to`, kept.
  virtual void move(size_t block, std::span<const double> to) = 0;
};

// Any function of the whole point as a CompassObjective: each try
// evaluates the point with the block moved.
class FunctionObjective final : public CompassObjective {
 public:
  FunctionObjective(std::function<double(std::span<const double>)> f, size_t block_size);
  double set(std::span<const double> x) override;
  double try_move(size_t block, std::span<const double> to) override;
  void move(size_t block, std::span<const double> to) override;

 private:
  std::function<double(std::span<const double>)> f_;
  size_t block_size_;
  std::vector<double> x_, scratch_;
};

struct CompassSettings {
  size_t block_size = 2;
  double step = 1.0 / 16, min_step = 1.0 / 256;
  double lo = -0.5, hi = 0.5;  // every coordinate stays in [lo, hi]
  int max_sweeps = 1000;       // per step size
  int max_tries = 0;           // 0: no limit; else the search ends after this many tries
  // A try is kept when its value is below the best by more than this
  // fraction of it (rounding in incremental sums is not a gain).
  double min_gain = 1e-12;
};

struct CompassResult {
  std::vector<double> x;
  double start_value = 0, value = 0;
  int tries = 0, kept = 0;
};

// Throws ParameterError naming "step", "min-step" or the bounds for settings
// out of range (steps in (0, hi - lo], min_step in (0, step], lo < hi, a
// start's size not a multiple of block_size or outside the bounds).
void validate(const CompassSettings& s, std::span<const double> start);

// progress: (step sizes done, step sizes, "J ... at step ..., sweep ...")
// after each sweep that kept a try, and as each step size finishes.
CompassResult compass_search(CompassObjective& objective, std::vector<double> start,
                             const CompassSettings& settings, const ItemsProgress& progress = {});

}  // namespace aapat

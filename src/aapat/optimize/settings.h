// The optimizer's knobs, with the values of Laine & Aila Sec. 5.2 as defaults.
#pragma once

#include <chrono>
#include <optional>

namespace aapat {

// The optimizer's counts on every face: random starts, iterations per start,
// and the steps per pixel of a position lattice.
inline constexpr int kMaxStarts = 1'000'000;
inline constexpr int kMaxIterations = 100'000'000;
// A run's time limit in seconds (about 116 days: long enough, and finite).
inline constexpr double kMaxTimeLimit = 1e7;
inline constexpr int kMinLatticeSteps = 2, kMaxLatticeSteps = 256;

// The descent heuristic, the minimax descent, annealing, and the epigraph
// form with NLopt's SLSQP, MMA or CCSAQ (optimize/epigraph.h).
enum class Method { kDescent, kMinimax, kAnneal, kSlsqp, kMma, kCcsaq };
inline bool is_epigraph(Method m) {
  return m == Method::kSlsqp || m == Method::kMma || m == Method::kCcsaq;
}

struct OptimizerSettings {
  Method method = Method::kDescent;
  double threshold = 0.99;     // t: terms within t of E2 take the large step
  double step_ratio = 100;     // c1 / c0
  double initial_step = 1e-3;  // c0 at the start; adapted as the run goes
  double min_step = 1e-13;     // stop once c0 shrinks below this
  int max_iterations = 4000;
  int window = 100;         // stop when E2 improved by less than
  double tolerance = 1e-8;  //   tolerance (relative) over `window` iterations
  // After a multi-start of the heuristic, polish the best start with the
  // minimax descent (which does not stall at kinks of the maximum).
  bool polish = true;
  int polish_count = 4;  // how many of the best starts are polished
  bool weights_only = false;
  bool nonnegative_weights = false;
  // Wall-clock limit for the whole run (all starts).
  std::optional<std::chrono::steady_clock::time_point> deadline;
};

struct RunResult {
  double initial_e2 = 0;
  double final_e2 = 0;
  int iterations = 0;
  int evaluations = 0;
};

inline bool past(const OptimizerSettings& s) {
  return s.deadline && std::chrono::steady_clock::now() >= *s.deadline;
}

}  // namespace aapat

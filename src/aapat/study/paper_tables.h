// The re-runs of the papers' experiments (Laine & Aila Table 3 and Figure
// 10) and the table of what the APIs' 1/16-pixel lattice costs. Each takes
// its settings and returns the numbers beside the published ones; the
// command line and the Python module format them.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "aapat/core/metric.h"
#include "aapat/optimize/settings.h"
#include "aapat/study/progress.h"

namespace aapat {

// Laine-Aila Table 3: P(16,16,4) patterns drawn as jittered grids and Poisson
// disk sets with h(x) h(y) weights; min / avg / max E2, then the best
// optimized for weights only (Opt W) and from there for positions too (Opt W+P).
struct Table3Settings {
  int patterns = 1000;  // per distribution
  int iterations = 4000;
  uint64_t seed = 1;
  // The Opt W+P stage's method (Opt W is the descent's convex optimum):
  // the default descent with its minimax polish, or an epigraph method.
  Method method = Method::kDescent;
};
struct Table3Row {
  std::string distribution;  // "jittered grid", "Poisson disk"
  std::array<double, 5> e2;  // Min, Avg, Max, Opt W, Opt W+P
  std::array<double, 5> paper;
};
std::vector<Table3Row> table3(const Metric& metric, const Table3Settings& settings,
                              const StudyProgress& progress = {});

// Laine-Aila Figure 10: the best E2 of P(1,1,n), P(4,1+,n), P(1,4,n) and
// P(4,4,n) for n = 2..6, and P(4,1+,n) for n = 1.25..1.75; for P(4,1+,n) each
// n tries the placements of figure10_placements and keeps the best.
struct Figure10Settings {
  int starts = 32;  // per family, n and placement
  uint64_t seed = 1;
};
struct Figure10Point {
  std::string family, placement;  // family "P(4,1+,2)"; placement empty: all inside
  double n = 0, e2 = 0;
  int series = 0;  // index into Figure10::series
};
struct Figure10 {
  std::vector<std::string> series;    // "P(1,1,n)", ... in order
  std::vector<Figure10Point> points;  // by series, then n
};
std::vector<std::string> figure10_placements(double n);
Figure10 figure10(const Metric& metric, const Figure10Settings& settings,
                  const StudyProgress& progress = {});

// For 2, 4, 8 and 16 samples per pixel: the standard MSAA pattern with a box
// resolve and with optimized weights, the best pattern found on the lattice
// for Direct3D 12 tier 1 (and tier 2 where the count allows), each beside
// the continuous optimum of its family; then the 1.25-2 sample sharing
// schemes snapped to the lattice and searched there.
struct HardwareTableSettings {
  int starts = 32;  // per family
  uint64_t seed = 1;
};
struct HardwareTableRow {
  std::string n, pattern, profile;
  std::string layout;  // "2x2 grid, 2x MSAA, reads 4"
  double continuous_e2 = 0, lattice_e2 = 0;
};
std::vector<HardwareTableRow> hardware_table(const Metric& metric,
                                             const HardwareTableSettings& settings,
                                             const StudyProgress& progress = {});

}  // namespace aapat

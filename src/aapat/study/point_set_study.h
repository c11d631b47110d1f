// What `aapat discrepancy` and `aapat spectrum` measure of a point set: the
// discrepancies asked, the 2D power spectrum averaged over
// realizations with its radial profile, and the 1D spectra of Goss & Wu's
// Figure 8 with the binned curves a plot can show.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "aapat/analyze/discrepancy.h"
#include "aapat/analyze/fast_spectrum.h"
#include "aapat/analyze/l2_discrepancy.h"
#include "aapat/analyze/spectrum.h"
#include "aapat/study/progress.h"

namespace aapat {

// Point sets one spectrum averages.
inline constexpr int kMaxRealizations = 100000;

// Which discrepancies to compute: "l2-star,star,edge" by default; any of
// those, the other L2 kinds (l2-centred, ...), or "all", in any order.
struct DiscrepancyMeasures {
  std::vector<L2Kind> l2{L2Kind::star};  // in the order of l2_kinds()
  bool star = true, edge = true;
};
DiscrepancyMeasures parse_measures(std::string_view list);  // ParameterError("measure")
inline constexpr std::string_view kDefaultDiscrepancyMeasures = "l2-star,star,edge";

struct L2Value {
  L2Kind kind;
  double value = 0;
};
struct DiscrepancyReport {
  size_t points = 0;
  std::vector<L2Value> l2;  // the L2 kinds asked, in the order of l2_kinds()
  std::optional<StarDiscrepancy> star;
  std::optional<EdgeDiscrepancy> edge;
};
// Only the measures asked; the size limits are those of the measures asked
// (the L2 discrepancies alone take up to kMaxL2StarPoints).
DiscrepancyReport discrepancy_report(const std::vector<Vec2>& points,
                                     const DiscrepancyMeasures& measures = {},
                                     const StudyProgress& progress = {});

// The exact 2D spectrum's work: points x frequencies x realizations.
inline constexpr double kMaxSpectrumTerms = 68719476736.0;  // 2^36

// Realization r of a point source (a file has one, whatever r).
using PointSource = std::function<std::vector<Vec2>(int realization)>;

// Points per realization of a generator when none is given (every face).
inline constexpr int kDefaultSpectrumPoints = 1024;

struct SpectrumSettings {
  int size = 256;              // frequencies -size/2 .. size/2-1 per axis
  int realizations = 1;        // point sets averaged, 1 to kMaxRealizations
  size_t expected_points = 0;  // when known, the work is checked before any point is drawn
  // The non-uniform FFT (analyze/fast_spectrum.h) instead of the exact sum:
  // O(N + M^2 log M), within a stated error bound, any N (even sizes).
  bool fast = false;
};
struct SpectrumStudy {
  Spectrum2D mean;
  double error_bound = 0;  // fast: on |P_fast - P| at every frequency but 0; exact: 0
  RadialProfile radial;
  size_t points = 0;                       // of the last realization
  double tail_radius = 0, tail_power = 0;  // mean power from the middle ring outwards
};
SpectrumStudy spectrum_study(const PointSource& source, const SpectrumSettings& settings,
                             const StudyProgress& progress = {});

struct LineSpectrum {
  std::string kind;
  size_t points = 0;
  std::vector<double> power;  // at k * max_frequency / frequencies
  // The mean of each of up to 2000 bins, from past the DC peak's main lobe
  // (|f| < 2 / length) on: a curve a plot can draw.
  std::vector<double> bin_frequency, bin_power;
};
// The 1D spectra's defaults, Goss & Wu's Figure 8 (7488 points, 2^17
// frequencies up to 4 cycles per mean spacing), and limits (docs/limits.md),
// checked by line_spectra for every face.
inline constexpr int kDefaultLinePoints = 7488, kDefaultLineFrequencies = 131072;
inline constexpr double kDefaultLineMaxFrequency = 4;
inline constexpr int kMinLineFrequencies = 16, kMaxLineFrequencies = 10'000'000;
inline constexpr double kMinLineMaxFrequency = 0.01, kMaxLineMaxFrequency = 1000;
std::vector<LineSpectrum> line_spectra(const std::vector<std::string>& kinds, int n, uint64_t seed,
                                       int frequencies, double max_frequency);
// The frequencies a LineSpectrum's power is at: k * max_frequency / frequencies.
std::vector<double> line_frequencies(int frequencies, double max_frequency);

}  // namespace aapat

// What the WebAssembly build leaves out (web/CMakeLists.txt says why), answered
// with an Error that names it instead of a link failure.
#include "aapat/analyze/fast_spectrum.h"
#include "aapat/core/geometry.h"
#include "aapat/optimize/epigraph.h"

namespace aapat {

RunResult epigraph(const ProblemE2&, Problem&, const OptimizerSettings&, EpigraphAlgorithm) {
  throw Error(
      "the epigraph methods (slsqp, mma, ccsaq) need NLopt, which the WebAssembly build leaves "
      "out: use descent, minimax or anneal");
}

FastSpectrum power_spectrum_fast(const std::vector<Vec2>&, int) {
  throw Error(
      "the fast (NUFFT) spectrum needs FFTW, which the WebAssembly build leaves out: the exact "
      "spectrum is computed instead");
}

}  // namespace aapat

// Drawings of a sequence: every frame's samples in the pixel, numbered by
// frame in time order (colour from the first frame's blue to the last's
// red), and the convergence curve of E2 after a cut (line_plot_svg).
#pragma once

#include <string>
#include <vector>

#include "aapat/temporal/sequence/sequence.h"

namespace aapat {

// Tile pixel 0 of every frame.
std::string sequence_svg(const Sequence& s);

// E2 at frames 0, 1, ... after a cut, one series per sequence.
struct CurveSeries {
  std::string label;
  std::vector<double> e2;
};
std::string convergence_svg(const std::vector<CurveSeries>& series, const std::string& title);

}  // namespace aapat

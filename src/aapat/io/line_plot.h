// A small SVG line chart: series of (x, y) points with markers, axes, ticks
// and a legend. The error profile and the Figure 10 reproduction draw with it.
#pragma once

#include <string>
#include <vector>

namespace aapat {

struct LineSeries {
  std::string label;
  std::vector<double> x, y;  // drawn in the given order
};

struct LinePlot {
  std::string title, x_label, y_label;
  std::vector<double> x_ticks;  // empty: five even ticks over the data
  double x_min = 0, x_max = 0;  // equal: from the data
  bool y_from_zero = true;
};

std::string line_plot_svg(const LinePlot& plot, const std::vector<LineSeries>& series);

}  // namespace aapat

#include "aapat/io/profile_plot.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "aapat/io/line_plot.h"

namespace aapat {

std::string profile_svg(const AcuityTable& acuity, const std::vector<ProfileSeries>& series,
                        const std::string& title) {
  // Angles as edge directions folded into [0, 180), in increasing order.
  std::vector<size_t> order(acuity.angles_deg.size());
  std::iota(order.begin(), order.end(), 0);
  auto folded = [&](size_t i) {
    const double a = std::fmod(acuity.angles_deg[i], 180.0);
    return a < 0 ? a + 180 : a;
  };
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return folded(a) < folded(b); });
  std::vector<LineSeries> lines;
  for (const auto& s : series) {
    LineSeries line{s.label, {}, {}};
    for (size_t i : order) {
      line.x.push_back(folded(i));
      line.y.push_back(s.values[i]);
    }
    lines.push_back(std::move(line));
  }
  LinePlot plot{title, "edge angle (degrees)", "W(theta) E1(theta)", {0, 45, 90, 135, 180}, 0, 180,
                true};
  return line_plot_svg(plot, lines);
}

std::string profile_csv(const AcuityTable& acuity, const std::vector<ProfileSeries>& series) {
  std::string csv = "edge_angle_deg,acuity";
  for (const auto& s : series) {
    std::string label = s.label;
    std::replace(label.begin(), label.end(), ',', ';');
    csv += "," + label;
  }
  csv += "\n";
  for (size_t i = 0; i < acuity.angles_deg.size(); ++i) {
    csv += fmt::format("{},{}", acuity.angles_deg[i], acuity.weights[i]);
    for (const auto& s : series) csv += fmt::format(",{:.10g}", s.values[i]);
    csv += "\n";
  }
  return csv;
}

}  // namespace aapat

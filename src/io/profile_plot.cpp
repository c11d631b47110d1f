#include "io/profile_plot.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "io/xml.h"

namespace aapat {

std::string profile_svg(const AcuityTable& acuity, const std::vector<ProfileSeries>& series,
                        const std::string& title) {
  constexpr double kW = 760, kH = 440, kLeft = 60, kRight = 200, kTop = 40, kBottom = 50;
  constexpr const char* kColors[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd",
                                     "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};
  double ymax = 0;
  for (const auto& s : series)
    for (double v : s.values) ymax = std::max(ymax, v);
  ymax = ymax > 0 ? ymax * 1.1 : 1;
  const double pw = kW - kLeft - kRight, ph = kH - kTop - kBottom;
  auto px = [&](double deg) { return kLeft + pw * deg / 180.0; };
  auto py = [&](double v) { return kTop + ph * (1 - v / ymax); };

  // Angles as edge directions folded into [0, 180), in increasing order.
  std::vector<size_t> order(acuity.angles_deg.size());
  std::iota(order.begin(), order.end(), 0);
  auto folded = [&](size_t i) {
    const double a = std::fmod(acuity.angles_deg[i], 180.0);
    return a < 0 ? a + 180 : a;
  };
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return folded(a) < folded(b); });

  std::string svg = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} "
      "{1}\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" "
      "fill=\"white\"/>\n<text x=\"{2}\" y=\"24\" font-size=\"15\">{3}</text>\n",
      kW, kH, kLeft, xml_escape(title));
  // Axes, ticks every 45 degrees and five value ticks.
  svg += fmt::format(
      "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#333\"/>\n", kLeft,
      kTop, pw, ph);
  for (int deg = 0; deg <= 180; deg += 45)
    svg += fmt::format(
        "<line x1=\"{0:.1f}\" y1=\"{1}\" x2=\"{0:.1f}\" y2=\"{2}\" stroke=\"#ddd\"/><text "
        "x=\"{0:.1f}\" y=\"{3}\" text-anchor=\"middle\">{4}</text>\n",
        px(deg), kTop, kTop + ph, kTop + ph + 16, deg);
  for (int i = 0; i <= 5; ++i) {
    const double v = ymax * i / 5;
    svg += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"end\">{:.3f}</text>\n",
                       kLeft - 6, py(v) + 4, v);
  }
  svg += fmt::format(
      "<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">edge angle (degrees)</text>\n",
      kLeft + pw / 2, kH - 12);
  svg += fmt::format(
      "<text transform=\"translate(16 {:.1f}) rotate(-90)\" text-anchor=\"middle\">W(&#952;) "
      "E1(&#952;)</text>\n",
      kTop + ph / 2);
  for (size_t s = 0; s < series.size(); ++s) {
    const char* color = kColors[s % std::size(kColors)];
    std::string points;
    for (size_t i : order)
      points += fmt::format("{:.2f},{:.2f} ", px(folded(i)), py(series[s].values[i]));
    // Past ten series the colours repeat, dashed.
    const char* dash = s < std::size(kColors) ? "none" : "6,3";
    svg += fmt::format(
        "<polyline points=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"2\" "
        "stroke-dasharray=\"{}\"/>\n",
        points, color, dash);
    if (order.size() <= 48)
      for (size_t i : order)
        svg += fmt::format("<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"3.5\" fill=\"{}\"/>\n",
                           px(folded(i)), py(series[s].values[i]), color);
    const double ly = kTop + 10 + 18.0 * s;
    svg += fmt::format(
        "<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{2:.1f}\" y2=\"{1:.1f}\" stroke=\"{3}\" "
        "stroke-width=\"3\"/><text x=\"{4:.1f}\" y=\"{5:.1f}\">{6}</text>\n",
        kLeft + pw + 12, ly, kLeft + pw + 32, color, kLeft + pw + 38, ly + 4,
        xml_escape(series[s].label));
  }
  return svg + "</svg>\n";
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

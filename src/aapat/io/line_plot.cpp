#include "aapat/io/line_plot.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "aapat/io/xml.h"

namespace aapat {

std::string line_plot_svg(const LinePlot& plot, const std::vector<LineSeries>& series) {
  constexpr double kW = 760, kH = 440, kLeft = 60, kRight = 200, kTop = 40, kBottom = 50;
  constexpr const char* kColors[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd",
                                     "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};
  double x0 = plot.x_min, x1 = plot.x_max, y0 = INFINITY, y1 = -INFINITY;
  const bool auto_x = x0 == x1;
  if (auto_x) x0 = INFINITY, x1 = -INFINITY;
  for (const auto& s : series) {
    for (double v : s.y) y0 = std::min(y0, v), y1 = std::max(y1, v);
    if (auto_x)
      for (double v : s.x) x0 = std::min(x0, v), x1 = std::max(x1, v);
  }
  if (!(y1 > y0)) y0 = 0, y1 = y1 > 0 ? y1 : 1;
  if (plot.y_from_zero) y0 = 0;
  y1 += (y1 - y0) * 0.1;
  if (!(x1 > x0)) x1 = x0 + 1;
  const double pw = kW - kLeft - kRight, ph = kH - kTop - kBottom;
  auto px = [&](double x) { return kLeft + pw * (x - x0) / (x1 - x0); };
  auto py = [&](double y) { return kTop + ph * (1 - (y - y0) / (y1 - y0)); };

  std::string svg = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} "
      "{1}\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" "
      "fill=\"white\"/>\n<text x=\"{2}\" y=\"24\" font-size=\"15\">{3}</text>\n"
      "<rect x=\"{2}\" y=\"{4}\" width=\"{5}\" height=\"{6}\" fill=\"none\" stroke=\"#333\"/>\n",
      kW, kH, kLeft, xml_escape(plot.title), kTop, pw, ph);
  std::vector<double> ticks = plot.x_ticks;
  if (ticks.empty())
    for (int i = 0; i <= 4; ++i) ticks.push_back(x0 + (x1 - x0) * i / 4);
  for (double t : ticks)
    svg += fmt::format(
        "<line x1=\"{0:.1f}\" y1=\"{1}\" x2=\"{0:.1f}\" y2=\"{2}\" stroke=\"#ddd\"/><text "
        "x=\"{0:.1f}\" y=\"{3}\" text-anchor=\"middle\">{4:g}</text>\n",
        px(t), kTop, kTop + ph, kTop + ph + 16, t);
  for (int i = 0; i <= 5; ++i) {
    const double v = y0 + (y1 - y0) * i / 5;
    svg += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"end\">{:.3f}</text>\n",
                       kLeft - 6, py(v) + 4, v);
  }
  svg += fmt::format(
      "<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">{}</text>\n<text "
      "transform=\"translate("
      "16 {:.1f}) rotate(-90)\" text-anchor=\"middle\">{}</text>\n",
      kLeft + pw / 2, kH - 12, xml_escape(plot.x_label), kTop + ph / 2, xml_escape(plot.y_label));
  for (size_t s = 0; s < series.size(); ++s) {
    const char* color = kColors[s % std::size(kColors)];
    // Past ten series the colours repeat, dashed.
    const char* dash = s < std::size(kColors) ? "none" : "6,3";
    std::string points;
    for (size_t i = 0; i < series[s].x.size(); ++i)
      points += fmt::format("{:.2f},{:.2f} ", px(series[s].x[i]), py(series[s].y[i]));
    svg += fmt::format(
        "<polyline points=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"2\" "
        "stroke-dasharray=\"{}\"/>\n",
        points, color, dash);
    if (series[s].x.size() <= 48)
      for (size_t i = 0; i < series[s].x.size(); ++i)
        svg += fmt::format("<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"3.5\" fill=\"{}\"/>\n",
                           px(series[s].x[i]), py(series[s].y[i]), color);
    const double ly = kTop + 10 + 18.0 * s;
    svg += fmt::format(
        "<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{2:.1f}\" y2=\"{1:.1f}\" stroke=\"{3}\" "
        "stroke-width=\"3\" stroke-dasharray=\"{4}\"/><text x=\"{5:.1f}\" "
        "y=\"{6:.1f}\">{7}</text>\n",
        kLeft + pw + 12, ly, kLeft + pw + 32, color, dash, kLeft + pw + 38, ly + 4,
        xml_escape(series[s].label));
  }
  return svg + "</svg>\n";
}

}  // namespace aapat

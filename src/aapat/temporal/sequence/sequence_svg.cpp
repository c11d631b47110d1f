#include "aapat/temporal/sequence/sequence_svg.h"

#include <fmt/format.h>

#include "aapat/io/line_plot.h"
#include "aapat/io/xml.h"

namespace aapat {

std::string sequence_svg(const Sequence& s) {
  validate(s);
  constexpr double kPixel = 360, kMargin = 30;
  const double size = kPixel + 2 * kMargin;
  auto sx = [&](double x) { return kMargin + (x + 0.5) * kPixel; };
  auto sy = [&](double y) { return kMargin + (0.5 - y) * kPixel; };  // y up
  std::string svg = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0:.0f}\" height=\"{1:.0f}\" "
      "viewBox=\"0 0 {0:.0f} {1:.0f}\" font-family=\"sans-serif\">\n"
      "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      "<rect x=\"{2:.0f}\" y=\"{2:.0f}\" width=\"{3:.0f}\" height=\"{3:.0f}\" fill=\"none\" "
      "stroke=\"#888\"/>\n"
      "<text x=\"{2:.0f}\" y=\"{4:.0f}\" font-size=\"13\">{5}: {6} frames, numbered in time "
      "order</text>\n",
      size, size + 10, kMargin, kPixel, kMargin - 10, xml_escape(s.name), s.period());
  const int k = s.period();
  for (int f = 0; f < k; ++f) {
    const double t = k > 1 ? double(f) / (k - 1) : 0;
    const std::string colour = fmt::format("rgb({},{},{})", static_cast<int>(40 + 200 * t), 60,
                                           static_cast<int>(240 - 200 * t));
    for (const Vec2 v : s.frames[static_cast<size_t>(f)].sets[0])
      svg += fmt::format(
          "<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"4\" fill=\"{}\"/>\n<text x=\"{:.2f}\" "
          "y=\"{:.2f}\" font-size=\"11\" fill=\"{}\">{}</text>\n",
          sx(v.x), sy(v.y), colour, sx(v.x) + 5, sy(v.y) - 5, colour, f);
  }
  return svg + "</svg>\n";
}

std::string convergence_svg(const std::vector<CurveSeries>& series, const std::string& title) {
  LinePlot plot;
  plot.title = title;
  plot.x_label = "frame after the cut";
  plot.y_label = "E2 of the image shown";
  std::vector<LineSeries> lines;
  for (const CurveSeries& c : series) {
    LineSeries l{c.label, {}, c.e2};
    for (size_t f = 0; f < c.e2.size(); ++f) l.x.push_back(static_cast<double>(f));
    lines.push_back(std::move(l));
  }
  return line_plot_svg(plot, lines);
}

}  // namespace aapat

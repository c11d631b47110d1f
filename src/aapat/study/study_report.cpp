#include "aapat/study/study_report.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "aapat/core/metric.h"
#include "aapat/core/text.h"
#include "aapat/io/pattern_svg.h"
#include "aapat/io/png_image.h"
#include "aapat/io/scene_json.h"
#include "aapat/io/xml.h"
#include "aapat/render/image_error.h"
#include "aapat/render/renderer.h"

namespace aapat {
namespace {

constexpr const char* kStyle = R"(
body { font: 14px/1.45 system-ui, sans-serif; margin: 24px auto; max-width: 1100px; color: #222; }
h1 { font-size: 22px; } h2 { font-size: 18px; margin-top: 36px; border-top: 1px solid #ccc; padding-top: 12px; }
figure { display: inline-block; margin: 8px 12px 8px 0; vertical-align: top; max-width: 100%; }
figure svg { max-width: 100%; height: auto; }
figcaption { font-size: 12px; color: #555; max-width: 420px; }
table { border-collapse: collapse; font-size: 12px; margin: 8px 0; }
td, th { border: 1px solid #ddd; padding: 2px 6px; text-align: right; }
td:first-child, th:first-child { text-align: left; }
.best { background: #e6f4e6; } .note { color: #555; }
img.crop { image-rendering: pixelated; border: 1px solid #aaa; }
)";

// Checks, once the page has loaded, that every figure shows something:
// images decoded with a size, drawings laid out with one. The result goes
// in the page (the browser test reads it) and nowhere else.
constexpr const char* kCheck = R"(
window.addEventListener('load', function () {
  var figures = document.querySelectorAll('figure');
  var shown = 0;
  figures.forEach(function (f) {
    var ok = true;
    f.querySelectorAll('img').forEach(function (i) { if (!i.complete || i.naturalWidth === 0) ok = false; });
    f.querySelectorAll('svg').forEach(function (s) { var r = s.getBoundingClientRect(); if (r.width === 0 || r.height === 0) ok = false; });
    if (f.querySelectorAll('img, svg').length === 0) ok = false;
    if (ok) shown += 1;
  });
  document.body.setAttribute('data-figures', figures.length);
  document.body.setAttribute('data-figures-shown', shown);
});
)";

std::string fixed(double v, int digits = 3) {
  return std::isnan(v) ? "-" : fmt::format("{:.{}f}", v, digits);
}

// The largest finite value of a column, for scaling plots.
double largest(const std::vector<double>& v) {
  double m = 0;
  for (double x : v)
    if (std::isfinite(x)) m = std::max(m, x);
  return m > 0 ? m : 1;
}

// W E1 every degree for a few patterns, as curves r(theta) on a polar grid
// (an edge at theta and theta + 180 degrees is the same edge: drawn twice).
std::string polar_svg(const std::vector<const StudyPattern*>& patterns) {
  constexpr double kSize = 320, kC = kSize / 2, kR = 140;
  const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"};
  double top = 0;
  for (const StudyPattern* p : patterns) top = std::max(top, largest(p->profile));
  std::string s = fmt::format(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="{0}" height="{1}" viewBox="0 0 {0} {1}">)",
      kSize + 160, kSize);
  for (int ring = 1; ring <= 4; ++ring)
    s += fmt::format(R"(<circle cx="{}" cy="{}" r="{:.1f}" fill="none" stroke="#ddd"/>)", kC, kC,
                     kR * ring / 4);
  s += fmt::format(R"(<text x="{:.0f}" y="{:.0f}" font-size="10" fill="#777">W E1 = {:.3f}</text>)",
                   kC + 4, kC - kR - 2, top);
  for (size_t i = 0; i < patterns.size(); ++i) {
    const auto& v = patterns[i]->profile;
    std::string d;
    for (size_t k = 0; k <= 2 * v.size(); ++k) {
      const double value = v[k % v.size()], a = kPi * double(k) / double(v.size());
      const double r = kR * value / top;
      d += fmt::format("{}{:.1f},{:.1f} ", k == 0 ? "M" : "L", kC + r * std::cos(a),
                       kC - r * std::sin(a));
    }
    const char* c = colours[i % 6];
    s += fmt::format(R"(<path d="{}" fill="none" stroke="{}" stroke-width="1.5"/>)", d, c);
    s += fmt::format(
        R"(<rect x="{}" y="{}" width="10" height="10" fill="{}"/><text x="{}" y="{}" font-size="11">{}</text>)",
        kSize + 4, 20 + 16 * i, c, kSize + 18, 29 + 16 * i,
        xml_escape(std::string(utf8_prefix(patterns[i]->name, 22))));
  }
  return s + "</svg>";
}

// One objective against the mean RMSE over the scenes, a dot per pattern.
std::string scatter_svg(const BudgetStudy& b, int objective, const std::string& title) {
  constexpr double kW = 360, kH = 260, kL = 50, kB = 36, kT = 24, kRight = 12;
  std::vector<double> x, y;
  for (const StudyPattern& p : b.patterns) {
    x.push_back(p.objective[static_cast<size_t>(objective)]);
    double sum = 0;
    for (const auto& m : p.measures) sum += m[0];
    y.push_back(sum / double(p.measures.size()));
  }
  const auto [xlo_it, xhi_it] = std::minmax_element(x.begin(), x.end());
  const auto [ylo_it, yhi_it] = std::minmax_element(y.begin(), y.end());
  const double xlo = *xlo_it, xhi = std::max(*xhi_it, xlo + 1e-9), ylo = *ylo_it,
               yhi = std::max(*yhi_it, ylo + 1e-9);
  auto px = [&](double v) { return kL + (v - xlo) / (xhi - xlo) * (kW - kL - kRight); };
  auto py = [&](double v) { return kH - kB - (v - ylo) / (yhi - ylo) * (kH - kB - kT); };
  std::string s = fmt::format(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="{0}" height="{1}" viewBox="0 0 {0} {1}">)",
      kW, kH);
  s += fmt::format(R"(<text x="{}" y="15" font-size="12">{}</text>)", kL, xml_escape(title));
  s += fmt::format(
      R"(<line x1="{0}" y1="{1}" x2="{2}" y2="{1}" stroke="#444"/><line x1="{0}" y1="{3}" x2="{0}" y2="{1}" stroke="#444"/>)",
      kL, kH - kB, kW - kRight, kT);
  s += fmt::format(
      R"(<text x="{}" y="{}" font-size="10">{}</text><text x="{}" y="{}" font-size="10" text-anchor="end">{}</text>)",
      kL, kH - kB + 14, fixed(xlo), kW - kRight, kH - kB + 14, fixed(xhi));
  s += fmt::format(
      R"(<text x="{}" y="{}" font-size="10" text-anchor="end">{}</text><text x="{}" y="{}" font-size="10" text-anchor="end">{}</text>)",
      kL - 4, kH - kB, fixed(ylo, 2), kL - 4, kT + 8, fixed(yhi, 2));
  s += fmt::format(R"(<text x="{}" y="{}" font-size="11" text-anchor="middle">objective E2</text>)",
                   (kL + kW) / 2, kH - 6);
  s += fmt::format(
      R"svg(<text x="12" y="{}" font-size="11" transform="rotate(-90 12 {})" text-anchor="middle">mean RMSE</text>)svg",
      (kT + kH - kB) / 2, (kT + kH - kB) / 2);
  for (size_t i = 0; i < x.size(); ++i)
    s += fmt::format(
        R"(<circle cx="{:.1f}" cy="{:.1f}" r="3" fill="#1f77b4" fill-opacity="0.7"><title>{}</title></circle>)",
        px(x[i]), py(y[i]), xml_escape(b.patterns[i].name));
  return s + "</svg>";
}

// A rendering as a PNG data URI, each pixel drawn `zoom` x `zoom`.
std::string png_uri(int w, int h, const std::vector<uint8_t>& pixels, int zoom) {
  std::vector<uint8_t> big(static_cast<size_t>(w * zoom) * (h * zoom));
  for (int y = 0; y < h * zoom; ++y)
    for (int x = 0; x < w * zoom; ++x)
      big[static_cast<size_t>(y) * (w * zoom) + x] =
          pixels[static_cast<size_t>(y / zoom) * w + x / zoom];
  return "data:image/png;base64," + base64(png_gray_bytes(w * zoom, h * zoom, big));
}

std::string budget_section(const StudyResult& r, const BudgetStudy& b, const StudySettings& s,
                           const ReferenceSource& references) {
  const size_t rec = static_cast<size_t>(r.recommended), pap = static_cast<size_t>(r.papers);
  auto best_by = [&](auto keep, size_t objective) {
    const StudyPattern* best = nullptr;
    for (const StudyPattern& p : b.patterns)
      if (keep(p) && (!best || p.objective[objective] < best->objective[objective])) best = &p;
    return best;
  };
  const StudyPattern* best_rec = best_by([](const StudyPattern&) { return true; }, rec);
  const StudyPattern* best_pap = best_by([](const StudyPattern&) { return true; }, pap);
  const StudyPattern* best_catalog =
      best_by([](const StudyPattern& p) { return p.source == "catalog"; }, pap);
  std::string h =
      fmt::format(R"(<section id="budget-{0}"><h2>{0} samples per pixel ({1} patterns)</h2>)",
                  b.budget, b.patterns.size());
  // The patterns drawn.
  std::vector<GalleryItem> gallery;
  for (const StudyPattern& p : b.patterns)
    gallery.push_back({p.pattern, std::string(utf8_prefix(p.name, 24)),
                       fmt::format("E2 {:.3f}", p.objective[rec])});
  h += "<figure><figcaption>Every pattern of this budget, its samples as weight discs, with E2 "
       "under the recommended objective.</figcaption>" +
       gallery_svg(gallery, 8, "") + "</figure>";
  // Per-angle curves.
  std::vector<const StudyPattern*> curves;
  for (const StudyPattern* p : {best_rec, best_pap, best_catalog})
    if (p && std::find(curves.begin(), curves.end(), p) == curves.end()) curves.push_back(p);
  h += "<figure><figcaption>W E1 at every edge angle (uniform weights, 1 degree): the best "
       "pattern under the recommended and the papers' objectives and the best catalog "
       "pattern.</figcaption>" +
       polar_svg(curves) + "</figure>";
  // Scatter plots.
  for (const size_t o : {pap, rec}) {
    h += "<figure><figcaption>" + xml_escape(r.objectives[o].name()) +
         fmt::format(" against the mean RMSE over the scenes: Spearman {:.3f} (mean over scenes)",
                     measure_spearman(b, int(o), 0).mean) +
         "</figcaption>" + scatter_svg(b, static_cast<int>(o), r.objectives[o].name()) +
         "</figure>";
  }
  // Renderings of the first static scene (else the last), with their errors.
  std::string scene = s.scenes.back();
  for (const std::string& sc : s.scenes)
    if (sc != "triangle" && sc != "circle" && sc != "halfplane") {
      scene = sc;
      break;
    }
  if (scene != "triangle" && scene != "circle" && scene != "halfplane") {
    const Scene sc = resolve_scene(scene, s.width, s.height);
    ReferenceSettings ref = s.reference;
    ref.seed = frame_reference_seed(ref.seed, 0);
    const Image reference = references(sc, s.width, s.height, ref, 0);
    h += "<figure><figcaption>" + xml_escape(scene) +
         ": each pattern's rendering (its own weights) and its error (white: none, black: 10% "
         "or more).</figcaption><div>";
    for (const StudyPattern* p : curves) {
      Sampling sampling;
      sampling.pattern = p->pattern;
      const Image image = render(sc, s.width, s.height, sampling, std::nullopt);
      h += fmt::format(
          R"(<div style="display:inline-block;margin-right:10px"><div class="note">{}</div><img class="crop" alt="rendering" src="{}"> <img class="crop" alt="error" src="{}"></div>)",
          xml_escape(p->name), png_uri(s.width, s.height, level_pixels(image), 3),
          png_uri(s.width, s.height, error_pixels(image, reference), 3));
    }
    h += "</div></figure>";
  }
  // The correlation table: each objective's mean Spearman per measure.
  h += "<table><tr><th>objective</th>";
  for (const char* m : kStudyMeasures) h += fmt::format("<th>{}</th>", m);
  h += "<th>mean</th></tr>";
  for (size_t o = 0; o < r.objectives.size(); ++o) {
    h += fmt::format(R"(<tr{}><td>{}</td>)", o == rec ? R"( class="best")" : "",
                     xml_escape(r.objectives[o].name()));
    for (size_t m = 0; m < kStudyMeasures.size(); ++m) {
      const MeasureSpearman s = measure_spearman(b, int(o), int(m));
      h += fmt::format("<td>{} <span class=\"note\">[{}, {}]</span></td>", fixed(s.mean),
                       fixed(s.low, 2), fixed(s.high, 2));
    }
    h += fmt::format("<td>{}</td></tr>", fixed(b.mean_spearman[o]));
  }
  h += "</table><p class=\"note\">Spearman's rho averaged over the scenes; in brackets the "
       "widest bootstrap interval of the scenes' (95%).</p>";
  // The patterns.
  h += "<table><tr><th>pattern</th><th>source</th>";
  for (const StudyObjective& o : r.objectives) h += "<th>" + xml_escape(o.name()) + "</th>";
  h += "<th>mean RMSE</th></tr>";
  for (const StudyPattern& p : b.patterns) {
    double rmse = 0;
    for (const auto& m : p.measures) rmse += m[0] / double(p.measures.size());
    h += "<tr><td>" + xml_escape(p.name) + "</td><td>" + xml_escape(p.source) + "</td>";
    for (const double v : p.objective) h += "<td>" + fixed(v) + "</td>";
    h += "<td>" + fixed(rmse, 2) + "</td></tr>";
  }
  return h + "</table></section>";
}

}  // namespace

std::string base64(const std::string& bytes) {
  static const char* kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const uint32_t v = (uint32_t(uint8_t(bytes[i])) << 16) |
                       (uint32_t(uint8_t(bytes[i + 1])) << 8) | uint8_t(bytes[i + 2]);
    for (int k = 3; k >= 0; --k) out += kAlphabet[(v >> (6 * k)) & 63];
  }
  if (i < bytes.size()) {
    uint32_t v = uint32_t(uint8_t(bytes[i])) << 16;
    if (i + 1 < bytes.size()) v |= uint32_t(uint8_t(bytes[i + 1])) << 8;
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? kAlphabet[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

std::string study_report_html(const StudyResult& r, const StudySettings& s,
                              const ReferenceSource& references) {
  std::string scenes;
  for (const std::string& sc : r.scenes) scenes += (scenes.empty() ? "" : ", ") + sc;
  const size_t rec = static_cast<size_t>(r.recommended), pap = static_cast<size_t>(r.papers);
  std::string h =
      "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
      "<title>aapat study: which objective predicts rendered error</title><style>" +
      std::string(kStyle) + "</style><script>" + kCheck + "</script></head><body>";
  h += "<h1>Which objective predicts rendered error?</h1>";
  h += "<p>" +
       fmt::format(
           "{} objectives (filter {}), {} scenes ({}) at {}&times;{} pixels, {} "
           "frames per animation, references of {} jittered samples per pixel "
           "with {}; seed {}.",
           r.objectives.size(), xml_escape(s.filter), r.scenes.size(), xml_escape(scenes), s.width,
           s.height, s.frames, s.reference.samples, xml_escape(s.reference.filter), s.seed) +
       "</p>";
  h += "<p><b>Recommended objective: " + xml_escape(r.objectives[rec].name()) +
       fmt::format(
           "</b>, mean Spearman {:.3f} over every budget, scene and measure; the papers' "
           "{} has {:.3f}.</p>",
           r.mean_spearman[rec], xml_escape(r.objectives[pap].name()), r.mean_spearman[pap]);
  for (const BudgetStudy& b : r.budgets) h += budget_section(r, b, s, references);
  return h + "</body></html>\n";
}

}  // namespace aapat

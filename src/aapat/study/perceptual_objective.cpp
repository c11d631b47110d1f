#include "aapat/study/perceptual_objective.h"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "aapat/analyze/flip_gradient.h"
#include "aapat/core/geometry.h"
#include "aapat/core/portable_math.h"
#include "aapat/io/json_report.h"
#include "aapat/render/image_flip.h"
#include "aapat/render/reference.h"
#include "aapat/render/renderer.h"
#include "aapat/render/thin_geometry.h"

namespace aapat {
namespace {

// Spacings of the repeated primitives, in pixels: not whole numbers, so that
// successive copies cross the pixel grid at different phases; wide enough
// that FLIP's contrast filters (a standard deviation of about a pixel at
// 67 ppd) see each copy apart.
constexpr double kLineSpacing = 6.7, kEdgeSpacing = 11.3, kDotSpacing = 5.3;
constexpr double kDotLatticeAngles[] = {0.3, 1.1};  // radians
// The charts' centre, off the pixel grid by an irrational-looking amount.
constexpr double kCentreShiftX = 0.137, kCentreShiftY = 0.291;

const Registry<PerceptualSpec>& registry() {
  static const Registry<PerceptualSpec> kRegistry(
      "objective",
      {{{std::string(kPerceptualObjective),
         "FLIP's model on test charts of straight edges, lines narrower than a pixel and dots "
         "at every direction: the mean FLIP of the pattern's renderings against the ideal",
         "FLIP (Andersson et al. 2020) applied to E2's edges and to thin features; "
         "study/perceptual_objective.h",
         {{"ppd", "67.02", "the FLIP observer's pixels per degree, 1 to 1000"},
          {"angles", "16", "directions of edges and lines over 180 degrees, 1 to 90"},
          {"patch", "48", "chart side in pixels, 16 to 256"},
          {"line", "0.5", "width of the wider line in pixels, 0 (none) to 4"},
          {"thin", "0.2", "width of the thinner line in pixels, 0 (none) to 4"},
          {"dot", "0.8", "dot diameter in pixels, 0 (none) to 4"},
          {"edge", "1", "1: straight edges, 0: none"},
          {"background", "0.25", "grey level of the background, 0 to 1"},
          {"foreground", "0.75", "grey level of the primitives, 0 to 1"},
          {"reference", "256", "jittered samples per pixel of the ideal (a square), 16 to 4096"},
          {"box", "0",
           "1: the ideal is the box-filtered pixel; 0: the study's Mitchell-Netravali "
           "reference"}}},
        [](const Spec& s) {
          PerceptualSpec p;
          p.ppd = s.in_range("ppd", kMinPixelsPerDegree, kMaxPixelsPerDegree);
          p.angles = s.whole("angles", 1, 90);
          p.patch = s.whole("patch", 16, 256);
          p.line = s.in_range("line", 0, 4);
          p.thin = s.in_range("thin", 0, 4);
          p.dot = s.in_range("dot", 0, 4);
          p.edge = s.whole("edge", 0, 1) == 1;
          p.background = s.in_range("background", 0, 1);
          p.foreground = s.in_range("foreground", 0, 1);
          p.reference = s.whole("reference", 16, 4096);
          p.box = s.whole("box", 0, 1) == 1;
          const int root = static_cast<int>(std::lround(std::sqrt(p.reference)));
          if (root * root != p.reference)
            throw ParameterError(
                "reference", fmt::format(" {}: expected a square number of samples", p.reference));
          if (p.line == 0 && p.thin == 0 && p.dot == 0 && !p.edge)
            throw ParameterError("perceptual",
                                 ": no primitives (give edge=1 or a line, thin or dot width)");
          if (p.background == p.foreground)
            throw ParameterError("foreground",
                                 fmt::format(" {}: equals the background; the charts would be "
                                             "blank",
                                             p.foreground));
          return p;
        }}});
  return kRegistry;
}

// Parallel bars at `angle`, `spacing` apart, across a chart of side p.
Scene bars(const PerceptualSpec& s, double angle, double width, double spacing) {
  ShapesScene scene;
  scene.background = s.background;
  const double p = s.patch, c = (p - 1) / 2;
  const Vec2 centre{c + kCentreShiftX, c + kCentreShiftY};
  const double dx = portable_cos(angle), dy = portable_sin(angle);
  const int copies = static_cast<int>(std::ceil(0.75 * p / spacing)) + 1;
  for (int k = -copies; k <= copies; ++k) {
    const Vec2 m{centre.x - dy * k * spacing, centre.y + dx * k * spacing};
    scene.shapes.push_back(
        bar_shape({m.x - dx * p, m.y - dy * p}, {m.x + dx * p, m.y + dy * p}, width, s.foreground));
  }
  index_shapes(scene);
  return Scene{std::move(scene)};
}

// Discs of diameter s.dot on a lattice turned by `angle`.
Scene dots(const PerceptualSpec& s, double angle) {
  ShapesScene scene;
  scene.background = s.background;
  const double p = s.patch, c = (p - 1) / 2;
  const double dx = portable_cos(angle), dy = portable_sin(angle);
  const int copies = static_cast<int>(std::ceil(0.75 * p / kDotSpacing)) + 1;
  for (int i = -copies; i <= copies; ++i)
    for (int j = -copies; j <= copies; ++j) {
      // A slightly sheared lattice, so rows do not repeat one phase.
      const double u = i * kDotSpacing + 0.37 * j, v = j * kDotSpacing;
      const Vec2 at{c + kCentreShiftX + dx * u - dy * v, c + kCentreShiftY + dy * u + dx * v};
      if (at.x < -2 || at.y < -2 || at.x > p + 1 || at.y > p + 1) continue;
      Shape d;
      d.centre = at;
      d.radius = s.dot / 2;
      d.grey = s.foreground;
      scene.shapes.push_back(std::move(d));
    }
  index_shapes(scene);
  return Scene{std::move(scene)};
}

}  // namespace

std::string PerceptualSpec::text() const {
  return fmt::format(
      "{}:ppd={},angles={},patch={},line={},thin={},dot={},edge={},background={},foreground={},"
      "reference={},box={}",
      kPerceptualObjective, ppd, angles, patch, line, thin, dot, edge ? 1 : 0, background,
      foreground, reference, box ? 1 : 0);
}

const SpecInfo& perceptual_info() {
  return registry().entries().front().info;
}

PerceptualSpec parse_perceptual(std::string_view text) {
  return registry().make(text);
}

bool is_perceptual(std::string_view text) {
  return split_spec(text).first == kPerceptualObjective;
}

PerceptualObjective::PerceptualObjective(PerceptualSpec spec) : spec_(std::move(spec)) {
  const auto add_kind = [&](const char* name) {
    kinds_.emplace_back(name);
    return static_cast<int>(kinds_.size()) - 1;
  };
  const auto angle = [&](int a) { return a * kPi / spec_.angles; };
  if (spec_.edge) {
    const int k = add_kind("edges");
    for (int a = 0; a < spec_.angles; ++a)
      charts_.push_back({k, bars(spec_, angle(a), kEdgeSpacing / 2, kEdgeSpacing)});
  }
  if (spec_.line > 0 || spec_.thin > 0) {
    const int k = add_kind("lines");
    for (const double width : {spec_.line, spec_.thin})
      if (width > 0)
        for (int a = 0; a < spec_.angles; ++a)
          charts_.push_back({k, bars(spec_, angle(a), width, kLineSpacing)});
  }
  if (spec_.dot > 0) {
    const int k = add_kind("dots");
    for (const double a : kDotLatticeAngles) charts_.push_back({k, dots(spec_, a)});
  }
  ideal_ = render_ideals(0);
}

// Each chart's ideal image at `offset` (Image::offset), its FLIP half
// prepared: the study's reference (or the box pixel) from spec.reference
// samples per pixel, clamped to [0, 1] as the charts' renderings are.
std::vector<FlipReference> PerceptualObjective::render_ideals(double offset) const {
  ReferenceSettings reference;
  reference.samples = spec_.reference;
  reference.filter = spec_.box ? "box" : "mitchell";
  std::vector<FlipReference> out(charts_.size());
  tbb::parallel_for(size_t{0}, charts_.size(), [&](size_t c) {
    out[c] = prepare_flip_reference(
        color_image(render_reference(charts_[c].scene, spec_.patch, spec_.patch, reference, offset),
                    ColorLevels::kExact),
        spec_.ppd);
  });
  return out;
}

const std::vector<FlipReference>& PerceptualObjective::ideals(double offset) const {
  if (offset == 0) return ideal_;
  // A 2x2 or 4x4 footprint reconstructs at the pixel corners: its ideal is
  // rendered there, once.
  std::call_once(shifted_once_, [&] { shifted_ = render_ideals(0.5); });
  return shifted_;
}

PerceptualError PerceptualObjective::evaluate(const Pattern& pattern) const {
  std::vector<double> flips(charts_.size());
  Sampling sampling;
  sampling.pattern = pattern;
  tbb::parallel_for(size_t{0}, charts_.size(), [&](size_t c) {
    const Image image = render(charts_[c].scene, spec_.patch, spec_.patch, sampling, std::nullopt);
    flips[c] = flip(ideals(image.offset)[c], color_image(image, ColorLevels::kExact)).mean;
  });
  return combine(flips);
}

PerceptualError PerceptualObjective::combine(const std::vector<double>& flips) const {
  PerceptualError e;
  std::vector<int> counts(kinds_.size());
  for (const std::string& k : kinds_) e.kinds.push_back({k, 0});
  for (size_t c = 0; c < charts_.size(); ++c) {
    e.kinds[static_cast<size_t>(charts_[c].kind)].flip += flips[c];
    ++counts[static_cast<size_t>(charts_[c].kind)];
  }
  for (size_t k = 0; k < kinds_.size(); ++k) {
    e.kinds[k].flip /= counts[k];
    e.value += e.kinds[k].flip;
  }
  e.value /= static_cast<double>(kinds_.size());
  return e;
}

// d value / d (chart c's mean FLIP): 1 / (kinds x the charts of c's kind).
std::vector<double> PerceptualObjective::chart_shares() const {
  std::vector<int> counts(kinds_.size());
  for (const Chart& c : charts_) ++counts[static_cast<size_t>(c.kind)];
  std::vector<double> shares;
  for (const Chart& c : charts_)
    shares.push_back(1.0 /
                     (static_cast<double>(kinds_.size()) * counts[static_cast<size_t>(c.kind)]));
  return shares;
}

PerceptualGradient PerceptualObjective::gradient(const Pattern& pattern) const {
  return differentiate(pattern, false, true);
}

PerceptualGradient PerceptualObjective::gradient_in_double(const Pattern& pattern,
                                                           bool with_gradient) const {
  return differentiate(pattern, true, with_gradient);
}

PerceptualGradient PerceptualObjective::differentiate(const Pattern& pattern, bool in_double,
                                                      bool with_gradient) const {
  validate(pattern);
  Sampling sampling;
  sampling.pattern = pattern;
  std::vector<Kernel> kernels;
  std::vector<double> weight_sums;  // each kernel's raw weights' sum (make_kernel divides by it)
  for (int k = 0; k < pattern.set_count(); ++k) {
    kernels.push_back(make_kernel(pattern, k));
    double sum = 0;
    for (double w : pattern.weights[static_cast<size_t>(k)]) sum += w;
    weight_sums.push_back(sum);
  }
  const std::vector<double> shares = chart_shares();
  const int side = spec_.patch;
  std::vector<double> flips(charts_.size());
  // Each chart's gradient in its own slot, summed in chart order below.
  std::vector<std::vector<std::vector<double>>> per_chart(charts_.size());
  tbb::parallel_for(size_t{0}, charts_.size(), [&](size_t c) {
    const Scene& scene = charts_[c].scene;
    const Image image = render(scene, side, side, sampling, std::nullopt);
    const FlipReference& ideal = ideals(image.offset)[c];
    FlipGradient g;
    if (in_double) {
      // color_image's clamp and row order, in double.
      std::vector<double> rgb(3 * image.pixels());
      for (int j = 0; j < side; ++j)
        for (int i = 0; i < side; ++i)
          for (size_t ch = 0; ch < 3; ++ch)
            rgb[3 * (static_cast<size_t>(side - 1 - j) * side + i) + ch] =
                std::clamp(image.at(i, j), 0.0, 1.0);
      g = flip_gradient_in_double(ideal, rgb, with_gradient);
    } else {
      g = flip_gradient(ideal, color_image(image, ColorLevels::kExact));
    }
    flips[c] = g.mean;
    if (!with_gradient) return;
    auto& out = per_chart[c];
    for (const auto& w : pattern.weights) out.emplace_back(w.size(), 0.0);
    for (int j = 0; j < side; ++j)
      for (int i = 0; i < side; ++i) {
        const double value = image.values[static_cast<size_t>(j) * side + i];
        // color_image clamps to [0, 1] and turns the rows over (row 0 at the top).
        if (value < 0 || value > 1) continue;
        const size_t at = 3 * (static_cast<size_t>(side - 1 - j) * side + i);
        const double d_pixel = shares[c] * (g.d_rgb[at] + g.d_rgb[at + 1] + g.d_rgb[at + 2]);
        if (d_pixel == 0) continue;
        const int k = set_index(pattern, i, j);
        const Kernel& kernel = kernels[static_cast<size_t>(k)];
        const double sum = weight_sums[static_cast<size_t>(k)];
        for (int r = 0; r < kernel.size(); ++r) {
          const double v =
              shade(scene, {i + image.offset + kernel.x[r], j + image.offset + kernel.y[r]});
          out[static_cast<size_t>(k)][static_cast<size_t>(r)] += d_pixel * (v - value) / sum;
        }
      }
  });
  PerceptualGradient result{combine(flips), {}};
  for (const auto& w : pattern.weights) result.weights.emplace_back(w.size(), 0.0);
  for (const auto& chart : per_chart)
    for (size_t k = 0; k < chart.size(); ++k)
      for (size_t r = 0; r < chart[k].size(); ++r) result.weights[k][r] += chart[k][r];
  return result;
}

nlohmann::ordered_json perceptual_eval_json(const PerceptualSpec& spec,
                                            const std::vector<Pattern>& patterns,
                                            const std::vector<PerceptualError>& errors) {
  JsonObject rows = JsonObject::array();
  for (size_t i = 0; i < patterns.size(); ++i) {
    JsonObject kinds = JsonObject::object();
    for (const PerceptualKind& k : errors[i].kinds) kinds[k.name] = k.flip;
    rows.push_back({{"pattern", patterns[i].name},
                    {"family", family(patterns[i])},
                    {"n", samples_per_pixel(patterns[i])},
                    {"perceptual", errors[i].value},
                    {"kinds", kinds}});
  }
  JsonObject doc = json_report("eval");
  doc["objective"] = spec.text();
  doc["rows"] = rows;
  return doc;
}

}  // namespace aapat

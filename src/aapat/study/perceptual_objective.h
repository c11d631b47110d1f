// The perceptual objective: FLIP's model (analyze/flip.h) applied to what E2
// sweeps and to what E2 never sees. E2 integrates the error of straight
// edges only, and the patterns it favours push their samples onto the pixel
// border, which every edge crosses; a wire narrower than a pixel through the
// pixel's interior is then seen by one sample, and flickers in and out.
//
// Here a pattern renders a fixed set of test charts, each a few dozen pixels
// square: straight edges (wide bars), lines of two widths narrower than a
// pixel and dots, at `angles` directions spaced evenly over 180 degrees
// (and two lattices of dots), on a background, every primitive repeated
// across the chart at spacings that are not whole pixels so that its
// sub-pixel phases are all represented. Each rendering (the pattern's own
// weights, exactly per sample) is compared with the chart's ideal image by
// FLIP at `ppd` pixels per degree: the contrast sensitivity filters, the
// colour difference, its exponent and remap, the feature term (FLIP's edge
// and point detectors respond to thin lines and dots) and the mean. The
// value is the mean over the three kinds (edges, lines, dots; those given)
// of the mean FLIP of their charts: lower is better, 0 is the ideal.
//
// The ideal is, by default, the study's reference (Mitchell-Netravali over
// 4x4 pixels from `reference` jittered samples per pixel, the image every
// rendered measure of `aapat study` compares with), so that the objective
// aims at what the study measures; `box=1` makes it the box-filtered pixel
// (the exact coverage), a sharper ideal (docs/perceptual.md says why the
// default is the study's). The ideal's half of FLIP is prepared once.
//
// Text form, a spec (core/spec.h): `perceptual` or
// `perceptual:ppd=67,angles=16,line=0.5,thin=0.2,dot=0.8,edge=1,...`. The
// defaults of contrast and directions are the study's choice on its tuning
// views (docs/studies/perceptual-objective.md).
#pragma once

#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "aapat/analyze/flip.h"
#include "aapat/core/objective.h"
#include "aapat/core/pattern.h"
#include "aapat/core/spec.h"
#include "aapat/render/scene.h"

namespace aapat {

struct PerceptualSpec {
  double ppd = 67.02;  // the FLIP observer's pixels per degree, [1, 1000]
  int angles = 16;     // directions of edges and lines over 180 degrees
  int patch = 48;      // chart side in pixels
  double line = 0.5;   // width of the wider line in pixels (0: none)
  double thin = 0.2;   // width of the thinner line (0: none)
  double dot = 0.8;    // dot diameter in pixels (0: none)
  bool edge = true;    // the straight edges
  // Grey levels in [0, 1], sRGB-encoded: a contrast of one half, which ranks
  // patterns as FLIP does best (full contrast saturates FLIP's colour term).
  double background = 0.25, foreground = 0.75;
  int reference = 256;  // jittered samples per pixel of the ideal
  bool box = false;     // the ideal: box pixel (true) or Mitchell
  // "perceptual:ppd=67.02,angles=8,...": every parameter, parseable.
  std::string text() const;
};

// The spec's entry (name, summary, parameters with defaults) for `aapat list`.
const SpecInfo& perceptual_info();
// Parses "perceptual[:key=value,...]"; errors name the parameter
// (ParameterError): ppd outside [1, 1000], no primitive at all, a
// non-finite or out-of-range level, equal levels, an unknown key.
PerceptualSpec parse_perceptual(std::string_view text);
// Whether the text names the perceptual objective (its first word).
bool is_perceptual(std::string_view text);

struct PerceptualKind {
  std::string name;  // "edges", "lines", "dots"
  double flip = 0;   // mean FLIP over its charts
};

struct PerceptualError {
  double value = 0;  // the objective: the mean over the kinds
  std::vector<PerceptualKind> kinds;
};

// The objective and its gradient with respect to the pattern's weights, in
// the shape of Pattern::weights (kernel k, sample r). A rendered pixel is
// sum_r w_r v_r / sum_r w_r over its kernel's samples v_r, so d pixel / d w_r
// = (v_r - pixel) / sum_r w_r, times FLIP's image gradient
// (analyze/flip_gradient.h), summed over the charts as the value is.
// Positions have no such gradient: a chart is point-sampled, so the value
// moves in steps as a sample crosses a primitive's boundary and is flat in
// between (study/refine_search.h searches them without derivatives).
struct PerceptualGradient {
  PerceptualError error;
  std::vector<std::vector<double>> weights;
};

class PerceptualObjective {
 public:
  // Renders the charts' ideals (offset 0; the half-pixel ones on first use).
  explicit PerceptualObjective(PerceptualSpec spec);
  const PerceptualSpec& spec() const { return spec_; }
  int chart_count() const { return static_cast<int>(charts_.size()); }
  // Deterministic at any thread count: every chart in its own slot, summed in order.
  PerceptualError evaluate(const Pattern& pattern) const;
  double operator()(const Pattern& pattern) const { return evaluate(pattern).value; }
  // The value (the same as evaluate's) and its weight gradient.
  PerceptualGradient gradient(const Pattern& pattern) const;
  // The same with FLIP in double (analyze/flip_gradient.h's
  // flip_gradient_in_double): the value to about 1e-7, for central
  // differences at steps float cannot resolve (without `with_gradient`,
  // the value alone).
  PerceptualGradient gradient_in_double(const Pattern& pattern, bool with_gradient = true) const;

 private:
  struct Chart {
    int kind = 0;  // index into kinds_
    Scene scene;
  };
  const std::vector<FlipReference>& ideals(double offset) const;
  std::vector<FlipReference> render_ideals(double offset) const;
  // The objective from each chart's mean FLIP, and each chart's share of it.
  PerceptualError combine(const std::vector<double>& flips) const;
  std::vector<double> chart_shares() const;
  PerceptualGradient differentiate(const Pattern& pattern, bool in_double,
                                   bool with_gradient) const;

  PerceptualSpec spec_;
  std::vector<std::string> kinds_;
  std::vector<Chart> charts_;
  std::vector<FlipReference> ideal_;
  mutable std::vector<FlipReference> shifted_;
  mutable std::once_flag shifted_once_;
};

// `aapat eval --objective perceptual --json`: the spec, and per pattern its
// family, n, value and each kind's mean FLIP.
nlohmann::ordered_json perceptual_eval_json(const PerceptualSpec& spec,
                                            const std::vector<Pattern>& patterns,
                                            const std::vector<PerceptualError>& errors);

}  // namespace aapat

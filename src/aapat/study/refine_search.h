// A pattern refined under an objective that has no useful gradient: the
// perceptual objective (study/perceptual_objective.h) or a rendered measure
// over scenes (study/objective_study.h's RenderedObjective). A compass search
// (optimize/compass_search.h) over the free coordinates of its samples (a
// border sample slides along its border, a corner stays) and its weights
// (non-negative, each kernel's summing to 1), from a start that is usually
// the E2 optimum or a standard pattern of the same family. Both objectives
// change in steps where a sample crosses a primitive's boundary, so the
// search is derivative-free; it never returns a pattern worse than its
// start. With an API, every pattern it measures is first snapped to the
// API's 1/16-pixel lattice (core/lattice.h), so it searches the lattice's
// positions and free weights, and the result is on the lattice.
//
// The weights do have a gradient under the perceptual objective (a rendered
// pixel is linear in them; study/perceptual_objective.h): with
// `weight_steps`, the compass search's result is then polished by projected
// gradient descent on the weights, its positions held.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "aapat/core/pattern.h"
#include "aapat/study/objective_study.h"
#include "aapat/study/perceptual_objective.h"
#include "aapat/work/work_items.h"

namespace aapat {

inline constexpr int kMaxWeightSteps = 10'000;

struct RefineSettings {
  double step = 1.0 / 16, min_step = 1.0 / 256;  // pixels (weights: the same amounts)
  int max_tries = 4000;                          // objective evaluations at most
  std::string api;  // non-empty: keep the samples on this API's lattice (core/hardware_layout.h)
  // After the compass search, at most this many gradient steps on the
  // weights (0: none; needs an objective with a weight gradient).
  int weight_steps = 0;
};

// What the search minimizes and how the result records it: `text` goes into
// the provenance under "refined" and the value under `key`; the result is
// named START-`key`, improved or not.
struct RefineObjective {
  std::function<double(const Pattern&)> value;
  std::string text, key;
  // d value / d Pattern::weights where the objective has it (empty otherwise).
  std::function<std::vector<std::vector<double>>(const Pattern&)> weight_gradient;
};
// The objectives as the search takes them (each must outlive the search).
RefineObjective refine_objective(const PerceptualObjective& objective);  // key "perceptual"
RefineObjective refine_objective(const RenderedObjective& objective);    // key "rendered"

struct RefineResult {
  Pattern pattern;
  double start_value = 0, value = 0;
  int tries = 0;             // objective evaluations, the gradient steps' included
  double compass_value = 0;  // the value after the compass search alone
  int gradient_steps = 0;    // weight steps taken (each lowered the value)
};

// Throws ParameterError for settings out of range (steps in (0, 1], min_step
// at most step, max_tries in 1..10^7, weight_steps in 0..10^4, an unknown API) and Error naming the
// rule where the start cannot fit the API: before any work, so that a face
// can call it before it builds an expensive objective.
void validate(const RefineSettings& settings, const Pattern& start);

// validate(), then the search; ParameterError ("weight-steps") where weight
// steps are asked of an objective without a weight gradient.
RefineResult refine_pattern(const Pattern& start, const RefineObjective& objective,
                            const RefineSettings& settings, const ItemsProgress& progress = {});

// `aapat refine --json` (and Python's refine, which adds the pattern): the
// objective's text, the start's name and family, the API when one was
// given, the objective before and after, the evaluations.
nlohmann::ordered_json refine_json(const RefineObjective& objective, const Pattern& start,
                                   const RefineSettings& settings, const RefineResult& result);

}  // namespace aapat

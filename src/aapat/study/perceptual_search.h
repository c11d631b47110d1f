// A pattern refined under the perceptual objective (study/perceptual_objective.h):
// a compass search (optimize/compass_search.h) over the free coordinates of
// its samples (a border sample slides along its border, a corner stays) and
// its weights (non-negative, each kernel's summing to 1), from a start that
// is usually the E2 optimum or a standard pattern of the same family. The
// objective has no useful gradient (a sample's move changes the rendered
// charts in steps, where it crosses a primitive's boundary), so the search
// is derivative-free; it never returns a pattern worse than its start. The
// result is named START-perceptual.
#pragma once

#include <nlohmann/json.hpp>

#include "aapat/core/pattern.h"
#include "aapat/study/perceptual_objective.h"
#include "aapat/work/work_items.h"

namespace aapat {

struct PerceptualSearchSettings {
  double step = 1.0 / 16, min_step = 1.0 / 256;  // pixels (weights: the same amounts)
  int max_tries = 4000;                          // objective evaluations at most
};

struct PerceptualSearchResult {
  Pattern pattern;
  double start_value = 0, value = 0;
  int tries = 0;
};

// Throws ParameterError for settings out of range (steps in (0, 1], min_step
// at most step, max_tries in 1..10^7).
PerceptualSearchResult refine_perceptual(const Pattern& start, const PerceptualObjective& objective,
                                         const PerceptualSearchSettings& settings,
                                         const ItemsProgress& progress = {});

// `aapat refine --json` (and Python's refine, which adds the pattern): the
// spec, the start's name and family, the objective before and after, the
// evaluations.
nlohmann::ordered_json refine_json(const PerceptualSpec& spec, const Pattern& start,
                                   const PerceptualSearchResult& result);

}  // namespace aapat

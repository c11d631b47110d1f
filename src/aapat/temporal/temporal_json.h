// The JSON objects of the temporal results, made once: `aapat sequence eval
// --json`, `aapat optimize --sequence --json` and Python's sequence_eval and
// optimize_sequence return the same keys (docs/json.md). Flicker has one
// meaning wherever its name appears: `flicker` is the mean over the period's
// transitions, `worst_flicker` the largest, `flicker_per_transition` each.
#pragma once

#include "aapat/io/json_report.h"
#include "aapat/temporal/engine_taa.h"
#include "aapat/temporal/pan_model.h"
#include "aapat/temporal/pan_search.h"
#include "aapat/temporal/sequence.h"
#include "aapat/temporal/sequence_optimizer.h"
#include "aapat/temporal/temporal_metrics.h"

namespace aapat {

// One row of `sequence eval`: the sequence's name, frames, family and every measure.
JsonObject temporal_report_json(const Sequence& s, const TemporalReport& r);

// The settings and result of a sequence search, with the objective J and
// Halton's J of the same length; "result" holds the sequence file's object.
// `optimize --sequence K --taa PRESET --json` and Python's
// optimize_sequence_pan: the start's and the result's steady mean E2 per
// velocity and their means, and the result as a sequence file's object.
JsonObject pan_search_json(const PanSequenceSearch& search, const Objective& objective,
                           const PanSequenceSearchResult& r);

JsonObject sequence_search_json(const SequenceSearch& search, std::string_view model,
                                const Objective& objective, const SequenceSearchResult& r);

// `aapat animate SCENE --taa PRESET --json` and Python's engine_taa: the
// settings (preset, its settings' text, ratio, render size, motion, phases,
// warm-up) and the measures (rmse and max_deviation over every frame's
// pixels, mean_flip, flicker, ghosting, sharpness: means over frames;
// engine_taa.h), with a row per frame.
JsonObject engine_taa_json(std::string_view scene, const EngineRun& run, const Sequence& s,
                           const EngineTaa& taa, const EngineResult& r);

// The rows of `aapat sequence pan --json` (Python's sequence_pan returns
// them), one per sequence: sequence, phases, mean_e2 and flicker (the means
// over the velocities), velocities: [{velocity [dx, dy], mean_e2, flicker}];
// every row after the first, against_first: {sequence, lower_at,
// velocities, mean_change, lowest_change, highest_change} (its mean E2
// against the first's, pan_distribution.h; changes as fractions).
JsonObject::array_t pan_rows_json(const std::vector<Sequence>& sequences,
                                  const std::vector<Vec2>& velocities,
                                  const std::vector<std::vector<PanReport>>& reports);

}  // namespace aapat

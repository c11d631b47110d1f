// The pan model (model/pan_model.h) under an engine preset: every sequence
// at every velocity with the preset's reconstruction, history sampler and
// steady blend (moving or, at velocity 0, still), as `aapat sequence pan`
// and Python's sequence_pan report it. The table owns its derived numbers
// (the means over the velocities and each sequence against the first), so
// that the faces only format them.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "aapat/core/geometry.h"
#include "aapat/core/metric.h"
#include "aapat/io/json_report.h"
#include "aapat/temporal/engine/engine_taa_settings.h"
#include "aapat/temporal/model/pan_distribution.h"
#include "aapat/temporal/model/pan_model.h"
#include "aapat/temporal/sequence/sequence.h"
#include "aapat/work/work_items.h"

namespace aapat {

// The pan model of a preset's reconstruction and history sampler at its
// ratio, panning at `velocity`: one definition for the evaluation and the search.
PanModel pan_model_of(const EngineTaa& taa, Vec2 velocity);

struct PanRow {
  std::string sequence;
  int phases = 0;
  std::vector<PanReport> at;  // per velocity, in the table's order
  PanReport mean;             // the means over the velocities
  // Every row after the first: its mean E2 against the first row's.
  std::optional<PanComparison> against_first;
};

struct PanTable {
  std::vector<Vec2> velocities;
  std::vector<PanRow> rows;  // one per sequence, in the order given
};

// progress: (pairs done, pairs, "SEQUENCE at DX,DY") as each (sequence,
// velocity) finishes, one call at a time. Throws ParameterError naming
// "velocity" for one out of range, before any work starts.
PanTable evaluate_pans(const std::vector<Sequence>& sequences, const EngineTaa& taa,
                       const std::vector<Vec2>& velocities, const Metric& metric,
                       const ItemsProgress& progress = {});

// The rows of `aapat sequence pan --json` (Python's sequence_pan returns
// them), one per sequence: sequence, phases, mean_e2 and flicker (the means
// over the velocities), velocities: [{velocity [dx, dy], mean_e2, flicker}];
// every row after the first, against_first: {sequence, lower_at,
// velocities, mean_change, lowest_change, highest_change} (changes as
// fractions).
JsonObject::array_t pan_rows_json(const PanTable& table);

}  // namespace aapat

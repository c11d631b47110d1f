// The JSON objects of the temporal results, made once: the command line's
// --json and Python return the same keys (docs/json.md). Flicker has one
// meaning wherever its name appears: `flicker` is the mean over the period's
// transitions, `worst_flicker` the largest, `flicker_per_transition` each.
#pragma once

#include "aapat/io/json_report.h"
#include "aapat/temporal/model/temporal_metrics.h"
#include "aapat/temporal/sequence/sequence.h"

namespace aapat {

// One row of `sequence eval`: the sequence's name, frames, family and every measure.
JsonObject temporal_report_json(const Sequence& s, const TemporalReport& r);

}  // namespace aapat

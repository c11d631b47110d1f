// The JSON objects of the temporal results, made once: the command line's
// --json and Python return the same keys (docs/json.md). Flicker has one
// meaning wherever its name appears: `flicker` is the mean over the period's
// transitions, `worst_flicker` the largest, `flicker_per_transition` each.
#pragma once

#include <string_view>

#include "aapat/core/objective.h"
#include "aapat/io/json_report.h"
#include "aapat/temporal/search/pan_search.h"
#include "aapat/temporal/search/still_search.h"

namespace aapat {

// The settings and result of a sequence search, with the objective J and
// Halton's J of the same length; "result" holds the sequence file's object.
// `optimize --sequence K --taa PRESET --json` and Python's
// optimize_sequence_pan: the start's and the result's steady mean E2 per
// velocity and their means, and the result as a sequence file's object.
JsonObject pan_search_json(const PanSequenceSearch& search, const Objective& objective,
                           const PanSequenceSearchResult& r);

JsonObject sequence_search_json(const SequenceSearch& search, std::string_view model,
                                const Objective& objective, const SequenceSearchResult& r);

}  // namespace aapat

// The JSON objects of the temporal results, made once: the command line's
// --json and Python return the same keys (docs/json.md). Flicker has one
// meaning wherever its name appears: `flicker` is the mean over the period's
// transitions, `worst_flicker` the largest, `flicker_per_transition` each.
#pragma once

#include <string_view>

#include "aapat/io/json_report.h"
#include "aapat/temporal/engine/engine_taa.h"
#include "aapat/temporal/sequence/sequence.h"

namespace aapat {

// `aapat animate SCENE --taa PRESET --json` and Python's engine_taa: the
// settings (preset, its settings' text, ratio, render size, motion, phases,
// warm-up) and the measures (rmse and max_deviation over every frame's
// pixels, mean_flip, flicker, ghosting, sharpness: means over frames;
// engine_taa.h), with a row per frame, and warnings [text] when the preset's
// engine would not run the sequence as given (engine_sequence_warnings).
JsonObject engine_taa_json(std::string_view scene, const EngineRun& run, const Sequence& s,
                           const EngineTaa& taa, const EngineResult& r);

}  // namespace aapat

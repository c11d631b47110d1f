// Every registry of specs and catalog, once, in the order `aapat list`
// prints them and under the keys its --json and Python's aapat.registry()
// use: objectives, patterns, the aapat catalog, filters, point generators,
// acuity tables, scenes, textures, texture filters, API profiles, motions,
// sequence generators, the optimized sequences and the engine TAA presets.
// (In the temporal layer, the top one, because it sees them all.)
#pragma once

#include <string>
#include <vector>

#include "aapat/core/spec.h"
#include "aapat/io/json_report.h"

namespace aapat {

struct RegistrySection {
  std::string key, heading;
  std::vector<SpecInfo> infos;
};

std::vector<RegistrySection> registry_sections();
// One entry as `aapat list --json` and the explorer page read it: name, usage,
// summary, source, parameters [{key, default (null: none), meaning}].
JsonObject spec_info_json(const SpecInfo& info);
// Every section under its key, each a list of spec_info_json entries.
JsonObject registry_json();

}  // namespace aapat

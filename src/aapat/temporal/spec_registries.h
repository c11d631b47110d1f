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

namespace aapat {

struct RegistrySection {
  std::string key, heading;
  std::vector<SpecInfo> infos;
};

std::vector<RegistrySection> registry_sections();

}  // namespace aapat

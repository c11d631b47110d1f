// The aapat catalog: for every budget and API, the best pattern aapat found
// under the objective the study recommends (data/patterns/*.json, written
// by scripts/make-catalog.sh with their provenance and embedded in the
// binary): aapat-N (one pixel, N samples), aapat-shared-N (Hasselgren's
// P(4,1+,N)), aapat-2x2-N (2x2-pixel kernels), each also on an API's
// lattice (aapat-8-d3d12-tier1, aapat-shared-2-vulkan, ...).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "aapat/core/pattern.h"
#include "aapat/core/spec.h"

namespace aapat {

// Every catalog name, sorted, with a line saying what it is.
std::vector<SpecInfo> aapat_catalog();
bool in_aapat_catalog(std::string_view name);
// Throws Error naming the known names for an unknown one.
Pattern aapat_catalog_pattern(std::string_view name);

}  // namespace aapat

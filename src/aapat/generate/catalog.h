// The catalog of named patterns, each with its provenance (paper, table or
// figure). `grid-NxN` names a uniform N x N grid for any N in 1..32.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "aapat/core/pattern.h"
#include "aapat/core/spec.h"

namespace aapat {

// The fixed entries, in listing order (grid-NxN is listed once as a template;
// catalog_pattern builds any grid-NxN). Catalog patterns take no parameters.
using PatternRegistry = Registry<Pattern>;
const PatternRegistry& pattern_registry();

// Builds a catalog pattern by name; throws Error listing the known names.
Pattern catalog_pattern(std::string_view name);

// A uniform N x N grid in one pixel, equal weights.
Pattern uniform_grid_pattern(int n);

}  // namespace aapat

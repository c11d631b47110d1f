// The named reference filters, their parameters with defaults and sources, in
// one registry that `aapat list`, the docs and the Python module read; and the parser for specs
// such as `mitchell:b=1/3,c=1/3`, `gaussian:sigma=0.5,radius=1.5`, `lanczos:lobes=3`.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "aapat/core/filter.h"
#include "aapat/core/spec.h"

namespace aapat {

// Every filter with its parameters, defaults and source (core/spec.h).
using FilterRegistry = Registry<FilterShape>;
const FilterRegistry& filter_registry();

// Builds a filter from its spec; throws Error naming the unknown filter,
// parameter or the out-of-range value.
Filter make_filter(std::string_view spec);

// The default reference filter of both papers: Mitchell-Netravali (1/3, 1/3).
inline constexpr std::string_view kDefaultFilter = "mitchell";

// A finite number written as a decimal or a fraction ("1/3", "-1/4", "0.5").
double parse_number(std::string_view text, std::string_view what);

// "WIDTHxHEIGHT" or "N" (N x N), whole numbers from 1 to `max`: every
// command's --size.
std::pair<int, int> parse_size(std::string_view text, std::string_view what, int max);

}  // namespace aapat

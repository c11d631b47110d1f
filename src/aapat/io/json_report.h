// The one shape of every JSON document a command prints with --json
// (docs/json.md): an object whose first keys are "command" and "schema",
// then the settings that made the result, then the result; tables of results
// are arrays of objects under "rows". Sizes are "width" and "height",
// angles end in "_deg", a number that is not finite is null.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "aapat/core/objective.h"

namespace aapat {

using JsonObject = nlohmann::ordered_json;

inline constexpr int kJsonSchema = 1;

// {"command": command, "schema": kJsonSchema}, to be filled in.
JsonObject json_report(std::string_view command);

// The objective a result's E2 is under, the same four keys in every
// document: "objective" (its name, or its components when it has none),
// "filter", "acuity", "norm" ("inf" or p).
JsonObject objective_json(const Objective& objective);

// A paired comparison's figures (analyze/paired_comparison.h): {lower, ties,
// scenes, mean_difference, low, high, mean_ratio, sign_p}, the one shape
// every comparison reports (study --compare, sequence compare).
struct PairedComparison;
JsonObject paired_comparison_json(const PairedComparison& c);

// Indented text with a final newline; bytes that are not UTF-8 (a file name)
// are replaced rather than failing.
std::string json_text(const JsonObject& doc);

}  // namespace aapat

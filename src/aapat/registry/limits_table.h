// Every limit aapat checks, in one table built from the constants the checks
// use: `aapat limits` prints it (--json, --markdown), Python's aapat.limits()
// returns it, and docs/limits.md's table is its --markdown text
// (scripts/docs-figures.sh writes it; the docs check compares).
#pragma once

#include <string>
#include <vector>

#include "aapat/io/json_report.h"

namespace aapat {

struct Limit {
  std::string what;     // "pattern tile side"
  std::string limit;    // "1 to 128 pixels"
  std::string defined;  // "`kMaxTileSide`, `core/pattern.h`": where the constant lives
};

const std::vector<Limit>& limits_table();

// {"limits": [{"what", "limit", "defined"}, ...]}.
JsonObject limits_json();

// The table as docs/limits.md shows it (a header row, then one row per limit).
std::string limits_markdown();

}  // namespace aapat

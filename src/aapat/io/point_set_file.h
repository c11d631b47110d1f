// Point sets in the unit square as files: CSV ("x,y" per line, '#' comments)
// or a pattern file, whose tile is scaled onto [0,1)^2.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "aapat/core/geometry.h"
#include "aapat/core/pattern.h"

namespace aapat {

inline constexpr size_t kMaxPointSetSize = 1'000'000;

std::vector<Vec2> parse_point_csv(std::string_view text, std::string_view source);
std::string point_csv(const std::vector<Vec2>& points);
// Every physical sample of the tile, in [0,1)^2.
std::vector<Vec2> pattern_points(const Pattern& p);
// A .csv or .json file.
std::vector<Vec2> load_point_set(const std::string& path);

}  // namespace aapat

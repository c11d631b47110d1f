#include "aapat/io/point_set_file.h"

#include <fmt/format.h>

#include <cmath>
#include <set>
#include <sstream>

#include "aapat/core/filter_catalog.h"
#include "aapat/io/atomic_file.h"
#include "aapat/io/pattern_json.h"

namespace aapat {

std::vector<Vec2> parse_point_csv(std::string_view text, std::string_view source) {
  std::vector<Vec2> points;
  std::istringstream in{std::string(text)};
  std::string line;
  for (int no = 1; std::getline(in, line); ++no) {
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const auto comma = line.find(',');
    const std::string where = fmt::format("point file {} line {}", source, no);
    if (comma == std::string::npos || line.find(',', comma + 1) != std::string::npos)
      throw Error(fmt::format("{}: expected 'x,y' with a comma, got '{}'", where, line));
    const std::string_view lv(line);
    const Vec2 p{parse_number(lv.substr(0, comma), where + ": x"),
                 parse_number(lv.substr(comma + 1), where + ": y")};
    if (p.x < 0 || p.x > 1 || p.y < 0 || p.y > 1)
      throw Error(fmt::format("{}: ({}, {}) lies outside the unit square [0, 1] x [0, 1]", where,
                              p.x, p.y));
    if (points.size() >= kMaxPointSetSize)
      throw Error(fmt::format("{}: more than {} points, the limit", where, kMaxPointSetSize));
    points.push_back(p);
  }
  if (points.empty()) throw Error(fmt::format("point file {}: no points", source));
  return points;
}

std::string point_csv(const std::vector<Vec2>& points) {
  std::string out = "# x,y in the unit square\n";
  for (const Vec2& p : points) out += fmt::format("{},{}\n", p.x, p.y);
  return out;
}

std::vector<Vec2> pattern_points(const Pattern& p) {
  std::set<std::pair<long long, long long>> seen;
  std::vector<Vec2> out;
  for (int k = 0; k < p.set_count(); ++k) {
    const int tx = k % p.tile_w, ty = k / p.tile_w;
    for (const Vec2& s : p.sets[k]) {
      // Tile coordinates with the tile's lower-left corner at 0, wrapped.
      double x = std::fmod(tx + s.x + 0.5, p.tile_w), y = std::fmod(ty + s.y + 0.5, p.tile_h);
      if (x < 0) x += p.tile_w;
      if (y < 0) y += p.tile_h;
      if (seen.insert(sample_key(p, k, s)).second) out.push_back({x / p.tile_w, y / p.tile_h});
    }
  }
  return out;
}

std::vector<Vec2> load_point_set(const std::string& path) {
  if (path.ends_with(".csv")) return parse_point_csv(read_file(path, "point file"), path);
  return pattern_points(load_pattern_file(path));
}

}  // namespace aapat

#include "aapat/io/catalog_clash.h"

#include <fmt/format.h>

#include <filesystem>

#include "aapat/core/warning.h"

namespace aapat {

bool same_samples(const Pattern& a, const Pattern& b) {
  if (a.tile_w != b.tile_w || a.tile_h != b.tile_h || !(a.footprint == b.footprint) ||
      a.sets.size() != b.sets.size() || a.weights != b.weights)
    return false;
  for (size_t k = 0; k < a.sets.size(); ++k) {
    if (a.sets[k].size() != b.sets[k].size()) return false;
    for (size_t i = 0; i < a.sets[k].size(); ++i)
      if (a.sets[k][i].x != b.sets[k][i].x || a.sets[k][i].y != b.sets[k][i].y) return false;
  }
  return true;
}

std::string name_off_the_catalog(std::string_view name, const std::string& path,
                                 const std::function<bool(std::string_view)>& taken,
                                 std::string_view what) {
  std::string renamed = std::filesystem::path(path).stem().string();
  if (renamed.empty() || taken(renamed)) renamed = std::string(name) + "-edited";
  warn(
      fmt::format("{} '{}' is named '{}', a catalog entry whose samples differ from the "
                  "file's: read as '{}'",
                  what, path, name, renamed));
  return renamed;
}

}  // namespace aapat

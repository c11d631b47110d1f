#include "cli/point_options.h"

#include "aapat/generate/point_generators.h"
#include "cli/commands.h"
#include "cli/progress.h"

namespace aapat {

void PointOptions::add_to(CLI::App* cmd) {
  cmd->add_option("source", source,
                  "generator spec (see `aapat list`) or a point file (.csv, .dat, .bin, .psa, "
                  ".f32, .json; docs/formats.md)")
      ->required();
  add_common(cmd);
}

void PointOptions::add_common(CLI::App* cmd) {
  cmd->add_option("--n", n, "points")
      ->capture_default_str()
      ->check(CLI::Range(1, kMaxGeneratedPoints));
  add_seed_option(cmd, seed, "random seed");
  cmd->add_option("--format", format,
                  "point file format: csv, safari, utk, utk-bin, psa, pspec, json (default: by "
                  "extension)");
}

PointSets PointOptions::file_sets() const {
  return load_point_sets(source, format);
}

std::vector<Vec2> PointOptions::points(int realization) const {
  if (is_file()) return file_sets().front();
  Progress bar("points");  // dart throwing and best candidate take seconds at their limits
  return generate_points(source, n, seed + static_cast<uint64_t>(realization), bar.callback());
}

}  // namespace aapat

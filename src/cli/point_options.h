// The options of the commands that take a point set: a generator spec or a
// point file in any of the peers' formats (docs/formats.md), --n, --seed, --format.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>
#include <vector>

#include "aapat/io/point_formats.h"

namespace aapat {

struct PointOptions {
  std::string source, format;
  int n = 16;
  uint64_t seed = 1;

  // The source as a required argument, then add_common.
  void add_to(CLI::App* cmd);
  // --n, --seed and --format.
  void add_common(CLI::App* cmd);
  bool is_file() const { return is_point_file(source); }
  // Every set of a file (UTK files hold several).
  PointSets file_sets() const;
  // A file's first set, or realization r of a generator (seed + r).
  std::vector<Vec2> points(int realization = 0) const;
};

}  // namespace aapat

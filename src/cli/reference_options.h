// The options every command with a reference image shares: its sample count
// and filter, and the on-disk cache (--cache DIR, --no-cache).
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "aapat/render/reference.h"

namespace aapat {

struct ReferenceOptions {
  ReferenceSettings settings;
  std::string cache_dir;
  bool no_cache = false;
  // Cached unless --no-cache; with `progress`, a reference rendered afresh
  // shows a bar on a terminal (for a command that renders one at a time).
  ReferenceSource source(bool progress = false) const;
};

// `samples_default` is the reference's default samples per pixel.
void add_reference_options(CLI::App* cmd, ReferenceOptions& o, int samples_default);

}  // namespace aapat

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
  ReferenceSource source() const;  // cached unless --no-cache
};

// `samples_default` is the reference's default samples per pixel.
void add_reference_options(CLI::App* cmd, ReferenceOptions& o, int samples_default);

}  // namespace aapat

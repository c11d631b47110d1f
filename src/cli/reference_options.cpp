#include "cli/reference_options.h"

#include "io/reference_cache.h"

namespace aapat {

ReferenceSource ReferenceOptions::source() const {
  if (no_cache) return render_reference;
  return cached_references(cache_dir.empty() ? default_cache_dir() : cache_dir);
}

void add_reference_options(CLI::App* cmd, ReferenceOptions& o, int samples_default) {
  o.settings.samples = samples_default;
  cmd->add_option("--reference-samples", o.settings.samples,
                  "jittered samples per pixel of the reference (a square)")
      ->capture_default_str()
      ->check(CLI::Range(1, 65536));
  cmd->add_option("--reference-filter", o.settings.filter, "the reference's filter")
      ->capture_default_str();
  cmd->add_option("--cache", o.cache_dir,
                  "folder of cached references (default $AAPAT_CACHE, else "
                  "$XDG_CACHE_HOME/aapat, else ~/.cache/aapat)");
  cmd->add_flag("--no-cache", o.no_cache, "always render the reference afresh");
}

}  // namespace aapat

#include "cli/reference_options.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>

#include "aapat/core/filter_catalog.h"
#include "aapat/io/reference_cache.h"
#include "cli/app.h"
#include "cli/progress.h"

namespace aapat {

ReferenceSource ReferenceOptions::source(bool progress) const {
  ReferenceSource render = render_reference;
  if (progress)
    render = [](const Scene& scene, int width, int height, const ReferenceSettings& r,
                double offset) {
      Progress bar(fmt::format("reference {}x{}", width, height));
      return render_reference_reporting(
          scene, width, height, r, offset,
          [&](int done, int total, const std::string&) { bar.update(done, total, "bands"); });
    };
  // In memory for the run either way: the commands that compare several
  // patterns ask for the same references again.
  if (no_cache) return remembered_references(render);
  return remembered_references(cached_references(
      cache_dir.empty() ? default_cache_dir() : cache_dir,
      [](const std::string& message) { warnings() << "aapat: warning: " << message << "\n"; },
      render));
}

void add_reference_options(CLI::App* cmd, ReferenceOptions& o, int samples_default) {
  o.settings.samples = samples_default;
  cmd->add_option("--reference-samples", o.settings.samples,
                  "jittered samples per pixel of the reference (a square)")
      ->capture_default_str()
      ->check(CLI::Range(1, kMaxSamplesPerPixel))
      ->check(CLI::Validator(
          [](const std::string& text) {
            const long n = std::strtol(text.c_str(), nullptr, 10);
            const long k = std::lround(std::sqrt(static_cast<double>(n)));
            return k * k == n ? std::string()
                              : fmt::format(
                                    "{} is not a square number: the reference takes k x k "
                                    "jittered samples (1, 4, 9, ..., 1024, ...)",
                                    text);
          },
          "SQUARE"));
  cmd->add_option("--reference-filter", o.settings.filter, "the reference's filter")
      ->capture_default_str();
  cmd->add_option("--cache", o.cache_dir,
                  "folder of cached references (default $AAPAT_CACHE, else "
                  "$XDG_CACHE_HOME/aapat, else ~/.cache/aapat)");
  cmd->add_flag("--no-cache", o.no_cache, "always render the reference afresh");
}

}  // namespace aapat

#include "cli/animation_options.h"

#include <fmt/format.h>

#include <tuple>

#include "aapat/core/filter_catalog.h"
#include "cli/commands.h"

namespace aapat {

AnimationSettings AnimationOptions::settings() const {
  AnimationSettings s = a;
  std::tie(s.width, s.height) = parse_size(size, "--size", kMaxAnimationSize);
  s.reference = reference.settings;
  check_animation_work(s.width, s.height, s.frames);  // before any scene is read
  return s;
}

void add_animation_options(CLI::App* cmd, AnimationOptions& o) {
  AnimationSettings& a = o.a;
  o.size = std::to_string(a.width);
  cmd->add_option("--size", o.size,
                  fmt::format("WIDTHxHEIGHT, or N for N x N, from {} to {} pixels",
                              kMinAnimationSize, kMaxAnimationSize))
      ->capture_default_str();
  cmd->add_option("--frames", a.frames, "frames")
      ->capture_default_str()
      ->check(CLI::Range(1, kMaxAnimationFrames));
  o.reference.settings = a.reference;
  add_reference_options(cmd, o.reference, a.reference.samples);
  add_seed_option(cmd, o.reference.settings.seed, "random seed of the reference");
}

}  // namespace aapat

#include "cli/animation_options.h"

#include "cli/commands.h"

namespace aapat {

AnimationSettings AnimationOptions::settings() const {
  AnimationSettings s = a;
  s.height = s.width;
  s.reference = reference.settings;
  return s;
}

void add_animation_options(CLI::App* cmd, AnimationOptions& o) {
  AnimationSettings& a = o.a;
  cmd->add_option("--size", a.width, "width and height in pixels")
      ->capture_default_str()
      ->check(CLI::Range(8, 4096));
  cmd->add_option("--frames", a.frames, "frames")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  o.reference.settings = a.reference;
  add_reference_options(cmd, o.reference, a.reference.samples);
  add_seed_option(cmd, o.reference.settings.seed, "random seed of the reference");
}

}  // namespace aapat

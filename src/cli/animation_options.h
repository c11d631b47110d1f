// The options `aapat animate` and `aapat table2` share: the image size, the
// frames, the reference (samples, filter, cache) and its seed.
#pragma once

#include <CLI/CLI.hpp>

#include "aapat/render/animation.h"
#include "cli/reference_options.h"

namespace aapat {

inline constexpr int kMinAnimationSize = 8, kMaxAnimationSize = 4096;

struct AnimationOptions {
  AnimationSettings a;
  std::string size;  // WIDTHxHEIGHT or N (N x N), as every command's --size
  ReferenceOptions reference;
  // The settings with the reference's options applied.
  AnimationSettings settings() const;
};

void add_animation_options(CLI::App* cmd, AnimationOptions& o);

}  // namespace aapat

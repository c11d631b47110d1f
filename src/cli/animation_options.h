// The options `aapat animate` and `aapat table2` share: the image size, the
// frames, the reference (samples, filter, cache) and its seed.
#pragma once

#include <CLI/CLI.hpp>
#include <algorithm>
#include <string>

#include "aapat/render/animation.h"
#include "cli/reference_options.h"

namespace aapat {

struct AnimationOptions {
  AnimationSettings a;
  std::string size;  // WIDTHxHEIGHT or N (N x N), as every command's --size
  ReferenceOptions reference;
  // The settings with the reference's options applied.
  AnimationSettings settings() const;
};

void add_animation_options(CLI::App* cmd, AnimationOptions& o);

// The digits of a frame's number in its file name (frame-0042.png): at least
// 4, and enough for the last of `frames`, so that the names sort in frame
// order for any count.
inline int frame_digits(int frames) {
  return std::max(4, static_cast<int>(std::to_string(std::max(frames - 1, 0)).size()));
}

}  // namespace aapat

// Animated GIF of grey frames (giflib), for looking at an animation's
// aliasing in a browser: a 256-level grey palette, looping forever.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace aapat {

// The frame rate of a written animation (GIF, MP4), frames per second.
inline constexpr int kMaxFramesPerSecond = 100;

struct GreyFrames {
  int width = 0, height = 0;
  int delay_cs = 8;                          // per frame, in hundredths of a second
  std::vector<std::vector<uint8_t>> frames;  // rows top-down
};

std::string gif_bytes(const GreyFrames& frames);
GreyFrames frames_from_gif(const std::string& bytes);  // for the round-trip test
void write_gif(const std::string& path, const GreyFrames& frames);

}  // namespace aapat

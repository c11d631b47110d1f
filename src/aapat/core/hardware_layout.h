// What a GPU is told: a pattern laid out for a programmable-sample-position
// API. Every API addresses 16 x 16 positions per pixel, [0, 15] from the
// pixel's upper-left corner with y down (Direct3D 12 writes them as -8..7
// from the centre; OpenGL counts from the lower-left corner, y up), in a
// small grid of pixels that repeats over the screen. A sample this project
// shares on a border at +1/2 lies at 16/16, outside what its pixel can
// address: the API's neighbouring pixel owns it at 0, and the resolve of
// each pixel reads it there. Each grid pixel owns the samples at [0, 15]^2
// of its square, so every physical sample is taken exactly once.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "aapat/core/pattern.h"
#include "aapat/core/spec.h"

namespace aapat {

enum class Api { kD3D12, kVulkan, kMetal, kOpenGL };

struct ApiProfile {
  std::string name, summary;
  Api api;
  int max_grid = 1;          // the largest pixel grid (square) the profile can program
  int max_samples = 16;      // samples per pixel with the largest grid
  bool y_down = true;        // rows counted from the top (all but OpenGL)
  bool grid_choice = false;  // the grid may be any size up to max_grid (Vulkan, OpenGL)
};

const std::vector<ApiProfile>& api_profiles();
// The profiles by name, for specs and listings (core/spec.h).
using ProfileRegistry = Registry<const ApiProfile*>;
const ProfileRegistry& profile_registry();
const ApiProfile& api_profile(std::string_view name);  // throws Error naming the known ones

struct LatticePoint {
  int x = 0, y = 0;  // 0..15 from the pixel's origin corner, in the API's y direction
  friend bool operator==(const LatticePoint&, const LatticePoint&) = default;
};

// One sample a resolve reads: in the pixel (dx, dy) away (API directions),
// its sample index there, and the weight.
struct Tap {
  int dx = 0, dy = 0, sample = 0;
  double weight = 0;
};

struct HardwareLayout {
  std::string profile;
  int grid_w = 1, grid_h = 1;  // grid pixel (gx, gy) is index gy * grid_w + gx, gy in API rows
  int sample_count = 1;        // the MSAA count to create: a power of two >= every pixel's own
  std::vector<std::vector<LatticePoint>> positions;  // per grid pixel: its own samples
  std::vector<std::vector<Tap>> taps;                // per grid pixel: its kernel
  Footprint footprint;
  std::string name;
  // Samples the resolve reads per output pixel, on average.
  double reads() const;
  // What MSAA sample i of grid pixel g is programmed to: its own sample, or
  // for a pixel that owns fewer than sample_count, a copy of its first (the
  // centre if it owns none), which the resolve never reads.
  LatticePoint slot(int g, int i) const;
};

// The layout of a pattern on the 1/16 lattice (snap it first) for a profile.
// grid 0: the pattern's tile (1x1 for the fixed-grid profiles when it fits).
// Throws Error when the pattern does not fit: off the lattice, a tile the
// grid cannot hold, more samples per pixel than the profile allows.
HardwareLayout hardware_layout(const Pattern& p, const ApiProfile& profile, int grid_w = 0,
                               int grid_h = 0);

// The pattern a layout describes (1 and 1+ footprints): the inverse of
// hardware_layout, exact on the lattice. A grid of equal pixels gives a 1x1 tile.
Pattern pattern_from_layout(const HardwareLayout& layout);

}  // namespace aapat

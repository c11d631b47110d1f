#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "aapat/core/geometry.h"

namespace aapat {

// The points of every pixel of a rectangle under one per-pixel generator,
// count and seed: pixel_points(spec, samples, seed, a, b) for each pixel,
// drawn once. A reference draws the same points under every scene and motion
// that shares its seed (the frames of a pan at every velocity, the scenes of
// a study), and drawing them (a generator seeded per pixel) was a quarter to
// a third of such a render.
class PixelPointTable {
 public:
  // Pixels [x0, x1) x [y0, y1).
  PixelPointTable(std::string_view spec, int samples, uint64_t seed, int x0, int y0, int x1,
                  int y1);

  bool covers(int a, int b) const { return a >= x0_ && a < x1_ && b >= y0_ && b < y1_; }
  // Pixel (a, b)'s points in its local frame [-0.5, 0.5)^2; covers(a, b) must hold.
  std::span<const Vec2> points(int a, int b) const {
    const size_t pixel = static_cast<size_t>(b - y0_) * static_cast<size_t>(x1_ - x0_) +
                         static_cast<size_t>(a - x0_);
    return {points_.data() + offsets_[pixel], offsets_[pixel + 1] - offsets_[pixel]};
  }
  size_t bytes() const { return points_.size() * sizeof(Vec2) + offsets_.size() * sizeof(size_t); }

 private:
  int x0_, y0_, x1_, y1_;
  std::vector<Vec2> points_;
  std::vector<size_t> offsets_;  // pixel k's points are [offsets_[k], offsets_[k + 1])
};

// The largest table shared_pixel_points keeps (a 64-sample reference of about
// 128 x 128 pixels), and the most it keeps in all, the least recently used
// dropped first.
inline constexpr size_t kMaxSharedPixelTableBytes = size_t{16} << 20;
inline constexpr size_t kMaxSharedPixelTablesBytes = size_t{64} << 20;

// The table for these arguments, drawn on first use and kept for the next
// render that asks for it (thread-safe); null when it would be larger than
// kMaxSharedPixelTableBytes (the caller draws each pixel's points itself).
std::shared_ptr<const PixelPointTable> shared_pixel_points(std::string_view spec, int samples,
                                                           uint64_t seed, int x0, int y0, int x1,
                                                           int y1);

}  // namespace aapat

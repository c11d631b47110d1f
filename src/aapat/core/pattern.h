// The P(s, r, n) pattern model of Laine & Aila Sec. 3.
//
// A pattern is a repeating tile of s = tile_w x tile_h pixel sample sets and
// one reconstruction kernel per tile pixel (s kernels). A kernel reads the sets
// of its footprint: 1 pixel, or a 2x2 / 4x4 block that reconstructs at the
// block's centre (the output grid shifted by half a pixel, Laine-Aila Fig. 3).
// A '+' footprint shares samples that lie exactly on pixel borders: each set
// lists every sample on its closed square, and the neighbours list the same
// physical sample on their side. n, the samples taken per pixel, is computed
// from the geometry: distinct physical samples per tile / pixels per tile.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "aapat/core/geometry.h"

namespace aapat {

struct Footprint {
  int size = 1;       // 1, 2 or 4 pixels on a side
  bool plus = false;  // reads the samples on the footprint's border

  int pixels() const { return size * size; }
  std::string text() const;  // "1", "1+", "2x2", "2x2+", "4x4", "4x4+"
  friend bool operator==(const Footprint&, const Footprint&) = default;
};

// Accepts "1", "1+", "2x2", "2x2+", "4x4", "4x4+" and the r of P(s,r,n): "4", "16", "4+".
Footprint parse_footprint(std::string_view text);

struct Pattern {
  std::string name;
  std::string description;
  int tile_w = 1;
  int tile_h = 1;
  Footprint footprint;
  // sets[ty * tile_w + tx]: the samples of tile pixel (tx, ty), y up, in that
  // pixel's local coordinates.
  std::vector<std::vector<Vec2>> sets;
  // weights[k]: kernel k's weights in kernel_samples(*this, k) order.
  std::vector<std::vector<double>> weights;
  // Where the pattern comes from: catalog source, generator and seed, optimizer run.
  std::vector<std::pair<std::string, std::string>> provenance;

  int set_count() const { return tile_w * tile_h; }
};

// One sample as kernel k reads it: position relative to the kernel's output
// point, and which set and sample it is.
struct KernelSample {
  Vec2 pos;
  int set = 0;
  int index = 0;
};

// The samples kernel k reads, in a fixed order: the footprint's pixels bottom
// to top, left to right; within a pixel its set order; a shared border sample
// once, where first met. For 1 and 1+ footprints this is simply set k.
std::vector<KernelSample> kernel_samples(const Pattern& p, int kernel);

// A kernel ready for the metric: positions relative to the output point and
// weights normalized to sum to 1 (structure of arrays for the hot loop).
struct Kernel {
  std::vector<double> x, y, w;
  int size() const { return static_cast<int>(w.size()); }
};
Kernel make_kernel(const Pattern& p, int kernel);
Kernel make_kernel(const std::vector<Vec2>& positions, const std::vector<double>& weights);

// The set of any pixel (x, y) of the plane: the tile repeats.
int set_index(const Pattern& p, int x, int y);

// The identity of a physical sample: sample s of set `set`, as its position
// in the tile modulo the tile (rounded to 1e-7), so every pixel that lists a
// shared border sample gives it the same key.
std::pair<long long, long long> sample_key(const Pattern& p, int set, Vec2 s);

// n: distinct physical samples per tile divided by pixels per tile.
double samples_per_pixel(const Pattern& p);
// "P(4,1+,1.25)".
std::string family(const Pattern& p);
std::string format_cost(double n);

// Whether a sample lies on its pixel's border (an edge or a corner).
bool on_border(Vec2 p);

// Where a sample sits in its pixel: "inside", an edge ("left", "right",
// "bottom", "top") or a corner ("bottom-left", ...). Costs 1, 1/2 and 1/4
// in a sharing (+) footprint.
std::string site_name(Vec2 p);

// Limits every pattern meets (docs/limits.md).
inline constexpr int kMaxTileSide = 128;
inline constexpr size_t kMaxSamplesPerSet = 1024;
inline constexpr size_t kMaxPatternSamples = 65536;  // over all sets
// A weight's magnitude: negative lobes are fine, weights that cancel in the
// thousands only lose precision (and overflow the optimizer's steps).
inline constexpr double kMaxWeightMagnitude = 1000;

// Throws Error whose message names the field (e.g. "sets[0][2]") and the rule.
void validate(const Pattern& p);

// Builders for the common shapes. Weights are given per sample of the base set.
Pattern single_pixel_pattern(std::string name, std::vector<Vec2> samples,
                             std::vector<double> weights, Footprint footprint = {1, false});
// The mirrored P(4, 1+, n) tile of Hasselgren et al.: the base set in pixel
// (0,0), mirrored in x for (1,0), in y for (0,1), in both for (1,1).
Pattern mirrored_tile_pattern(std::string name, std::vector<Vec2> base,
                              std::vector<double> weights);

}  // namespace aapat

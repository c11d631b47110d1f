// The dense reference a rendering is measured against: N jittered samples per
// pixel (a square count) reconstructed with a reference filter, by default
// 1024 samples and the 4x4-pixel Mitchell-Netravali filter (Hasselgren Sec. 6.1).
#pragma once

#include <functional>
#include <string>

#include "aapat/render/renderer.h"
#include "aapat/work/work_items.h"

namespace aapat {

struct ReferenceSettings {
  int samples = 1024;
  std::string filter = "mitchell";
  uint64_t seed = 1000004;
};

// "1024 jittered samples per pixel, mitchell:b=1/3,c=1/3": the reference as
// the JSON documents name it.
std::string describe_reference(const ReferenceSettings& settings);

// The reference seed rules, written once. A rendering with seed S is
// measured against a reference seeded S + 1000003 (independent of the
// rendering's own jitter); frame f of an animation against one seeded
// reference seed + 7919 (f + 1), so that frames' references are independent.
// Frame -1 is a still image: the reference seed itself.
inline constexpr int kStillFrame = -1;
uint64_t reference_seed(uint64_t render_seed);
uint64_t frame_reference_seed(uint64_t reference_seed, int frame);

// Reconstructed at (i + offset, j + offset), to match a rendering whose
// footprint shifts it (Image::offset).
Image render_reference(const Scene& scene, int width, int height, const ReferenceSettings& r,
                       double offset);
// The same, telling `progress` of each band of rows as it finishes.
Image render_reference_reporting(const Scene& scene, int width, int height,
                                 const ReferenceSettings& r, double offset,
                                 const ItemsProgress& progress);

// Where references come from: render_reference, or a cache in front of it.
using ReferenceSource =
    std::function<Image(const Scene&, int width, int height, const ReferenceSettings&, double)>;

}  // namespace aapat

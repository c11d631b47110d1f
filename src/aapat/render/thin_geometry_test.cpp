#include "aapat/render/thin_geometry.h"

#include <gtest/gtest.h>

#include <cmath>

namespace aapat {
namespace {

// The same seed gives the same scene, another seed another; every feature
// contrasts with the background by at least 0.35; the spec builds it.
TEST(ThinGeometry, SeededContrastingAndThin) {
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    const Scene a = thin_geometry(12, seed, 128, 96);
    EXPECT_EQ(canonical_text(a), canonical_text(thin_geometry(12, seed, 128, 96)));
    EXPECT_NE(canonical_text(a), canonical_text(thin_geometry(12, seed + 100, 128, 96)));
    const auto& s = std::get<ShapesScene>(a.shape);
    ASSERT_GE(s.shapes.size(), 12u);
    for (const Shape& shape : s.shapes) {
      EXPECT_GE(std::abs(shape.grey - s.background), 0.35 - 1e-3);
      if (shape.polygon.empty()) {
        EXPECT_LE(shape.radius, 0.8);          // a dot
      } else if (shape.polygon.size() == 4) {  // a bar: its width is that of a wire or fence
        const double width = std::hypot(shape.polygon[0].x - shape.polygon[3].x,
                                        shape.polygon[0].y - shape.polygon[3].y);
        EXPECT_GE(width, 0.08 - 1e-9);
        EXPECT_LE(width, 1.5 + 1e-9);
      }
    }
  }
  EXPECT_EQ(canonical_text(make_scene("thin-geometry:count=5,seed=9", 64, 64)),
            canonical_text(thin_geometry(5, 9, 64, 64)));
  EXPECT_THROW(make_scene("thin-geometry:count=0", 64, 64), Error);
}

}  // namespace
}  // namespace aapat

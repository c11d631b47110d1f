#include "aapat/core/lattice.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include "aapat/generate/catalog.h"

namespace aapat {
namespace {

TEST(Lattice, BordersStayAndLatticePatternsDoNotMove) {
  EXPECT_EQ(snap_coordinate(0.5, 16), 0.5);
  EXPECT_EQ(snap_coordinate(-0.5, 16), -0.5);
  EXPECT_EQ(snap_coordinate(0.49, 16), 7.0 / 16);  // an interior sample never reaches a border
  // Without sharing: D3D12's -8..7 with y down, so x may be -1/2 and y (up) +1/2.
  EXPECT_EQ(snap_sample({0.5, -0.5}, 16, false), (Vec2{7.0 / 16, -7.0 / 16}));
  EXPECT_EQ(snap_sample({-0.5, 0.5}, 16, false), (Vec2{-0.5, 0.5}));
  for (const char* name : {"msaa-2", "msaa-4", "msaa-8", "msaa-16", "rgss", "box2x2"}) {
    const Pattern p = catalog_pattern(name);
    EXPECT_EQ(off_lattice_sample(p, 16), "") << name;
    EXPECT_EQ(snap_to_lattice(p, 16).sets, p.sets) << name;
  }
  EXPECT_EQ(off_lattice_sample(catalog_pattern("flipquad"), 16),
            "sets[0][0] = (-0.5, 0.166667) is not on the 1/16 lattice");
  EXPECT_THROW(snap_to_lattice(catalog_pattern("rgss"), 3), Error);
}

// Snapping keeps every catalog pattern's family and cost n: borders stay shared.
TEST(Lattice, SnappingKeepsFamilyAndCost) {
  for (const auto& [e, build] : pattern_registry().entries()) {
    if (e.name == "grid-NxN") continue;
    const Pattern p = catalog_pattern(e.name);
    Pattern q;
    try {
      q = snap_to_lattice(p, 16);
    } catch (const Error& err) {  // only dense grids may collide on the lattice
      EXPECT_NE(std::string(err.what()).find("same position"), std::string::npos) << e.name;
      continue;
    }
    EXPECT_EQ(family(q), family(p)) << e.name;
    EXPECT_EQ(samples_per_pixel(q), samples_per_pixel(p)) << e.name;
    EXPECT_EQ(off_lattice_sample(q, 16), "") << e.name;
  }
}

}  // namespace
}  // namespace aapat

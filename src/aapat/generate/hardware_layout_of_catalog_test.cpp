#include "aapat/core/hardware_layout.h"

#include <gtest/gtest.h>

#include "aapat/core/lattice.h"
#include "aapat/generate/catalog.h"
#include "testing/error_message.h"

namespace aapat {
namespace {

using testing::error_message;

TEST(HardwareLayout, FlipquadOnATier2Grid) {
  const Pattern fq = snap_to_lattice(catalog_pattern("flipquad"), 16);
  const HardwareLayout L = hardware_layout(fq, api_profile("d3d12-tier2"));
  EXPECT_EQ(L.grid_w, 2);
  EXPECT_EQ(L.grid_h, 2);
  EXPECT_EQ(L.sample_count, 2);
  EXPECT_EQ(L.reads(), 4);
  // Screen pixel (0, 0) is the tile's top-left pixel: set 2, whose left
  // sample (-1/2, -3/16) is D3D12's (-8, +3) and top sample (-3/16, +1/2) is (-3, -8).
  ASSERT_EQ(L.positions[0].size(), 2u);
  EXPECT_EQ(L.positions[0][0], (LatticePoint{0, 11}));
  EXPECT_EQ(L.positions[0][1], (LatticePoint{5, 0}));
  // Its right sample is the right neighbour's left one; its bottom one the lower neighbour's top.
  const auto& taps = L.taps[0];
  ASSERT_EQ(taps.size(), 4u);
  EXPECT_EQ(taps[1].dx, 1);
  EXPECT_EQ(taps[1].dy, 0);
  EXPECT_EQ(taps[3].dx, 0);
  EXPECT_EQ(taps[3].dy, 1);
  EXPECT_EQ(pattern_from_layout(L).sets, fq.sets);
}

// Every sample is owned by exactly one grid pixel, inside [0, 15]^2, and the
// layout reads back as the pattern (footprints 1 and 1+).
TEST(HardwareLayout, EveryPhysicalSampleOnceAndTheRoundTrip) {
  int checked = 0;
  for (const auto& [e, build] : pattern_registry().entries()) {
    if (e.name == "grid-NxN") continue;
    Pattern p;
    try {
      p = snap_to_lattice(catalog_pattern(e.name), 16);
    } catch (const Error&) {
      continue;  // dense grids collide on the lattice
    }
    for (const ApiProfile& profile : api_profiles()) {
      HardwareLayout L;
      try {
        L = hardware_layout(p, profile);
      } catch (const Error&) {
        continue;  // the tile or the count does not fit this profile
      }
      size_t owned = 0;
      for (const auto& px : L.positions) {
        owned += px.size();
        for (const LatticePoint& q : px) {
          EXPECT_GE(q.x, 0);
          EXPECT_LE(q.x, 15);
          EXPECT_GE(q.y, 0);
          EXPECT_LE(q.y, 15);
        }
        EXPECT_LE(static_cast<int>(px.size()), L.sample_count);
      }
      EXPECT_NEAR(static_cast<double>(owned), samples_per_pixel(p) * L.grid_w * L.grid_h, 1e-9)
          << e.name << " " << profile.name;
      if (p.footprint.size == 1 && L.grid_w == p.tile_w && L.grid_h == p.tile_h) {
        const Pattern back = pattern_from_layout(L);
        EXPECT_EQ(back.sets, p.sets) << e.name << " " << profile.name;
        EXPECT_EQ(back.weights, p.weights) << e.name << " " << profile.name;
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 40);
}

TEST(HardwareLayout, PatternsThatDoNotFitAreNamed) {
  const Pattern fq = snap_to_lattice(catalog_pattern("flipquad"), 16);
  EXPECT_EQ(error_message([&] { hardware_layout(fq, api_profile("d3d12-tier1")); }),
            "flipquad: a 2x2 tile does not fit d3d12-tier1's pixel grid (1x1 asked, at most 1x1, "
            "a multiple of the tile)");
  EXPECT_NE(error_message([&] {
              hardware_layout(catalog_pattern("flipquad"), api_profile("vulkan"));
            }).find("snap it first"),
            std::string::npos);
  EXPECT_EQ(
      error_message([&] { hardware_layout(catalog_pattern("msaa-16"), api_profile("metal")); }),
      "msaa-16: 16 samples per pixel (as 16x MSAA) is more than metal allows with a 1x1 grid "
      "(8)");
  EXPECT_NE(error_message([] { api_profile("d3d9"); }).find("known API profiles are d3d12-tier1"),
            std::string::npos);
  // Vulkan takes a larger grid than the tile: the tile repeats in it.
  const HardwareLayout L = hardware_layout(catalog_pattern("msaa-4"), api_profile("vulkan"), 2, 2);
  EXPECT_EQ(L.positions.size(), 4u);
  EXPECT_EQ(pattern_from_layout(L).tile_w, 1);  // equal pixels read back as one
}

}  // namespace
}  // namespace aapat

#include "aapat/generate/enumerate.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <set>

#include "aapat/core/geometry.h"

namespace aapat {
namespace {

size_t count(const std::vector<double>& costs, const EnumerationRules& rules = {}) {
  size_t total = 0;
  for (double n : costs) total += enumerate_placements(n, rules).size();
  return total;
}

// Hasselgren et al. Sec. 5.2: "only 94 in total". Any number of samples per
// edge, n from 1 to 2 in quarters, rotations and reflections removed.
TEST(Enumerate, NinetyFourConfigurationsForOneToTwoSamples) {
  EXPECT_EQ(enumerate_placements(1).size(), 9u);
  EXPECT_EQ(enumerate_placements(1.25).size(), 9u);
  EXPECT_EQ(enumerate_placements(1.5).size(), 19u);
  EXPECT_EQ(enumerate_placements(1.75).size(), 19u);
  EXPECT_EQ(enumerate_placements(2).size(), 38u);
  EXPECT_EQ(count({1, 1.25, 1.5, 1.75, 2}), 94u);
  EXPECT_EQ(count({1.25, 1.5, 1.75, 2}), 85u);  // the four costs the paper studies
}

TEST(Enumerate, OtherRuleSets) {
  EXPECT_EQ(count({1.25, 1.5, 1.75, 2}, {1, false}), 43u);  // at most one sample per edge
  EXPECT_EQ(count({1.25, 1.5, 1.75, 2}, {2, false}), 75u);
  EXPECT_EQ(count({1.25, 1.5, 1.75, 2}, {8, true}), 79u);  // the one-border-line cull
  EXPECT_EQ(enumerate_placements(0.25).size(), 1u);        // one corner
}

// Every configuration costs n, is the least of its 8 images, and no two
// configurations are images of each other; together their orbits are every
// raw placement of that cost.
TEST(Enumerate, ConfigurationsAreDistinctClassesCoveringEverything) {
  for (double n : {1.0, 1.25, 1.5, 1.75, 2.0}) {
    const auto configs = enumerate_placements(n);
    std::set<PlacementConfig> orbits;
    for (const auto& c : configs) {
      EXPECT_DOUBLE_EQ(c.cost(), n);
      for (const auto& image : symmetric_images(c)) {
        EXPECT_LE(c, image);
        orbits.insert(image);
      }
    }
    size_t raw = 0;  // every placement of cost n, counted directly
    for (int mask = 0; mask < 16; ++mask)
      for (int b = 0; b <= 4; ++b)
        for (int r = 0; r <= 4; ++r)
          for (int t = 0; t <= 4; ++t)
            for (int l = 0; l <= 4; ++l) {
              const double rest =
                  n - 0.25 * std::popcount(static_cast<unsigned>(mask)) - 0.5 * (b + r + t + l);
              if (rest >= 0 && rest == std::floor(rest)) ++raw;
            }
    EXPECT_EQ(orbits.size(), raw) << n;
  }
}

TEST(Enumerate, RejectsCostsOffTheQuarterGrid) {
  EXPECT_THROW(enumerate_placements(1.3), Error);
  EXPECT_THROW(enumerate_placements(0), Error);
}

}  // namespace
}  // namespace aapat

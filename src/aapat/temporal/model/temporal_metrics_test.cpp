#include "aapat/temporal/model/temporal_metrics.h"

#include <gtest/gtest.h>

#include "aapat/generate/catalog.h"
#include "aapat/temporal/sequence/sequence_generators.h"

namespace aapat {
namespace {

Vec2 first_jitter(const Sequence& s, int f) {
  return s.frames[static_cast<size_t>(f)].sets[0][0];
}

// Orderings keep the pattern's samples, one per frame; the rooks order's
// prefixes of 1, 2 and 4 samples of a 4x4 grid are N-rooks.
TEST(PrefixMeasures, OrderingsMakeEveryPrefixStratified) {
  const Pattern grid = catalog_pattern("grid-4x4");
  for (const char* spec : {"rooks-order", "blue-noise-order"}) {
    const Sequence s = make_sequence(spec, grid);
    ASSERT_EQ(s.period(), 16) << spec;
    std::set<std::pair<double, double>> got, want;
    for (int f = 0; f < 16; ++f) got.insert({first_jitter(s, f).x, first_jitter(s, f).y});
    for (const Vec2 v : grid.sets[0]) want.insert({v.x, v.y});
    EXPECT_EQ(got, want) << spec;
  }
  const Sequence rooks = make_sequence("rooks-order", grid);
  std::vector<Vec2> points;
  for (int f = 0; f < 16; ++f)
    points.push_back({first_jitter(rooks, f).x + 0.5, first_jitter(rooks, f).y + 0.5});
  const std::vector<PrefixMeasure> m = prefix_measures(points);
  for (int prefix : {1, 2, 4}) {
    EXPECT_EQ(m[static_cast<size_t>(prefix - 1)].most_in_x, 1) << prefix;
    EXPECT_EQ(m[static_cast<size_t>(prefix - 1)].most_in_y, 1) << prefix;
  }
  const Sequence split = make_sequence("split:frames=4", grid);
  EXPECT_EQ(split.frames[0].sets[0].size(), 4u);
}

}  // namespace
}  // namespace aapat

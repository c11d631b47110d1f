#include "aapat/core/pattern_edit.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include "aapat/core/metric.h"
#include "aapat/core/objective.h"
#include "testing/error_message.h"

namespace aapat {
namespace {

using testing::error_message;

// The catalog's patterns, built here from their published positions (the
// core's tests do not reach the generate layer's catalog).
Pattern msaa(int n) {
  // data/msaa-standard-positions.csv in sixteenths, y down; here y up.
  static const std::vector<std::pair<int, int>> k4{{-2, -6}, {6, -2}, {-6, 2}, {2, 6}},
      k8{{1, -3}, {-1, 3}, {5, 1}, {-3, -5}, {-5, 5}, {-7, -1}, {3, 7}, {7, -7}};
  std::vector<Vec2> s;
  for (const auto& [x, y] : n == 4 ? k4 : k8) s.push_back({x / 16.0, -y / 16.0});
  return single_pixel_pattern(fmt::format("msaa-{}", n), s,
                              std::vector<double>(s.size(), 1.0 / static_cast<double>(s.size())));
}
Pattern flipquad() {  // Akenine-Moller & Strom 2003
  return mirrored_tile_pattern("flipquad",
                               {{-0.5, 1.0 / 6}, {0.5, -1.0 / 6}, {-1.0 / 6, -0.5}, {1.0 / 6, 0.5}},
                               {0.25, 0.25, 0.25, 0.25});
}

// Standard MSAA 4x (data/msaa-standard-positions.csv, y up):
// (-2/16, 6/16), (6/16, 2/16), (-6/16, -2/16), (2/16, -6/16).
TEST(PatternEdit, AMoveInsideKeepsTheWeightsAndTheFamily) {
  const Pattern q = move_sample(msaa(4), 0, 1, {0.1, 0.2});
  EXPECT_EQ(q.sets[0][1], (Vec2{0.1, 0.2}));
  EXPECT_EQ(q.sets[0][0], (Vec2{-0.125, 0.375}));
  EXPECT_EQ(q.weights[0], (std::vector<double>{0.25, 0.25, 0.25, 0.25}));
  EXPECT_EQ(family(q), "P(1,1,4)");
  EXPECT_EQ(q.name, "msaa-4-edited");
  EXPECT_EQ(q.provenance,
            (std::vector<std::pair<std::string, std::string>>{{"edited-from", "msaa-4"}}));
  EXPECT_EQ(move_sample(q, 0, 1, {0.0, 0.0}).name, "msaa-4-edited");  // named once
}

// Dropped within kBorderSnap of the left edge: on it, and shared with the
// neighbour (in a 1x1 tile the pixel itself, across its right edge). The
// kernel now reads 5 samples, equally weighted; a pixel still pays for 4.
TEST(PatternEdit, ASampleDroppedOnABorderIsShared) {
  const Pattern q = move_sample(msaa(4), 0, 2, {-0.49, -0.125});
  ASSERT_EQ(q.sets[0].size(), 5u);
  EXPECT_EQ(q.sets[0][2], (Vec2{-0.5, -0.125}));
  EXPECT_EQ(q.sets[0][4], (Vec2{0.5, -0.125}));
  EXPECT_EQ(q.footprint.text(), "1+");
  EXPECT_EQ(family(q), "P(1,1+,4)");
  EXPECT_EQ(q.weights[0], std::vector<double>(5, 0.2));
  // The same E2 as the pattern written out by hand.
  const Pattern by_hand = single_pixel_pattern(
      "by-hand", {{-0.125, 0.375}, {0.375, 0.125}, {-0.5, -0.125}, {0.125, -0.375}, {0.5, -0.125}},
      std::vector<double>(5, 0.2), {1, true});
  const Metric metric = named_objective("recommended").metric();
  EXPECT_EQ(metric.evaluate(q).e2, metric.evaluate(by_hand).e2);

  // Dragged back inside, it stops being shared: P(1,1,4) again.
  const Pattern back = move_sample(q, 0, 2, {-0.375, -0.125});
  EXPECT_EQ(back.sets[0].size(), 4u);
  EXPECT_EQ(back.footprint.text(), "1");
  EXPECT_EQ(family(back), "P(1,1,4)");
  EXPECT_EQ(metric.evaluate(back).e2, metric.evaluate(msaa(4)).e2);
}

// A plain pattern may keep a sample on its closed pixel's border (MSAA 16x's
// x = -8/16); when another is dropped on a border the footprint gains its
// '+', and that sample is shared as well.
TEST(PatternEdit, GainingThePlusSharesTheSamplesAlreadyOnBorders) {
  const Pattern p = single_pixel_pattern(
      "closed", {{-0.5, 0.25}, {0.1, 0.1}, {0.2, -0.3}, {-0.2, 0}}, {0.25, 0.25, 0.25, 0.25});
  const Pattern q = move_sample(p, 0, 1, {0.1, -0.495});
  EXPECT_EQ(q.footprint.text(), "1+");
  EXPECT_EQ(q.sets[0].size(), 6u);  // both border samples listed on both sides
  EXPECT_EQ(family(q), "P(1,1+,4)");
}

// FLIPQUAD's samples sit on its pixels' edges, shared by the mirrored 2x2
// tile's neighbours: sliding one along its edge moves every copy, keeps the
// cost (P(4,1+,2)) and, with the same reads, the weights.
TEST(PatternEdit, ASharedSampleSlidesWithItsCopies) {
  const Pattern p = flipquad();
  int index = -1;
  for (int i = 0; i < static_cast<int>(p.sets[0].size()); ++i)
    if (p.sets[0][i].x == -0.5) index = i;
  ASSERT_GE(index, 0);
  const Pattern q = move_sample(p, 0, index, {-0.5, 0.3125});
  EXPECT_EQ(family(q), "P(4,1+,2)");
  EXPECT_EQ(q.weights, p.weights);
  // Set 1 (tile pixel (1, 0)) lies across the left edge of pixel 0 in a 2-wide tile.
  bool copy = false;
  for (const Vec2& s : q.sets[1]) copy = copy || s == Vec2{0.5, 0.3125};
  EXPECT_TRUE(copy);
  EXPECT_EQ(samples_per_pixel(q), 2.0);
}

TEST(PatternEdit, TheLatticeRoundsToSixteenths) {
  const Pattern q = move_sample(msaa(4), 0, 0, {0.13, -0.2}, 16);
  EXPECT_EQ(q.sets[0][0], (Vec2{2.0 / 16, -3.0 / 16}));
  // -8/16 is the border: shared.
  EXPECT_EQ(move_sample(msaa(4), 0, 0, {-0.49, 0.1}, 16).footprint.text(), "1+");
}

TEST(PatternEdit, BadEditsAreRefusedWithTheirReason) {
  const Pattern p = msaa(4);
  EXPECT_EQ(error_message([&] {
              move_sample(p, 1, 0, {0, 0});
            }),
            "set 1 does not exist: the pattern has 1 sets (0 to 0)");
  EXPECT_EQ(error_message([&] {
              move_sample(p, 0, 4, {0, 0});
            }),
            "sample 4 of set 0 does not exist: it has 4 samples");
  EXPECT_EQ(error_message([&] {
              move_sample(p, 0, 0, {NAN, 0});
            }),
            "position (nan, 0) is not a pair of finite numbers");
  EXPECT_NE(error_message([&] {
              move_sample(p, 0, 0, {0.375, 0.125});
            }).find("same position"),
            std::string::npos);
  EXPECT_EQ(error_message([&] { set_weight(p, 0, 0, NAN); }),
            "weight 0 of kernel 0: nan is not a finite number");
  EXPECT_EQ(error_message([&] { set_weight(p, 0, 9, 0.5); }),
            "weight 9 of kernel 0 does not exist: it has 4 weights");
  EXPECT_EQ(error_message([&] {
              set_weight(single_pixel_pattern("one", {{0, 0}}, {1}), 0, 0, 0.5);
            }),
            "kernel 0 reads one sample: its weight is 1");
}

// The other weights keep their proportions and the kernel still sums to 1.
TEST(PatternEdit, AWeightSetScalesTheOthers) {
  const Pattern q = set_weight(msaa(4), 0, 0, 0.4);
  EXPECT_EQ(q.weights[0][0], 0.4);
  for (int i = 1; i < 4; ++i) EXPECT_NEAR(q.weights[0][i], 0.2, 1e-15);
  const Pattern r = set_weight(set_weight(q, 0, 1, 0.0), 0, 0, 1.0);
  EXPECT_EQ(r.weights[0], (std::vector<double>{1, 0, 0, 0}));
  const Pattern s = set_weight(r, 0, 0, 0.25);  // the others were all 0: shared equally
  for (int i = 1; i < 4; ++i) EXPECT_NEAR(s.weights[0][i], 0.25, 1e-15);
}

// Any move of any sample of MSAA 8x to a point strictly inside its pixel puts
// that sample there and leaves every other sample and weight as it was.
RC_GTEST_PROP(PatternEdit, AnInteriorMoveChangesOnlyThatSample, ()) {
  const Pattern p = msaa(8);
  const int index = *rc::gen::inRange(0, 8);
  const auto coord = [] {
    return (*rc::gen::inRange(-450, 451)) / 1000.0;  // clear of kBorderSnap
  };
  const Vec2 to{coord(), coord()};
  bool clash = false;
  for (int i = 0; i < 8; ++i) clash = clash || (i != index && same_point(p.sets[0][i], to));
  RC_PRE(!clash);
  const Pattern q = move_sample(p, 0, index, to);
  RC_ASSERT(q.sets[0].size() == 8u);
  for (int i = 0; i < 8; ++i) RC_ASSERT(q.sets[0][i] == (i == index ? to : p.sets[0][i]));
  RC_ASSERT(q.weights == p.weights);
  RC_ASSERT(family(q) == "P(1,1,8)");
}

}  // namespace
}  // namespace aapat

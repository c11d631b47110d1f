#include "aapat/temporal/search/rendered_search.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "aapat/temporal/sequence/sequence_generators.h"
#include "testing/centre_reference.h"
#include "testing/error_message.h"

namespace aapat {
namespace {

RenderedSearch tiny() {
  RenderedSearch s;
  s.comparison.taa = make_engine_taa("bevy", 1, {});
  s.comparison.scenes = random_scene_specs(2, 4, 21);
  s.comparison.motion = "random-pan";
  s.comparison.width = s.comparison.height = 12;
  s.comparison.frames = 3;
  s.comparison.warmup = 2;
  s.start = make_sequence("halton:frames=4");
  s.baseline = make_sequence("halton:frames=4");
  s.step = 1.0 / 8;
  s.min_step = 1.0 / 16;
  s.max_tries = 12;
  return s;
}

// Started at the baseline the objective is 0; the result never exceeds it,
// and its value is the objective's definition over the comparison's renders.
TEST(RenderedSearch, NeverEndsAboveItsStartAndItsValueIsTheDefinition) {
  const RenderedSearch s = tiny();
  const RenderedSearchResult r = search_rendered(s, testing::centre_reference);
  EXPECT_EQ(r.start_value, 0.0);
  EXPECT_LE(r.value, 0.0);
  EXPECT_LE(r.tries, 12);
  const EngineComparisonResult c =
      compare_under_engine({s.baseline, r.best}, s.comparison, testing::centre_reference);
  double sum = 0;
  for (const ComparedScene& scene : c.scenes) {
    const double a = std::log(scene.measures[1][0] / scene.measures[0][0]),
                 b = std::log(scene.measures[1][1] / scene.measures[0][1]),
                 e = std::log(scene.measures[1][2] / scene.measures[0][2]);
    // The errors (rmse, flip) rewarded both ways, flicker only penalized.
    sum += a + e + s.loss * (std::max(0.0, a) + std::max(0.0, e)) + (1 + s.loss) * std::max(0.0, b);
  }
  EXPECT_NEAR(r.value, sum / 2, 1e-12);
  for (const Pattern& f : r.best.frames) {
    EXPECT_LE(std::abs(f.sets[0][0].x), 0.5);
    EXPECT_LE(std::abs(f.sets[0][0].y), 0.5);
  }
}

// With `worst` after a cut, each scene's measures are its worst phase's.
TEST(RenderedSearch, TheWorstIsEachScenesWorstPhase) {
  RenderedSearch s = tiny();
  s.comparison.motion = "cut";
  s.worst = true;
  s.max_tries = 6;
  const RenderedSearchResult r = search_rendered(s, testing::centre_reference);
  EXPECT_LE(r.value, 0.0);
  const EngineComparisonResult c =
      compare_under_engine({s.baseline, r.best}, s.comparison, testing::centre_reference);
  double sum = 0;
  for (const ComparedScene& scene : c.scenes) {
    const ComparisonMeasures &ours = scene.spread[1].worst, &theirs = scene.spread[0].worst;
    const double a = std::log(ours[0] / theirs[0]), b = std::log(ours[1] / theirs[1]),
                 e = std::log(ours[2] / theirs[2]);
    sum += a + e + s.loss * (std::max(0.0, a) + std::max(0.0, e)) + (1 + s.loss) * std::max(0.0, b);
  }
  EXPECT_NEAR(r.value, sum / 2, 1e-12);
  s.comparison.motion = "random-pan";  // one way per scene: no worst to take
  EXPECT_EQ(testing::error_parameter([&] { validate(s); }), "worst");
}

// Several motions at once: the objective is the mean over the motions of
// each one's objective, every motion's measures rendered as it renders them.
TEST(RenderedSearch, SeveralMotionsAreTheMeanOfTheirObjectives) {
  RenderedSearch s = tiny();
  s.also_motions = {"cut"};
  s.max_tries = 4;
  const RenderedSearchResult r = search_rendered(s, testing::centre_reference);
  double total = 0;
  for (const char* motion : {"random-pan", "cut"}) {
    EngineComparison c = s.comparison;
    c.motion = motion;
    const EngineComparisonResult cr =
        compare_under_engine({s.baseline, r.best}, c, testing::centre_reference);
    double sum = 0;
    for (const ComparedScene& scene : cr.scenes) {
      const double a = std::log(scene.measures[1][0] / scene.measures[0][0]),
                   b = std::log(scene.measures[1][1] / scene.measures[0][1]),
                   e = std::log(scene.measures[1][2] / scene.measures[0][2]);
      sum +=
          a + e + s.loss * (std::max(0.0, a) + std::max(0.0, e)) + (1 + s.loss) * std::max(0.0, b);
    }
    total += sum / 2;
  }
  EXPECT_NEAR(r.value, total / 2, 1e-12);
  EXPECT_EQ(rendered_search_json(s, r)["motions"].size(), 2u);
  s.also_motions = {"spin:fast"};
  EXPECT_THROW(validate(s), Error);
}

// Under FSR 2 no frame's jitter is the pixel centre: a start with one is
// refused, and the search never moves a frame onto it.
TEST(RenderedSearch, Fsr2NeverTakesANullVector) {
  RenderedSearch s = tiny();
  s.comparison.taa = make_engine_taa("fsr2", 1.5, {});
  s.start = make_sequence("bevy-halton:frames=8");  // the centre first
  EXPECT_EQ(testing::error_parameter([&] { validate(s); }), "start");
  s.start = s.baseline = make_sequence("halton:frames=4");
  s.step = 1.0 / 6;  // frame 0 is (0, -1/6): one step up in y is the null vector
  s.min_step = 1.0 / 12;
  const RenderedSearchResult r = search_rendered(s, testing::centre_reference);
  for (const Pattern& f : r.best.frames) EXPECT_FALSE(f.sets[0][0].x == 0 && f.sets[0][0].y == 0);
}

// Unbiased (XeSS's rule): from a biased start (Halton's four frames from
// index 1) every frame of the result is the searched one centred, so their
// mean is (0, 0), and the start's value is the centred start's; a start the
// centring pushes past the bound is refused by name.
TEST(RenderedSearch, UnbiasedKeepsTheMeanJitterAtZero) {
  RenderedSearch s = tiny();
  s.unbiased = true;
  const RenderedSearchResult r = search_rendered(s, testing::centre_reference);
  double mx = 0, my = 0;
  for (const Pattern& f : r.best.frames) {
    mx += f.sets[0][0].x;
    my += f.sets[0][0].y;
    EXPECT_LE(std::abs(f.sets[0][0].x), 0.5);
  }
  EXPECT_NEAR(mx, 0, 1e-12);
  EXPECT_NEAR(my, 0, 1e-12);
  EXPECT_LE(r.value, r.start_value);
  Sequence centred = s.start;
  double sx = 0, sy = 0;
  for (const Pattern& f : centred.frames) {
    sx += f.sets[0][0].x / 4;
    sy += f.sets[0][0].y / 4;
  }
  ASSERT_GT(std::abs(sx) + std::abs(sy), 0.01);  // the start is biased
  for (Pattern& f : centred.frames) f.sets[0][0] = {f.sets[0][0].x - sx, f.sets[0][0].y - sy};
  RenderedSearch at_centre = tiny();
  at_centre.start = centred;
  at_centre.max_tries = 1;
  EXPECT_NEAR(search_rendered(at_centre, testing::centre_reference).start_value, r.start_value,
              1e-12);
  EXPECT_EQ(rendered_search_json(s, r)["unbiased"], true);
  Sequence lopsided = s.start;
  const double xs[4] = {-0.5, 0.49, 0.49, 0.49};
  for (size_t f = 0; f < 4; ++f) lopsided.frames[f].sets[0][0].x = xs[f];
  s.start = lopsided;
  EXPECT_EQ(testing::error_parameter([&] { search_rendered(s, testing::centre_reference); }),
            "start");
}

// Settings out of range, and a baseline with nothing to take a ratio of,
// are refused by name.
TEST(RenderedSearch, RefusesWhatItCannotSearch) {
  RenderedSearch s = tiny();
  s.loss = -1;
  EXPECT_EQ(testing::error_parameter([&] { validate(s); }), "loss");
  s = tiny();
  s.step = 0.75;
  EXPECT_EQ(testing::error_parameter([&] { validate(s); }), "step");
  s = tiny();
  s.start = make_sequence("msaa-alternating:samples=2,frames=2");
  EXPECT_THROW(validate(s), Error);
  s = tiny();
  s.comparison.scenes = {"halfplane"};
  s.comparison.motion = "static";
  s.baseline = make_sequence("halton:frames=1");  // one phase: no flicker
  EXPECT_THROW(search_rendered(s, testing::centre_reference), Error);
}

}  // namespace
}  // namespace aapat

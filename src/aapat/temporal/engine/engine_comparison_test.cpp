#include "aapat/temporal/engine/engine_comparison.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "aapat/io/scene_json.h"
#include "aapat/render/motion.h"
#include "aapat/temporal/model/pan_distribution.h"
#include "aapat/temporal/sequence/sequence_generators.h"
#include "testing/centre_reference.h"
#include "testing/error_message.h"

namespace aapat {
namespace {

EngineComparison small(const std::string& motion) {
  EngineComparison c;
  c.taa = make_engine_taa("bevy", 1, {});
  c.scenes = random_scene_specs(3, 4, 11);
  c.motion = motion;
  c.width = c.height = 16;
  c.frames = 4;
  c.warmup = 3;
  c.resamples = 200;
  return c;
}

// After a cut, a measure is its mean over the phases the cut can fall on:
// the sequence started at each of its frames, rendered from an empty history.
TEST(EngineComparison, ACutIsTheMeanOverEveryStartingPhase) {
  const Sequence s = make_sequence("r2:frames=3");
  const EngineComparison c = small("cut");
  const EngineComparisonResult r = compare_under_engine({s, s}, c, testing::centre_reference);
  EngineRun run;
  run.scene = resolve_scene(c.scenes[2], 16, 16);
  run.motion = make_motion("static", 16, 16);
  run.width = run.height = 16;
  run.frames = 4;
  run.warmup = 0;
  run.reference = c.reference;
  double rmse = 0, flicker = 0, flip = 0, worst_rmse = 0, worst_flip = 0;
  for (int phase = 0; phase < 3; ++phase) {
    const Sequence started = started_at(s, phase);
    EXPECT_EQ(started.frames[0].sets[0][0].x, s.frames[static_cast<size_t>(phase)].sets[0][0].x);
    const EngineResult e = render_engine_taa(run, started, c.taa, {}, testing::centre_reference);
    rmse += e.total.rmse / 3;
    flicker += e.flicker / 3;
    flip += e.mean_flip / 3;
    worst_rmse = std::max(worst_rmse, e.total.rmse);
    worst_flip = std::max(worst_flip, e.mean_flip);
  }
  EXPECT_DOUBLE_EQ(r.scenes[2].measures[0][0], rmse);
  EXPECT_DOUBLE_EQ(r.scenes[2].measures[0][1], flicker);
  EXPECT_DOUBLE_EQ(r.scenes[2].measures[0][2], flip);
  ASSERT_EQ(r.scenes[2].spread.size(), 2u);
  EXPECT_EQ(r.scenes[2].spread[0].each.size(), 3u);
  EXPECT_EQ(r.scenes[2].spread[0].worst[0], worst_rmse);
  EXPECT_EQ(r.scenes[2].spread[0].worst[2], worst_flip);
  EXPECT_GE(worst_rmse, rmse);
  const JsonObject json = engine_comparison_json(c, r);
  const auto& row = json["scenes"][2]["rows"][0];
  EXPECT_EQ(row["worst_phase"]["rmse"].get<double>(), worst_rmse);
  EXPECT_EQ(row["worst_phase_at"]["rmse"].get<int>(), r.scenes[2].spread[0].worst_at[0]);
  EXPECT_EQ(json["against_first_worst"][0]["rmse"]["ties"], 3);  // the same sequence twice
  // Other motions have no phases to be worst at.
  const EngineComparisonResult still =
      compare_under_engine({s, s}, small("static"), testing::centre_reference);
  EXPECT_TRUE(still.scenes[0].spread.empty());
  EXPECT_TRUE(still.against_first_worst.empty());
  EXPECT_FALSE(engine_comparison_json(small("static"), still).contains("against_first_worst"));
  EXPECT_EQ(r.scenes[2].measures[0], r.scenes[2].measures[1]);  // the same sequence twice
}

// At the resonances every scene is panned at each resonant velocity (render
// pixels per frame, on the display times the ratio) in steady state: each
// measure is the mean over them, the worst is the largest with the velocity
// it came at, and the worst are compared as the means are.
TEST(EngineComparison, TheResonancesAreEveryResonantVelocitysRender) {
  const std::vector<Sequence> seqs{make_sequence("halton:frames=4"), make_sequence("r2:frames=4")};
  EngineComparison c = small("resonant");
  c.taa = make_engine_taa("fsr2", 1.5, {});
  c.scenes.resize(2);
  c.width = c.height = 12;
  c.frames = 2;
  c.warmup = 2;
  const EngineComparisonResult r = compare_under_engine(seqs, c, testing::centre_reference);
  const std::vector<Vec2> velocities = resonant_velocities();
  ASSERT_EQ(r.velocities.size(), velocities.size());
  const MeasureSpread& spread = r.scenes[1].spread[1];
  ASSERT_EQ(spread.each.size(), velocities.size());
  EngineRun run;
  run.scene = resolve_scene(c.scenes[1], 12, 12);
  run.width = run.height = 12;
  run.frames = 2;
  run.warmup = 2;
  run.reference = c.reference;
  ComparisonMeasures mean{};
  for (size_t v = 0; v < velocities.size(); ++v) {
    run.motion = make_motion(
        fmt::format("pan:dx={},dy={}", 1.5 * velocities[v].x, 1.5 * velocities[v].y), 12, 12);
    if (v == 33) {  // (1/2, 1/3): Halton's two resonances at once
      EXPECT_EQ(run.motion.pan.x, 0.75);
      EXPECT_EQ(run.motion.pan.y, 0.5);
    }
    const EngineResult e = render_engine_taa(run, seqs[1], c.taa, {}, testing::centre_reference);
    EXPECT_EQ(spread.each[v][0], e.total.rmse) << v;
    EXPECT_EQ(spread.each[v][2], e.mean_flip) << v;
    mean[0] += e.total.rmse / static_cast<double>(velocities.size());
  }
  EXPECT_NEAR(r.scenes[1].measures[1][0], mean[0], 1e-12 * mean[0]);
  for (size_t q = 0; q < kComparisonMeasures.size(); ++q) {
    const auto i = static_cast<size_t>(spread.worst_at[q]);
    EXPECT_EQ(spread.worst[q], spread.each[i][q]);
    for (const ComparisonMeasures& m : spread.each) EXPECT_LE(m[q], spread.worst[q]);
  }
  std::vector<double> ours, theirs;
  for (const ComparedScene& s : r.scenes)
    ours.push_back(s.spread[1].worst[0]), theirs.push_back(s.spread[0].worst[0]);
  const PairedComparison p = compare_paired(ours, theirs, c.resamples, c.confidence, c.seed);
  EXPECT_EQ(r.against_first_worst[0][0].mean_difference, p.mean_difference);
  const JsonObject json = engine_comparison_json(c, r);
  EXPECT_EQ(json["velocities"].size(), velocities.size());
  const auto& row = json["scenes"][1]["rows"][1];
  EXPECT_EQ(row["per_velocity"].size(), velocities.size());
  EXPECT_EQ(row["worst_velocity"]["rmse"].get<double>(), spread.worst[0]);
  const Vec2 at = velocities[static_cast<size_t>(spread.worst_at[0])];
  EXPECT_EQ(row["worst_velocity_at"]["rmse"][0].get<double>(), at.x);
  EXPECT_EQ(row["worst_velocity_at"]["rmse"][1].get<double>(), at.y);
}

// The grid holds each axis's resonances with both signs, and R2's step.
TEST(EngineComparison, TheResonantVelocitiesHoldEveryResonance) {
  const std::vector<Vec2> v = resonant_velocities();
  ASSERT_EQ(v.size(), 38u);
  const auto has = [&](Vec2 w) {
    return std::any_of(v.begin(), v.end(), [&](Vec2 u) { return u.x == w.x && u.y == w.y; });
  };
  for (const double a : {0.0, 0.25, -0.25, 1.0 / 3, -1.0 / 3, 0.5})
    for (const double b : {0.0, 0.25, -0.25, 1.0 / 3, -1.0 / 3, 0.5}) EXPECT_TRUE(has({a, b}));
  EXPECT_NEAR(v[36].x, 0.7548776662466927, 1e-15);  // 1/g, g^3 = g + 1
  EXPECT_NEAR(v[36].y, 0.5698402909980532, 1e-15);  // 1/g^2
  EXPECT_EQ(v[37].x, -v[36].x);
}

// Every scene's measures are the engine's own render of it, and every
// comparison is compare_paired of those measures.
TEST(EngineComparison, ItsMeasuresAreTheRendersAndItsComparisonsThePairedStatistics) {
  const std::vector<Sequence> seqs{make_sequence("halton:frames=8"), make_sequence("r2:frames=8")};
  const EngineComparison c = small("random-pan");
  const EngineComparisonResult r = compare_under_engine(seqs, c, testing::centre_reference);
  ASSERT_EQ(r.scenes.size(), 3u);
  ASSERT_EQ(r.against_first.size(), 1u);
  const std::vector<Vec2> v = random_pan_velocities(3, c.max_speed, c.seed);
  EngineRun run;
  run.scene = resolve_scene(c.scenes[1], 16, 16);
  run.motion = make_motion(r.scenes[1].motion, 16, 16);
  run.width = run.height = 16;
  run.frames = 4;
  run.warmup = 3;
  run.reference = c.reference;
  const EngineResult e = render_engine_taa(run, seqs[1], c.taa, {}, testing::centre_reference);
  EXPECT_EQ(r.scenes[1].motion, fmt::format("pan:dx={:g},dy={:g}", v[1].x, v[1].y));
  EXPECT_EQ(r.scenes[1].measures[1][0], e.total.rmse);
  EXPECT_EQ(r.scenes[1].measures[1][1], e.flicker);
  EXPECT_EQ(r.scenes[1].measures[1][2], e.mean_flip);
  for (size_t q = 0; q < kComparisonMeasures.size(); ++q) {
    std::vector<double> ours, theirs;
    for (const ComparedScene& s : r.scenes)
      ours.push_back(s.measures[1][q]), theirs.push_back(s.measures[0][q]);
    const PairedComparison p = compare_paired(ours, theirs, c.resamples, c.confidence, c.seed);
    EXPECT_EQ(r.against_first[0][q].lower, p.lower) << q;
    EXPECT_EQ(r.against_first[0][q].low, p.low) << q;
    EXPECT_EQ(r.against_first[0][q].high, p.high) << q;
  }
}

// A sequence against itself ties on every scene; a cut has no warm-up.
TEST(EngineComparison, ASequenceAgainstItselfTiesEverywhere) {
  const std::vector<Sequence> seqs{make_sequence("halton:frames=4"),
                                   make_sequence("halton:frames=4")};
  const EngineComparisonResult r =
      compare_under_engine(seqs, small("cut"), testing::centre_reference);
  for (const PairedComparison& p : r.against_first[0]) {
    EXPECT_EQ(p.ties, 3);
    EXPECT_EQ(p.mean_difference, 0.0);
    EXPECT_EQ(p.sign_p, 1.0);
  }
  EXPECT_EQ(r.scenes[0].motion, "static");
  EXPECT_EQ(engine_comparison_json(small("cut"), r)["warmup"], 0);
}

// Settings out of range are refused by name before any render.
TEST(EngineComparison, RefusesSettingsByName) {
  const std::vector<Sequence> two{make_sequence("halton:frames=4"), make_sequence("r2:frames=4")};
  EngineComparison c = small("static");
  c.scenes.clear();
  EXPECT_EQ(testing::error_parameter([&] { validate(c, 2); }), "scene");
  c = small("static");
  EXPECT_THROW(validate(c, 1), Error);
  c.frames = 0;
  EXPECT_EQ(testing::error_parameter([&] { validate(c, 2); }), "frames");
  c = small("spin:fast");
  EXPECT_THROW(validate(c, 2), Error);
  // An unknown motion lists the comparison's own motions and the render's.
  c = small("sideways");
  const std::string m = testing::error_message([&] { validate(c, 2); });
  EXPECT_EQ(testing::error_parameter([&] { validate(c, 2); }), "motion");
  EXPECT_NE(m.find("'sideways'"), std::string::npos) << m;
  EXPECT_NE(m.find("resonant"), std::string::npos) << m;
  EXPECT_NE(m.find("orbit"), std::string::npos) << m;
  EXPECT_EQ(testing::error_parameter([&] { random_scene_specs(0, 4, 1); }), "random-scenes");
  EXPECT_EQ(testing::error_parameter([&] { random_scene_specs(3, 0, 1); }), "shapes");
  EXPECT_EQ(random_scene_specs(2, 5, 7)[1], "random-shapes:count=5,seed=8");
}

}  // namespace
}  // namespace aapat

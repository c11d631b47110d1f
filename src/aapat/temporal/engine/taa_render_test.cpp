#include "aapat/temporal/engine/taa_render.h"

#include <gtest/gtest.h>

#include "aapat/temporal/sequence/sequence_generators.h"
#include "testing/centre_reference.h"

namespace aapat {
namespace {

const ReferenceSource kCheapReference = testing::centre_reference;

TaaScenes still(const Scene& scene, int frames) {
  TaaScenes s;
  s.scene_at = [scene](int) { return scene; };
  s.reference_frame = [](int) { return 0; };
  s.width = 12;
  s.height = 10;
  s.frames = frames;
  return s;
}

// A box of the period over a static scene shows, at every steady frame, the
// scene rendered with the union of the frames' samples at equal weights;
// an EMA of alpha 1 shows the frame's own rendering.
TEST(TaaRender, AccumulatedFramesAreThePatternsTheMetricEvaluates) {
  const Scene scene = make_scene("spiral", 12, 10);
  const Sequence s = make_sequence("r2:frames=5");
  std::vector<Vec2> all = samples_in_order(s);
  Sampling union_sampling;
  union_sampling.pattern = single_pixel_pattern("union", all, std::vector<double>(all.size(), 1.0));
  const Image expected = render(scene, 12, 10, union_sampling, std::nullopt);
  Accumulation box;
  box.kind = AccumulationKind::box;
  render_taa(
      still(scene, 5), s, box, true,
      [&](int, const Image& shown) {
        for (size_t i = 0; i < shown.values.size(); ++i)
          EXPECT_NEAR(shown.values[i], expected.values[i], 1e-12);
      },
      kCheapReference);
  Accumulation single;
  single.alpha = 1;
  const TaaResult r = render_taa(
      still(scene, 5), s, single, true,
      [&](int f, const Image& shown) {
        Sampling own;
        own.pattern = s.frames[static_cast<size_t>(f)];
        EXPECT_EQ(shown.values, render(scene, 12, 10, own, std::nullopt).values) << f;
      },
      kCheapReference);
  EXPECT_EQ(r.frames.size(), 5u);
  EXPECT_EQ(r.frames[0].flicker, 0);
}

// The whole period in a box shows the same image every frame: no flicker.
TEST(TaaRender, ABoxOfThePeriodDoesNotFlickerOnAStaticScene) {
  Accumulation box;
  box.kind = AccumulationKind::box;
  const TaaResult r = render_taa(still(make_scene("circles", 12, 10), 8),
                                 make_sequence("halton:frames=4"), box, true, {}, kCheapReference);
  EXPECT_EQ(r.flicker, 0);
  Accumulation ema;
  EXPECT_GT(render_taa(still(make_scene("circles", 12, 10), 8), make_sequence("halton:frames=4"),
                       ema, true, {}, kCheapReference)
                .flicker,
            0);
}

}  // namespace
}  // namespace aapat

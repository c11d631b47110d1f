#include "aapat/render/motion.h"

#include <gtest/gtest.h>

#include <random>

#include "aapat/render/scene.h"

namespace aapat {
namespace {

// A motion vector points where the scene point under a pixel was a frame
// earlier: the views of frames f and f - 1 read the same scene point there.
TEST(Motion, PreviousPointReadsTheSameScenePoint) {
  const Scene base = make_scene("checkerboard", 40, 30);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0, 30);
  for (const char* spec : {"pan:dx=0.7,dy=-0.3", "rotate:deg=3,cx=10,cy=12", "static"}) {
    const Motion m = make_motion(spec, 40, 30);
    for (int f : {-3, 1, 5}) {
      const Scene now = moved_scene(base, m, f), before = moved_scene(base, m, f - 1);
      for (int k = 0; k < 20; ++k) {
        const Vec2 p{u(rng), u(rng)};
        const Vec2 a = now.view.to_scene(p), b = before.view.to_scene(previous_point(m, p));
        EXPECT_NEAR(a.x, b.x, 1e-9) << spec;
        EXPECT_NEAR(a.y, b.y, 1e-9) << spec;
      }
    }
  }
  EXPECT_THROW(make_motion("pan:dx=20", 40, 30), Error);      // half the image per frame
  EXPECT_THROW(make_motion("rotate:deg=90", 40, 30), Error);  // the corners move too far
  EXPECT_THROW(make_motion("pan:speed=1", 40, 30), Error);
  EXPECT_THROW(make_motion("spin", 40, 30), Error);
  EXPECT_THROW(make_motion("rotate:deg=nan", 40, 30), Error);
}

}  // namespace
}  // namespace aapat

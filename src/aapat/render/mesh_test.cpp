#include "aapat/render/mesh.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include "aapat/core/filter_catalog.h"
#include "aapat/render/adaptive.h"
#include "aapat/render/color_render.h"
#include "aapat/render/motion.h"
#include "aapat/render/renderer.h"
#include "aapat/render/surface.h"
#include "testing/error_message.h"

namespace aapat {
namespace {

// A mesh of the given triangles (one flat white material, no texture).
std::shared_ptr<Mesh> mesh_of(std::vector<Vec3> positions,
                              std::vector<std::array<uint32_t, 3>> triangles) {
  auto m = std::make_shared<Mesh>();
  m->positions = std::move(positions);
  m->triangles = std::move(triangles);
  m->material.assign(m->triangles.size(), 0);
  m->materials.push_back({"white", {1, 1, 1}, {}, ""});
  return m;
}

// Lit evenly (ambient 1) on a black background: a covered point is 1.
MeshLight flat_light() {
  MeshLight l;
  l.ambient = 1;
  l.background = {0, 0, 0};
  return l;
}

// The eye at (0, 0, d) looking at the origin: a point (x, y, 0) projects to
// the image centre plus focal x / d, focal = (h / 2) / tan(fov / 2).
TEST(Mesh, ProjectsThroughAPinhole) {
  auto m = mesh_of({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
  const MeshCamera cam{{0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 90};
  const auto view = make_mesh_view(m, cam, flat_light(), 101, 101);
  ASSERT_EQ(view->triangles().size(), 1u);
  const ScreenTriangle& t = view->triangles()[0];
  const double focal = 50.5;  // tan(45 deg) = 1
  EXPECT_NEAR(t.p[0].x, 50, 1e-12);
  EXPECT_NEAR(t.p[0].y, 50, 1e-12);
  EXPECT_NEAR(t.p[1].x, 50 + focal / 5, 1e-12);
  EXPECT_NEAR(t.p[2].y, 50 + focal / 5, 1e-12);
  EXPECT_NEAR(t.inv_z[0], 0.2, 1e-15);
}

// The nearer of two overlapping triangles is seen, whichever comes first.
TEST(Mesh, DepthTestPerSample) {
  for (bool near_first : {true, false}) {
    std::vector<Vec3> p = {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}, {-1, -1, 1}, {1, -1, 1}, {0, 1, 1}};
    std::vector<std::array<uint32_t, 3>> tris = {{0, 1, 2}, {3, 4, 5}};
    if (near_first) std::swap(tris[0], tris[1]);
    auto m = mesh_of(p, tris);
    m->materials.push_back({"grey", {0.5, 0.5, 0.5}, {}, ""});
    m->material = {0, 1};  // the first listed white, the second grey
    const auto view =
        make_mesh_view(m, {{0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 60}, flat_light(), 64, 64);
    const MeshHit h = view->hit({31.5, 31.5});
    ASSERT_GE(h.triangle, 0);
    EXPECT_EQ(view->triangles()[static_cast<size_t>(h.triangle)].source, near_first ? 0u : 1u);
  }
}

// Two triangles sharing an edge leave no crack along it: every point of the
// diagonal of a quad is covered.
TEST(Mesh, SharedEdgesLeaveNoCrack) {
  auto m = mesh_of({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}, {{0, 1, 2}, {0, 2, 3}});
  const auto view =
      make_mesh_view(m, {{0.3, 0.2, 4}, {0, 0, 0}, {0, 1, 0}, 50}, flat_light(), 97, 61);
  const auto& t = view->triangles();
  for (int k = 0; k <= 1000; ++k) {
    const double s = k / 1000.0;
    const Vec2 a = t[0].p[0], c = t[0].p[2];  // the diagonal 0-2 in screen space
    EXPECT_GE(view->hit({a.x + s * (c.x - a.x), a.y + s * (c.y - a.y)}).triangle, 0) << s;
  }
}

// A triangle through the eye's plane is clipped at the near plane: what is
// in front renders, nothing is NaN, and no vertex behind the eye flips over.
TEST(Mesh, ClipsAtTheNearPlane) {
  auto m = mesh_of({{-1, -0.2, 0}, {1, -0.2, 0}, {0, -0.2, 10}}, {{0, 1, 2}});  // reaches behind
  const auto view = make_mesh_view(m, {{0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 60}, flat_light(), 64, 64);
  ASSERT_FALSE(view->triangles().empty());
  for (const ScreenTriangle& t : view->triangles())
    for (int k = 0; k < 3; ++k) {
      EXPECT_TRUE(std::isfinite(t.p[k].x) && std::isfinite(t.p[k].y));
      EXPECT_GT(t.inv_z[k], 0);
    }
  Sampling s;
  s.pattern = std::nullopt;
  s.generator = "jittered";
  s.samples = 4;
  const Image img = render(Scene(MeshScene{view, 0}), 64, 64, s, make_filter("box"));
  for (double v : img.values) EXPECT_TRUE(v >= 0 && v <= 1);
  EXPECT_GT(img.at(32, 5), 0.5);  // the floor in front, below the centre
}

// The perspective-correct weights: 1 at their own vertex, summing to 1, and
// their derivatives those of finite differences.
RC_GTEST_PROP(Mesh, PerspectiveWeightsAndTheirDerivatives, ()) {
  auto coord = [] { return *rc::gen::inRange(-100, 100) / 100.0; };
  auto m = mesh_of({{coord(), coord(), coord()},
                    {coord() + 1.5, coord(), coord()},
                    {coord(), coord() + 1.5, coord() - 0.5}},
                   {{0, 1, 2}});
  const MeshCamera cam{{0.3, 0.4, 6}, {0, 0, 0}, {0, 1, 0}, 40};
  const auto view = make_mesh_view(m, cam, flat_light(), 128, 96);
  RC_PRE(view->triangles().size() == 1u);
  const ScreenTriangle& t = view->triangles()[0];
  RC_PRE(std::abs((t.p[1].x - t.p[0].x) * (t.p[2].y - t.p[0].y) -
                  (t.p[1].y - t.p[0].y) * (t.p[2].x - t.p[0].x)) > 20);
  for (int k = 0; k < 3; ++k) {
    const MeshView::Weights w = view->weights(0, t.p[k]);
    for (int q = 0; q < 3; ++q) RC_ASSERT(std::abs(w.w[q] - (q == k ? 1.0 : 0.0)) < 1e-9);
  }
  const Vec2 p = (1.0 / 3) * (t.p[0] + t.p[1] + t.p[2]);
  const MeshView::Weights w = view->weights(0, p);
  RC_ASSERT(std::abs(w.w[0] + w.w[1] + w.w[2] - 1) < 1e-12);
  const double h = 1e-5;
  const MeshView::Weights xp = view->weights(0, {p.x + h, p.y}),
                          xm = view->weights(0, {p.x - h, p.y});
  const MeshView::Weights yp = view->weights(0, {p.x, p.y + h}),
                          ym = view->weights(0, {p.x, p.y - h});
  for (int q = 0; q < 3; ++q) {
    RC_ASSERT(std::abs((xp.w[q] - xm.w[q]) / (2 * h) - w.dx[q]) < 1e-6);
    RC_ASSERT(std::abs((yp.w[q] - ym.w[q]) / (2 * h) - w.dy[q]) < 1e-6);
  }
}

// Lambert's law: a face turned by angle a from the light is lit
// ambient + (1 - ambient) cos a, from either side.
TEST(Mesh, LambertFromOneDirectionalLight) {
  auto m = mesh_of({{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}}, {{0, 1, 2}});
  for (bool flipped : {false, true}) {
    if (flipped) m->triangles[0] = {0, 2, 1};
    MeshLight l;
    l.ambient = 0.25;
    l.direction = {0, std::sin(radians(30)),
                   std::cos(radians(30))};  // 30 degrees above the view axis
    const auto view = make_mesh_view(m, {{0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 60}, l, 32, 32);
    EXPECT_NEAR(view->triangles()[0].light, 0.25 + 0.75 * std::cos(radians(30)), 1e-12);
  }
}

// The orbit camera frames the bounding sphere: every vertex lands in the
// image, and the sphere's centre at its centre.
RC_GTEST_PROP(Mesh, OrbitFramesTheModel, ()) {
  std::vector<Vec3> p;
  for (int k = 0; k < 12; ++k)
    p.push_back({*rc::gen::inRange(-500, 500) / 50.0, *rc::gen::inRange(-500, 500) / 50.0,
                 *rc::gen::inRange(-500, 500) / 50.0});
  std::vector<std::array<uint32_t, 3>> tris;
  for (uint32_t k = 0; k + 2 < 12; k += 3) tris.push_back({k, k + 1, k + 2});
  auto m = mesh_of(p, tris);
  const double yaw = *rc::gen::inRange(-180, 180), pitch = *rc::gen::inRange(-80, 80);
  const MeshCamera cam = orbit_camera(*m, yaw, pitch, 40);
  const auto view = make_mesh_view(m, cam, flat_light(), 64, 64);
  for (const ScreenTriangle& t : view->triangles())
    for (const Vec2& q : t.p) RC_ASSERT(q.x >= -0.5 && q.x <= 63.5 && q.y >= -0.5 && q.y <= 63.5);
}

// A mesh with a bad index, a NaN vertex or no triangles is refused by name.
TEST(Mesh, ValidationNamesTheProblem) {
  auto m = mesh_of({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 3}});
  EXPECT_EQ(testing::error_message([&] { validate(*m, "m"); }),
            "m: triangle 0 names vertex 3 of 3");
  m->triangles[0] = {0, 1, 2};
  m->positions[1].y = NAN;
  EXPECT_EQ(testing::error_message([&] { validate(*m, "m"); }),
            "m: vertex 1 is not finite (1, nan, 0)");
  m->triangles.clear();
  m->material.clear();
  EXPECT_EQ(testing::error_message([&] { validate(*m, "m"); }), "m: the model has no triangles");
  EXPECT_EQ(testing::error_message([&] {
              validate(MeshCamera{{0, 0, 0}, {0, 0, 0}, {0, 1, 0}, 40}, "c");
            }),
            "c: the eye is at the target");
}

// A colour rendering carries the three channels of one set of samples: with
// base colours in powers of two, the channels' ratios are exact; and the
// grey face of channel c (shade) is the colour's channel c.
TEST(Mesh, ColourRendersThreeChannelsOfTheSameSamples) {
  auto m = mesh_of({{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}}, {{0, 1, 2}});
  m->materials[0].base = {1, 0.5, 0.25};
  const auto view = make_mesh_view(m, {{0, 0, 4}, {0, 0, 0}, {0, 1, 0}, 60}, flat_light(), 24, 16);
  Sampling s;
  s.generator = "jittered";
  s.samples = 4;
  const Scene scene(MeshScene{view, 0});
  const Image img = render(scene, 24, 16, s, make_filter("box"));
  ASSERT_EQ(img.channels, 3);
  ASSERT_EQ(img.values.size(), 3 * img.pixels());
  double covered = 0;
  for (size_t p = 0; p < img.pixels(); ++p) {
    EXPECT_DOUBLE_EQ(img.values[3 * p + 1], 0.5 * img.values[3 * p]);
    EXPECT_DOUBLE_EQ(img.values[3 * p + 2], 0.25 * img.values[3 * p]);
    covered += img.values[3 * p];
  }
  EXPECT_GT(covered, 10);
  for (int k = 0; k < 200; ++k) {
    const Vec2 p{k % 24 + 0.37, (k * 7) % 16 + 0.61};
    const Rgb c = shade_colour(scene, p);
    for (int ch = 0; ch < 3; ++ch)
      EXPECT_EQ(shade(Scene(MeshScene{view, ch}), p), c[static_cast<size_t>(ch)]);
  }
  EXPECT_EQ(channel_image(img, 1).values[0], img.values[1]);
}

// Adaptive refinement judges each channel: a red triangle on a black
// background refines along its edges (where red changes) and nowhere else,
// and the image is in colour, green and blue zero.
TEST(Mesh, AdaptiveRefinementInColour) {
  auto m = mesh_of({{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}}, {{0, 1, 2}});
  m->materials[0].base = {1, 0, 0};
  const auto view = make_mesh_view(m, {{0, 0, 4}, {0, 0, 0}, {0, 1, 0}, 60}, flat_light(), 32, 32);
  AdaptiveSettings a;
  a.initial.generator = "jittered";
  a.initial.samples = 4;
  a.criterion = RefinementCriterion::contrast;
  const AdaptiveImage r = render_adaptive(Scene(MeshScene{view, 0}), 32, 32, a, make_filter("box"));
  ASSERT_EQ(r.image.channels, 3);
  EXPECT_GT(r.refined_fraction, 0.02);
  EXPECT_LT(r.refined_fraction, 0.5);
  for (size_t p = 0; p < r.image.pixels(); ++p) {
    EXPECT_EQ(r.image.values[3 * p + 1], 0);
    EXPECT_EQ(r.image.values[3 * p + 2], 0);
  }
}

// An orbit's motion vectors: a pixel's surface point, projected through the
// earlier camera, is the surface point the earlier frame shows there; the
// front triangle hides a part of the back one, which then has no history.
TEST(Mesh, OrbitMotionVectorsFindTheSameSurfacePoint) {
  auto m = mesh_of({{-1, -1, 0},
                    {1, -1, 0},
                    {1, 1, 0},
                    {-1, 1, 0},
                    {-0.2, -0.2, 0.5},
                    {0.3, -0.2, 0.5},
                    {0.05, 0.3, 0.5}},
                   {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}});
  MeshScene mesh{make_mesh_view(m, {{0, 0, 4}, {0, 0, 0}, {0, 1, 0}, 50}, flat_light(), 64, 48), 0};
  const Scene first(mesh);
  const Motion orbit = make_motion("orbit:deg=3", 64, 48);
  const Scene now = moved_scene(first, orbit, 1), before = moved_scene(first, orbit, 0);
  int followed = 0, disoccluded = 0;
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 64; ++x) {
      const Vec2 p{double(x), double(y)};
      const Vec2 q = previous_point(orbit, now, before, p);
      const auto a = std::get<MeshScene>(now.shape).view->surface_point(p);
      if (!a) {
        EXPECT_EQ(q, p);  // the background stays
        continue;
      }
      if (std::isnan(q.x)) {
        ++disoccluded;
        continue;
      }
      const auto b = std::get<MeshScene>(before.shape).view->surface_point(q);
      ASSERT_TRUE(b.has_value());
      EXPECT_NEAR(b->x, a->x, 1e-6);
      EXPECT_NEAR(b->y, a->y, 1e-6);
      EXPECT_NEAR(b->z, a->z, 1e-6);
      ++followed;
    }
  EXPECT_GT(followed, 500);
  EXPECT_GT(disoccluded, 0);  // the back quad's strip the front triangle hid
  EXPECT_THROW(moved_scene(make_scene("spiral", 64, 48), orbit, 1), Error);
}

}  // namespace
}  // namespace aapat

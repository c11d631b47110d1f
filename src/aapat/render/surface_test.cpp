#include "aapat/render/surface.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include "aapat/core/filter_catalog.h"
#include "aapat/generate/catalog.h"
#include "aapat/render/renderer.h"

namespace aapat {
namespace {

std::shared_ptr<const TexturedSurface> surface(const char* spec) {
  return std::make_shared<const TexturedSurface>(make_texture(spec));
}

Scene textured_board(const char* texture = "checker:cells=8,size=256", double rotation = 20) {
  CheckerboardScene board;
  board.width = board.height = 64;
  board.rotation_deg = rotation;
  board.texture = surface(texture);
  return board;
}

// Finite differences of the texture coordinates against the analytic
// Jacobian, on the plane in perspective (through a rotated, scaled view).
RC_GTEST_PROP(TextureCoordinates, ThePlanesJacobianIsTheDerivative, ()) {
  Scene scene = textured_board("checker", *rc::gen::inRange(-90, 90));
  scene.view = {{32, 32}, double(*rc::gen::inRange(-30, 30)), 1.25, {0.5, -2}};
  const Vec2 p{*rc::gen::inRange(0, 6400) / 100.0, *rc::gen::inRange(0, 4000) / 100.0};
  const auto c = texture_coordinates(scene, 1, p);
  RC_PRE(c.has_value());
  const double h = 1e-5;
  const auto px = texture_coordinates(scene, 1, {p.x + h, p.y});
  const auto py = texture_coordinates(scene, 1, {p.x, p.y + h});
  RC_PRE(px && py);
  auto close = [&](double analytic, double numeric) {
    return std::abs(analytic - numeric) <= 1e-4 * (1 + std::abs(analytic));
  };
  RC_ASSERT(close(c->j.dsdx, (px->s - c->s) / h));
  RC_ASSERT(close(c->j.dtdx, (px->t - c->t) / h));
  RC_ASSERT(close(c->j.dsdy, (py->s - c->s) / h));
  RC_ASSERT(close(c->j.dtdy, (py->t - c->t) / h));
}

// Straight ahead on the ground at depth z (board unrotated): one pixel spans
// z / f squares across and z^2 / (eye f) squares in depth, T / period texels
// a square, so the max formula's level is log2 of the larger.
TEST(TextureCoordinates, TheLevelOnThePlaneAtKnownDepths) {
  CheckerboardScene board;
  board.width = board.height = 256;
  board.rotation_deg = 0;
  board.texture = surface("checker:cells=8,size=512");
  const Scene scene = board;
  const double f = board.focal * board.width, texels_per_square = 512 / board.period;
  for (const double z : {2.0, 5.0, 20.0, 80.0}) {
    // The row whose ray meets the ground at depth z: drop = eye / z.
    const Vec2 p{board.width / 2, board.horizon * board.height - board.eye_height / z * f};
    const auto c = texture_coordinates(scene, 1, p);
    ASSERT_TRUE(c);
    EXPECT_NEAR(c->j.dsdx, z / f * texels_per_square, 1e-9 * z);
    EXPECT_NEAR(c->j.dtdy, z * z / (board.eye_height * f) * texels_per_square, 1e-9 * z * z);
    const double footprint = std::max(z / f, z * z / (board.eye_height * f)) * texels_per_square;
    EXPECT_NEAR(level_of_detail(c->j, LodFormula::max), std::log2(footprint), 1e-9) << z;
  }
}

// A textured square facing the viewer at one depth (all w equal): affine,
// T / side texels per pixel; at twice the depth it is drawn half as large and
// its level is one higher.
TEST(TextureCoordinates, APolygonFacingTheViewer) {
  for (const double side : {32.0, 16.0}) {
    ShapesScene s;
    Shape square;
    square.polygon = {{0, 0}, {side, 0}, {side, side}, {0, side}};
    square.uv = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    square.w = {2, 2, 2, 2};
    square.texture = surface("checker:cells=4,size=64");
    s.shapes.push_back(square);
    index_shapes(s);
    const Scene scene = s;
    const auto c = texture_coordinates(scene, 1, {side / 4, side / 2});
    ASSERT_TRUE(c);
    EXPECT_NEAR(c->s, 16, 1e-12);
    EXPECT_NEAR(c->t, 32, 1e-12);
    EXPECT_NEAR(level_of_detail(c->j, LodFormula::max), std::log2(64 / side), 1e-12);
  }
}

// Perspective-correct interpolation: a square tilted away, its far edge at
// w = 3 drawn a third as wide, reads the texture as the projection does:
// u = x_world, the screen point x = x_world / w.
TEST(TextureCoordinates, PerspectiveCorrectInterpolation) {
  ShapesScene s;
  Shape quad;
  // World square [0,1]^2 at depth w = 1 + 2 y, drawn at (x / w, y / w) scaled by 60.
  auto screen = [](double x, double y) {
    const double w = 1 + 2 * y;
    return Vec2{60 * x / w, 60 * y / w};
  };
  quad.polygon = {screen(0, 0), screen(1, 0), screen(1, 1), screen(0, 1)};
  quad.uv = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  quad.w = {1, 1, 3, 3};
  quad.texture = surface("checker:cells=1,size=100");
  s.shapes.push_back(quad);
  index_shapes(s);
  const Scene scene = s;
  for (const auto& [x, y] : {std::pair{0.3, 0.2}, std::pair{0.7, 0.9}, std::pair{0.5, 0.5}}) {
    const auto c = texture_coordinates(scene, 1, screen(x, y));
    ASSERT_TRUE(c);
    EXPECT_NEAR(c->s, 100 * x, 1e-9);
    EXPECT_NEAR(c->t, 100 * y, 1e-9);
  }
}

// Flat primitives: shading once per pixel and primitive is shading every
// sample, so multisampling is supersampling exactly, for every catalog
// pattern, both shading points, both reconstructions.
TEST(Multisampling, EqualsSupersamplingOnFlatScenes) {
  ShapesScene shapes;
  shapes.background = 0.2;
  Shape tri, disc;
  tri.polygon = {{2, 3}, {28, 9}, {11, 27}};
  tri.grey = 0.9;
  disc.centre = {20, 20};
  disc.radius = 7.3;
  disc.grey = 0.45;
  shapes.shapes = {tri, disc};
  index_shapes(shapes);
  CheckerboardScene board;
  board.width = board.height = 32;
  const std::vector<Scene> scenes = {Scene(shapes), Scene(board),
                                     Scene(HalfPlaneScene{{15.2, 16.1}, 33, 0.3}),
                                     make_scene("circles", 32, 32), make_scene("sliver", 32, 32)};
  for (const auto& entry : pattern_registry().entries()) {
    Sampling s;
    s.pattern = catalog_pattern(entry.info.name == "grid-NxN" ? "grid-3x3" : entry.info.name);
    for (const Scene& scene : scenes)
      for (const auto& filter :
           {std::optional<Filter>(), std::optional<Filter>(make_filter("box"))}) {
        s.shading = {};
        const Image super = render(scene, 32, 32, s, filter);
        for (const ShadingPoint point : {ShadingPoint::centre, ShadingPoint::centroid}) {
          s.shading.mode = ShadingMode::multisample;
          s.shading.point = point;
          EXPECT_EQ(render(scene, 32, 32, s, filter).values, super.values) << entry.info.name;
        }
      }
  }
}

// A texture varies within a primitive: shading it once per pixel differs
// from shading every sample; a fully covered pixel of a symmetric pattern
// is shaded alike at its centre and its samples' centroid.
TEST(Multisampling, DiffersOnTexturedScenes) {
  const Scene scene = textured_board();
  Sampling s;
  s.pattern = catalog_pattern("rgss");
  const Image super = render(scene, 64, 64, s, std::nullopt);
  s.shading.mode = ShadingMode::multisample;
  const Image centre = render(scene, 64, 64, s, std::nullopt);
  s.shading.point = ShadingPoint::centroid;
  const Image centroid = render(scene, 64, 64, s, std::nullopt);
  EXPECT_NE(super.values, centre.values);
  for (int j = 0; j < 40; ++j)  // below the horizon (row 51), every pixel all ground
    for (int i = 0; i < 64; ++i) ASSERT_EQ(centre.at(i, j), centroid.at(i, j)) << i << "," << j;
}

// The textured board with an 8 x 8 checker repeating every 8 squares is the
// checkerboard: supersampling its exact texels gives the same image.
TEST(Multisampling, TheCheckerTextureIsTheCheckerboard) {
  CheckerboardScene plain;
  plain.width = plain.height = 64;
  Sampling s;
  for (const char* pattern : {"rgss", "msaa-8", "flipquad"}) {
    s.pattern = catalog_pattern(pattern);
    EXPECT_EQ(render(textured_board(), 64, 64, s, std::nullopt).values,
              render(plain, 64, 64, s, std::nullopt).values)
        << pattern;
  }
}

// Texture lookups counted per pixel: one per pixel and primitive when
// multisampled (the ground; the sky has no texture), one per sample when
// supersampled, the anisotropic probes counted.
TEST(Multisampling, CountsTheLookups) {
  const Scene scene = textured_board();
  Sampling s;
  s.pattern = catalog_pattern("msaa-4");
  s.shading.mode = ShadingMode::multisample;
  s.shading.texture = make_texture_filter("trilinear");
  RenderStats multi, super, aniso;
  render(scene, 64, 64, s, std::nullopt, &multi);
  s.shading.mode = ShadingMode::supersample;
  render(scene, 64, 64, s, std::nullopt, &super);
  s.shading.texture = make_texture_filter("aniso:probes=8");
  render(scene, 64, 64, s, std::nullopt, &aniso);
  EXPECT_GT(multi.lookups_per_pixel, 0.6);  // the ground's share of the pixels
  EXPECT_LE(multi.lookups_per_pixel, 1.0);
  EXPECT_NEAR(super.lookups_per_pixel, 4 * multi.lookups_per_pixel, 0.05);
  EXPECT_GT(aniso.lookups_per_pixel, super.lookups_per_pixel);
}

}  // namespace
}  // namespace aapat

namespace aapat {
namespace {

// The reference cache is keyed by the scene's canonical text: a texture
// (its texels, its period) is part of it.
TEST(TextureCoordinates, TheCacheKeyKnowsTheTexture) {
  CheckerboardScene plain;
  const Scene a = textured_board("checker:cells=8,size=256"),
              b = textured_board("checker:cells=4,size=256");
  Scene c = textured_board("checker:cells=8,size=256");
  std::get<CheckerboardScene>(c.shape).period = 4;
  const std::string untextured = canonical_text(Scene(plain));
  EXPECT_NE(canonical_text(a), canonical_text(b));
  EXPECT_NE(canonical_text(a), canonical_text(c));
  EXPECT_EQ(canonical_text(a), canonical_text(textured_board("checker:cells=8,size=256")));
  EXPECT_EQ(untextured.find("texture"), std::string::npos);
}

}  // namespace
}  // namespace aapat

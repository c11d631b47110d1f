#include "aapat/render/texture_filter.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <numeric>
#include <random>

namespace aapat {
namespace {

Texture random_texture(int w, int h, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  Texture t{"random", w, h, std::vector<double>(static_cast<size_t>(w) * h)};
  for (double& v : t.texels) v = u(rng);
  return t;
}

double mean(const Texture& t) {
  return std::accumulate(t.texels.begin(), t.texels.end(), 0.0) / double(t.texels.size());
}

// The lecture's pyramid: each level's texel is the average of its four
// children; odd sizes average the children that exist.
TEST(Mipmap, EachTexelIsTheMeanOfItsChildren) {
  for (const auto& [w, h] : {std::pair{64, 64}, std::pair{37, 21}, std::pair{1, 8}}) {
    const Mipmap m = build_mipmap(random_texture(w, h, 3), MipmapKind::box);
    EXPECT_EQ(m.levels.back().width, 1);
    EXPECT_EQ(m.levels.back().height, 1);
    for (size_t l = 1; l < m.levels.size(); ++l) {
      const Texture &fine = m.levels[l - 1], &coarse = m.levels[l];
      EXPECT_EQ(coarse.width, (fine.width + 1) / 2);
      for (int j = 0; j < coarse.height; ++j)
        for (int i = 0; i < coarse.width; ++i) {
          double sum = 0;
          int n = 0;
          for (int dj = 0; dj < 2; ++dj)
            for (int di = 0; di < 2; ++di)
              if (2 * i + di < fine.width && 2 * j + dj < fine.height)
                sum += fine.at(2 * i + di, 2 * j + dj), ++n;
          EXPECT_NEAR(coarse.at(i, j), sum / n, 1e-15) << w << "x" << h << " level " << l;
        }
    }
  }
}

// Both pyramids keep the mean of a power-of-two texture at every level (the
// binomial's taps sum to 1, and every fine texel weighs the same in all).
TEST(Mipmap, EveryLevelKeepsTheMean) {
  const Texture t = random_texture(32, 16, 9);
  for (const MipmapKind kind : {MipmapKind::box, MipmapKind::gaussian}) {
    const Mipmap m = build_mipmap(t, kind);
    for (const Texture& level : m.levels) EXPECT_NEAR(mean(level), mean(t), 1e-14);
  }
}

// The level from the Jacobian of a plane facing the viewer, c texels per
// pixel along both axes: log2 c by the max formula, log2 (c sqrt 2) by the
// root of the sum of squares.
TEST(LevelOfDetail, TheFootprintOfAPlaneFacingTheViewer) {
  for (const double c : {0.25, 1.0, 3.0, 64.0}) {
    const TextureJacobian j{c, 0, 0, c};
    EXPECT_NEAR(level_of_detail(j, LodFormula::max), std::log2(c), 1e-15);
    EXPECT_NEAR(level_of_detail(j, LodFormula::root_sum_squares), std::log2(c * std::sqrt(2.0)),
                1e-15);
  }
  // A rotated footprint of the same size: the rms formula does not see the
  // rotation, the max formula sees the larger component.
  const double c = 8, a = 0.3;
  const TextureJacobian r{c * std::cos(a), c * std::sin(a), -c * std::sin(a), c * std::cos(a)};
  EXPECT_NEAR(level_of_detail(r, LodFormula::root_sum_squares), std::log2(c * std::sqrt(2.0)),
              1e-14);
  EXPECT_NEAR(level_of_detail(r, LodFormula::max), std::log2(c * std::cos(a)), 1e-14);
}

// Trilinear lookup has no jump where the level crosses a whole number.
RC_GTEST_PROP(Trilinear, ContinuousAcrossLevelBoundaries, ()) {
  static const Mipmap m = build_mipmap(random_texture(64, 64, 5), MipmapKind::box);
  const int level = *rc::gen::inRange(1, 6);
  const double s = *rc::gen::inRange(-100000, 100000) / 997.0;
  const double t = *rc::gen::inRange(-100000, 100000) / 991.0;
  const double below = trilinear(m, level - 1e-9, s, t), above = trilinear(m, level + 1e-9, s, t);
  RC_ASSERT(std::abs(below - above) <= 1e-8);
  // And from level to level it moves by at most the texels' range, 1.
  RC_ASSERT(std::abs(trilinear(m, level - 0.5, s, t) - trilinear(m, level + 0.5, s, t)) <= 1);
}

TEST(TextureFilter, EachLookupOnKnownTexels) {
  const TexturedSurface surface(random_texture(16, 16, 7));
  const Texture& t = surface.texture;
  const TextureJacobian unit{1, 0, 0, 1};
  auto value = [&](const char* spec, double s, double v, TextureJacobian j = {1, 0, 0, 1}) {
    return filtered_value(surface, make_texture_filter(spec), s, v, j);
  };
  // At texel centres bilinear is the texel; nearest is the texel anywhere in it.
  EXPECT_NEAR(value("bilinear", 3.5, 7.5), t.at(3, 7), 1e-15);
  EXPECT_EQ(value("nearest", 3.9, 7.1), t.at(3, 7));
  EXPECT_EQ(value("nearest", 3.9 + 16, 7.1 - 32), t.at(3, 7));  // it repeats
  // Halfway between texels bilinear is their mean.
  EXPECT_NEAR(value("bilinear", 4.0, 7.5), (t.at(3, 7) + t.at(4, 7)) / 2, 1e-15);
  // A footprint of 4 texels reads level 2, whose texels average 4 x 4 of level 0.
  const TextureJacobian four{4, 0, 0, 4};
  double block = 0;
  for (int j = 4; j < 8; ++j)
    for (int i = 0; i < 4; ++i) block += t.at(i, j) / 16;
  EXPECT_NEAR(value("mip-nearest", 1.0, 5.0, four), block, 1e-15);
  EXPECT_NEAR(value("trilinear", 2.0, 6.0, four), block, 1e-15);  // level 2's texel centre
  // A round footprint: anisotropic filtering is one trilinear probe.
  int probes = 0;
  EXPECT_EQ(filtered_value(surface, make_texture_filter("aniso:probes=8"), 5.3, 2.2, unit, &probes),
            trilinear(surface.box, 0, 5.3, 2.2));
  EXPECT_EQ(probes, 1);
  // A footprint 6 times longer than wide: 6 probes (8 at most).
  probes = 0;
  filtered_value(surface, make_texture_filter("aniso:probes=8"), 5.3, 2.2, {6, 0, 0, 1}, &probes);
  EXPECT_EQ(probes, 6);
  probes = 0;
  filtered_value(surface, make_texture_filter("aniso:probes=4"), 5.3, 2.2, {60, 0, 0, 1}, &probes);
  EXPECT_EQ(probes, 4);
}

TEST(TextureFilter, SpecsAreNamedAndChecked) {
  EXPECT_EQ(make_texture_filter("aniso").name, "aniso:probes=8");
  EXPECT_THROW(make_texture_filter("aniso:probes=0"), Error);
  EXPECT_THROW(make_texture_filter("cubic"), Error);
  EXPECT_THROW(parse_lod_formula("min"), Error);
  EXPECT_THROW(parse_mipmap_kind("lanczos"), Error);
}

TEST(Texture, ProceduralTexturesAndTheirChecks) {
  const Texture c = make_texture("checker:cells=2,size=4");
  EXPECT_EQ(c.texels, (std::vector<double>{1, 1, 0, 0, 1, 1, 0, 0, 0, 0, 1, 1, 0, 0, 1, 1}));
  const Texture z = make_texture("zoneplate:size=64");
  for (double v : z.texels) EXPECT_TRUE(v >= 0 && v <= 1);
  const Texture n = make_texture("noise:size=64,seed=3");
  EXPECT_NE(n.content_hash(), make_texture("noise:size=64,seed=4").content_hash());
  EXPECT_THROW(make_texture("checker:size=100000"), Error);
  Texture bad{"bad", 2, 1, {0.5, std::nan("")}};
  EXPECT_THROW(validate(bad, "bad"), Error);
  bad.texels = {0.5, 1.5};
  EXPECT_THROW(validate(bad, "bad"), Error);
}

}  // namespace
}  // namespace aapat

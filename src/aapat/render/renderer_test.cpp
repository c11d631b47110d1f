#include "aapat/render/renderer.h"

#include <gtest/gtest.h>

#include "aapat/core/half_plane_area.h"

#include <cmath>
#include <cstring>
#include <set>

#include "aapat/core/filter_catalog.h"
#include "aapat/generate/catalog.h"
#include "aapat/render/image_error.h"
#include "aapat/render/reference.h"
#include "aapat/render/scene.h"

namespace aapat {
namespace {

// The exact area of pixel (i, j) on the white side of a half-plane scene.
double covered(const HalfPlaneScene& s, int i, int j) {
  const double a = radians(s.angle_deg);
  // Shift the pixel to the unit square [0,1]^2: p' = p - (i - 1/2, j - 1/2).
  const double t =
      s.offset + (s.origin.x - (i - 0.5)) * std::cos(a) + (s.origin.y - (j - 0.5)) * std::sin(a);
  return half_plane_area(a, t);
}

double mean_error(const Image& img, const HalfPlaneScene& s) {
  double sum = 0;
  for (int j = 0; j < img.height; ++j)
    for (int i = 0; i < img.width; ++i) sum += std::abs(img.at(i, j) - covered(s, i, j));
  return sum / (img.width * img.height);
}

// Box-filtered supersampling converges to the exact covered area.
TEST(Renderer, BoxFilteredJitterConvergesToTheCoveredArea) {
  const HalfPlaneScene edge{{7.3, 6.1}, 23, 0.2};
  double previous = INFINITY;
  for (int k : {1, 2, 4, 8, 16, 32}) {
    Sampling s;
    s.generator = "jittered";
    s.samples = k * k;
    const double e = mean_error(render(edge, 16, 16, s, make_filter("box")), edge);
    EXPECT_LT(e, previous) << k;
    previous = e;
  }
  EXPECT_LT(previous, 0.002);
}

TEST(Renderer, RegularGridWithItsOwnWeightsConverges) {
  const HalfPlaneScene edge{{7.3, 6.1}, 67, -0.4};
  Sampling s;
  s.pattern = catalog_pattern("grid-32x32");
  EXPECT_LT(mean_error(render(edge, 16, 16, s, std::nullopt), edge), 0.002);
  s.pattern = catalog_pattern("centroid");  // one sample: coverage 0 or 1
  const Image one = render(edge, 16, 16, s, std::nullopt);
  for (double v : one.values) EXPECT_TRUE(v == 0.0 || v == 1.0);
}

// The perspective checkerboard, far from the horizon: a pixel whose corners
// fall in one square is that square's colour exactly; a pixel crossed by one
// grid line is covered by the image of that line, a straight line.
TEST(Renderer, CheckerboardMatchesAnalyticCoverageFarFromTheHorizon) {
  const int w = 64, h = 64;
  const CheckerboardScene board =
      std::get<CheckerboardScene>(make_scene("checkerboard", w, h).shape);
  Sampling s;
  s.generator = "jittered";
  s.samples = 32 * 32;
  const Image img = render(board, w, h, s, make_filter("box"));
  const double f = board.focal * board.width, r = radians(board.rotation_deg);
  auto ground = [&](double x, double y) {  // (gx, gz) of an image point below the horizon
    const double z = board.eye_height / ((board.horizon * board.height - y) / f);
    const double gx0 = (x - board.width / 2) / f * z;
    return Vec2{gx0 * std::cos(r) - z * std::sin(r), gx0 * std::sin(r) + z * std::cos(r)};
  };
  int interior = 0, edges = 0;
  double edge_error = 0;
  for (int j = 0; j < h / 3; ++j)  // the bottom third: squares of several pixels
    for (int i = 0; i < w; ++i) {
      const Vec2 c[4] = {ground(i - 0.5, j - 0.5), ground(i + 0.5, j - 0.5),
                         ground(i + 0.5, j + 0.5), ground(i - 0.5, j + 0.5)};
      std::set<long long> xs, zs;
      for (const Vec2& g : c)
        xs.insert(std::llround(std::floor(g.x))), zs.insert(std::llround(std::floor(g.y)));
      if (xs.size() == 1 && zs.size() == 1) {
        EXPECT_EQ(img.at(i, j), shade(board, {double(i), double(j)})) << i << "," << j;
        ++interior;
      } else if (xs.size() + zs.size() == 3) {
        // One line gx = c (or gz = c): find where it crosses the pixel's
        // bottom and top rows, which are lines of constant depth.
        const bool along_x = xs.size() == 2;
        const double line = static_cast<double>(along_x ? *xs.rbegin() : *zs.rbegin());
        auto cross = [&](double y) {  // x where the coordinate equals `line` on row y (linear in x)
          const double a = along_x ? ground(0, y).x : ground(0, y).y;
          const double b = along_x ? ground(1, y).x : ground(1, y).y;
          return (line - a) / (b - a);
        };
        const Vec2 p0{cross(j - 0.5), j - 0.5}, p1{cross(j + 0.5), j + 0.5};
        // The half-plane (p - p0) . n <= 0 with n normal to p0 -> p1, and
        // whether that side is white (probed a quarter pixel into it).
        const double ang = std::atan2(-(p1.x - p0.x), p1.y - p0.y);
        const HalfPlaneScene side{p0, ang * 180 / kPi, 0};
        const double area = covered(side, i, j);
        // Probe the pixel's corner deepest on that side: no other line crosses the pixel.
        Vec2 probe{i - 0.5, j - 0.5};
        double deepest = INFINITY;
        for (double dx : {-0.5, 0.5})
          for (double dy : {-0.5, 0.5}) {
            const Vec2 q{i + dx, j + dy};
            const double d = (q.x - p0.x) * std::cos(ang) + (q.y - p0.y) * std::sin(ang);
            if (d < deepest) deepest = d, probe = q;
          }
        const double expected = shade(board, probe) == 1.0 ? area : 1 - area;
        edge_error += std::abs(img.at(i, j) - expected);
        EXPECT_NEAR(img.at(i, j), expected, 0.03) << i << "," << j;
        ++edges;
      }
    }
  EXPECT_GT(interior, 300);
  EXPECT_GT(edges, 100);
  EXPECT_LT(edge_error / edges, 0.005);
}

TEST(Renderer, SharedBorderSamplesAreTakenOnceAndCounted) {
  Sampling s;
  s.pattern = catalog_pattern("flipquad");
  RenderStats stats;
  const HalfPlaneScene edge{{8, 8}, 10, 0};
  render(edge, 8, 8, s, std::nullopt, &stats);
  EXPECT_EQ(stats.samples_per_pixel, 2.0);
  // With a filter, each physical sample enters once: a flat scene stays flat.
  const HalfPlaneScene all_white{{0, 0}, 0, 1e9};
  const Image img = render(all_white, 8, 8, s, make_filter("mitchell"));
  for (double v : img.values) EXPECT_NEAR(v, 1.0, 1e-12);
}

TEST(ImageError, RmseMaxDeviationAndHistogramOnTheLevelScale) {
  Image a{2, 2, 0, {0, 0.5, 1, 1}}, b{2, 2, 0, {0, 0.5, 1, 0.9}};
  const ImageError e = compare(a, b);
  const int dev = 255 - 230;  // round(255 * 0.9) = 230
  EXPECT_EQ(e.max_deviation, dev);
  EXPECT_NEAR(e.rmse, std::sqrt(dev * dev / 4.0), 1e-12);
  EXPECT_EQ(e.count[0], 3);
  EXPECT_NEAR(e.contribution[dev], dev * dev / 4.0, 1e-12);
  const auto err = error_pixels(a, b);
  EXPECT_EQ(err[0], 255);  // top-left is row 1: (0, 1) with no error
  EXPECT_EQ(err[1], 0);    // (1, 1): 10% off, black
  EXPECT_THROW(compare(a, Image{1, 1, 0, {0}}), Error);
}

// A reference renders in bands of rows, each a work item that may run on
// another process: the bands put together are the whole image, bit for bit,
// and render_reference (banded) equals the one-piece rendering.
TEST(Renderer, BandsOfRowsAreTheWholeImageBitForBit) {
  const Scene scene = make_scene("circles", 37, 29);
  Sampling s;
  s.generator = "jittered";
  s.samples = 16;
  s.seed = 77;
  for (const double offset : {0.0, 0.5}) {
    const Image whole = render(scene, 37, 29, s, make_filter("mitchell"), nullptr, offset);
    std::vector<double> joined;
    for (int j0 = 0; j0 < 29; j0 += kRenderBlockRows) {
      const Image band = render_rows(scene, 37, 29, s, make_filter("mitchell"), offset, j0,
                                     std::min(29, j0 + kRenderBlockRows));
      EXPECT_EQ(band.height, std::min(29, j0 + kRenderBlockRows) - j0);
      joined.insert(joined.end(), band.values.begin(), band.values.end());
    }
    ASSERT_EQ(joined.size(), whole.values.size());
    EXPECT_EQ(std::memcmp(joined.data(), whole.values.data(), joined.size() * sizeof(double)), 0);
    ReferenceSettings r;
    r.samples = 16;
    r.seed = 77;
    const Image reference = render_reference(scene, 37, 29, r, offset);
    EXPECT_EQ(
        std::memcmp(reference.values.data(), whole.values.data(), joined.size() * sizeof(double)),
        0);
  }
  EXPECT_THROW(render_rows(scene, 37, 29, s, make_filter("box"), 0, 3, 11),
               Error);  // not a block start
  EXPECT_THROW(render_rows(scene, 37, 29, s, make_filter("box"), 0, 8, 30),
               Error);  // past the image
}

}  // namespace
}  // namespace aapat

#include "aapat/render/thin_geometry.h"

#include <algorithm>
#include <cmath>
#include <random>

#include "aapat/core/geometry.h"
#include "aapat/core/portable_math.h"
#include "aapat/generate/unit_random.h"

namespace aapat {
namespace {

class Draw {
 public:
  explicit Draw(uint64_t seed) : rng_(seed) {}
  double uniform(double lo, double hi) { return lo + (hi - lo) * unit_double(rng_); }
  int whole(int lo, int hi) { return lo + static_cast<int>(unit_double(rng_) * (hi - lo + 1)); }
  bool chance(double p) { return unit_double(rng_) < p; }

 private:
  std::mt19937_64 rng_;
};

Vec2 along(Vec2 p, double angle, double distance) {
  return {p.x + distance * portable_cos(angle), p.y + distance * portable_sin(angle)};
}

}  // namespace

Shape bar_shape(Vec2 a, Vec2 b, double width, double grey) {
  const double dx = b.x - a.x, dy = b.y - a.y, len = std::hypot(dx, dy);
  const double nx = -dy / len * width / 2, ny = dx / len * width / 2;
  Shape s;
  s.polygon = {
      {a.x + nx, a.y + ny}, {b.x + nx, b.y + ny}, {b.x - nx, b.y - ny}, {a.x - nx, a.y - ny}};
  s.grey = grey;
  return s;
}

Scene thin_geometry(int count, uint64_t seed, int width, int height) {
  Draw d(seed);
  const double w = width, h = height, side = std::min(w, h);
  ShapesScene scene;
  const bool dark = d.chance(0.5);
  scene.background = dark ? d.uniform(0, 0.3) : d.uniform(0.7, 1);
  // A grey at least 0.35 from the background: thin features of contrast.
  const auto grey = [&] {
    return std::round((dark ? d.uniform(scene.background + 0.35, 1)
                            : d.uniform(0, scene.background - 0.35)) *
                      1000) /
           1000;
  };
  for (int i = 0; i < count; ++i) {
    const double kind = d.uniform(0, 1);
    const Vec2 at{d.uniform(0, w), d.uniform(0, h)};
    if (kind < 0.4) {  // a wire
      const double angle = d.uniform(0, kPi), length = d.uniform(side / 3, 1.5 * side);
      scene.shapes.push_back(bar_shape(along(at, angle, -length / 2), along(at, angle, length / 2),
                                       d.uniform(0.08, 1.2), grey()));
    } else if (kind < 0.65) {  // a fence
      const double angle =
          d.chance(0.5) ? d.whole(0, 3) * kPi / 2 + d.uniform(-0.087, 0.087) : d.uniform(0, kPi);
      const int bars = d.whole(3, 8);
      const double spacing = d.uniform(2, 8), length = d.uniform(side / 4, side),
                   bar_width = d.uniform(0.2, 1.5), g = grey();
      for (int k = 0; k < bars; ++k) {
        const Vec2 centre = along(at, angle + kPi / 2, (k - bars / 2.0) * spacing);
        scene.shapes.push_back(bar_shape(along(centre, angle, -length / 2),
                                         along(centre, angle, length / 2), bar_width, g));
      }
    } else if (kind < 0.85) {  // a tuft of grass
      const int blades = d.whole(5, 12);
      const double g = grey();
      for (int k = 0; k < blades; ++k) {
        const Vec2 base{at.x + d.uniform(-4, 4), at.y};
        const double angle = kPi / 2 + d.uniform(-0.5, 0.5),
                     length = d.uniform(side / 10, side / 3), half = d.uniform(0.25, 1);
        Shape s;
        s.polygon = {{base.x - half, base.y}, {base.x + half, base.y}, along(base, angle, length)};
        s.grey = g;
        scene.shapes.push_back(std::move(s));
      }
    } else {  // dots
      const int dots = d.whole(5, 20);
      const double g = grey();
      for (int k = 0; k < dots; ++k) {
        Shape s;
        s.centre = {at.x + d.uniform(-side / 8, side / 8), at.y + d.uniform(-side / 8, side / 8)};
        s.radius = d.uniform(0.15, 0.8);
        s.grey = g;
        scene.shapes.push_back(std::move(s));
      }
    }
  }
  index_shapes(scene);
  return Scene{std::move(scene)};
}

}  // namespace aapat

#include "render/scene.h"

#include <fmt/format.h>

#include <cmath>

#include "core/filter_catalog.h"
#include "core/overloaded.h"
#include "core/text.h"

namespace aapat {
namespace {

// Inside the triangle abc (either winding), edges included.
bool in_triangle(Vec2 p, Vec2 a, Vec2 b, Vec2 c) {
  auto side = [](Vec2 u, Vec2 v, Vec2 q) {
    return (v.x - u.x) * (q.y - u.y) - (v.y - u.y) * (q.x - u.x);
  };
  const double d1 = side(a, b, p), d2 = side(b, c, p), d3 = side(c, a, p);
  const bool neg = d1 < 0 || d2 < 0 || d3<0, pos = d1> 0 || d2 > 0 || d3 > 0;
  return !(neg && pos);
}

}  // namespace

double shade(const Scene& scene, Vec2 p) {
  return std::visit(
      Overloaded{
          [&](const HalfPlaneScene& s) {
            const double a = radians(s.angle_deg);
            return (p.x - s.origin.x) * std::cos(a) + (p.y - s.origin.y) * std::sin(a) <= s.offset
                       ? 1.0
                       : 0.0;
          },
          [&](const CheckerboardScene& s) {
            // A ray through the image point meets the ground plane (below the
            // horizon) at depth z = eye / drop; the squares are unit sized.
            const double f = s.focal * s.width;
            const double u = (p.x - s.width / 2) / f;
            const double drop = (s.horizon * s.height - p.y) / f;
            if (drop <= 0) return 0.75;  // sky
            const double z = s.eye_height / drop, x = u * z;
            const double r = radians(s.rotation_deg);
            const double gx = x * std::cos(r) - z * std::sin(r),
                         gz = x * std::sin(r) + z * std::cos(r);
            return (static_cast<long long>(std::floor(gx)) +
                    static_cast<long long>(std::floor(gz))) %
                               2 ==
                           0
                       ? 1.0
                       : 0.0;
          },
          [&](const CirclesScene& s) {
            // Discs on a grid of cells, radius growing from 0.3 pixel to most of a cell.
            const int cols = static_cast<int>(std::ceil(std::sqrt(double(s.count))));
            const double cw = s.width / cols, ch = s.height / cols;
            const int ci = static_cast<int>(std::floor(p.x / cw)),
                      cj = static_cast<int>(std::floor(p.y / ch));
            const int idx = cj * cols + ci;
            if (ci < 0 || cj < 0 || ci >= cols || cj >= cols || idx >= s.count) return 0.0;
            const double t = s.count > 1 ? double(idx) / (s.count - 1) : 1.0;
            const double r = 0.3 + t * (0.45 * std::min(cw, ch) - 0.3);
            return std::hypot(p.x - (ci + 0.5) * cw, p.y - (cj + 0.5) * ch) <= r ? 1.0 : 0.0;
          },
          [&](const SliverScene& s) { return in_triangle(p, s.a, s.b, s.c) ? 1.0 : 0.0; },
          [&](const SpiralScene& s) {
            const double dx = p.x - s.centre.x, dy = p.y - s.centre.y, r = std::hypot(dx, dy);
            if (r > s.max_radius) return 0.0;
            // The arm is the set where the winding phase minus the radius phase falls in [0, arm).
            const double phase = std::atan2(dy, dx) / (2 * kPi) - r * s.turns / s.max_radius;
            return phase - std::floor(phase) < s.arm ? 1.0 : 0.0;
          },
          [&](const DiscScene& s) {
            return std::hypot(p.x - s.centre.x, p.y - s.centre.y) <= s.radius ? 1.0 : 0.0;
          },
          [&](const TriangleScene& s) { return in_triangle(p, s.a, s.b, s.c) ? 1.0 : 0.0; },
          [&](const ZonePlateScene& s) {
            const double r2 =
                (p.x - s.centre.x) * (p.x - s.centre.x) + (p.y - s.centre.y) * (p.y - s.centre.y);
            return 0.5 + 0.5 * std::cos(kPi * s.k * r2);
          }},
      scene);
}

Scene make_scene(std::string_view spec, int width, int height) {
  const auto colon = spec.find(':');
  const std::string_view name = spec.substr(0, colon);
  const double w = width, h = height;
  const Vec2 centre{(w - 1) / 2, (h - 1) / 2};
  if (name == "halfplane") {
    HalfPlaneScene s{centre, 30, 0};
    if (colon != std::string_view::npos)
      for (std::string_view item : split(spec.substr(colon + 1))) {
        const auto eq = item.find('=');
        const std::string_view key = trim(item.substr(0, eq));
        if (eq == std::string_view::npos || (key != "angle" && key != "offset"))
          throw Error(fmt::format(
              "scene halfplane: unknown parameter '{}' (it takes angle, offset)", item));
        (key == "angle" ? s.angle_deg : s.offset) = parse_number(item.substr(eq + 1), "halfplane");
      }
    return s;
  }
  if (colon != std::string_view::npos)
    throw Error(fmt::format("scene {}: takes no parameters", name));
  if (name == "checkerboard") return CheckerboardScene{w, h, 0.8, 1.0, 1.0, 20};
  if (name == "circles") return CirclesScene{w, h, 16};
  if (name == "sliver")
    return SliverScene{{0.03 * w, 0.04 * h}, {0.97 * w, 0.16 * h}, {0.97 * w, 0.21 * h}};
  if (name == "spiral") return SpiralScene{centre, 6, 0.47 * std::min(w, h), 0.35};
  if (name == "zoneplate") return ZonePlateScene{centre, 1.0 / std::max(w, h)};
  std::string known;
  for (const auto& s : scene_catalog()) known += (known.empty() ? "" : ", ") + s.spec;
  throw Error(fmt::format("unknown scene '{}': known scenes are {}", name, known));
}

Scene animation_frame(std::string_view animation, int width, int height, int frame, int frames) {
  const double t = frames > 1 ? double(frame) / frames : 0.0;
  const Vec2 centre{(width - 1) / 2.0, (height - 1) / 2.0};
  const double size = std::min(width, height);
  if (animation == "circle")
    // Sub-pixel steps along a shallow diagonal: every edge angle meets every phase.
    return DiscScene{{centre.x + 5 * t - 2.5, centre.y + 2 * t - 1}, 0.3 * size};
  if (animation == "triangle") {
    const double a = 2 * kPi * t, r = 0.4 * size;
    auto corner = [&](double phase) {
      return Vec2{centre.x + r * std::cos(a + phase), centre.y + r * std::sin(a + phase)};
    };
    return TriangleScene{corner(0), corner(2.3), corner(4.1)};  // a scalene triangle
  }
  throw Error(
      fmt::format("unknown animation '{}': known animations are circle, triangle", animation));
}

const std::vector<SceneInfo>& scene_catalog() {
  static const std::vector<SceneInfo> kInfo = {
      {"checkerboard", "infinite flat-shaded checkerboard in perspective (Goss & Wu Sec. 3.1)"},
      {"circles", "white discs from 0.3 pixel to large (Laine & Aila Fig. 7)"},
      {"sliver", "a thin triangle, sub-pixel at its tip (Hasselgren Fig. 4)"},
      {"spiral", "a spiral arm (Hasselgren Fig. 5)"},
      {"zoneplate", "0.5 + 0.5 cos(pi r^2 / size): frequency grows to Nyquist at the edge"},
      {"halfplane:angle=30,offset=0", "white where (p - centre) . (cos a, sin a) <= offset"},
  };
  return kInfo;
}

}  // namespace aapat

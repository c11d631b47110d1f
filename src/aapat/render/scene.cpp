#include "aapat/render/scene.h"

#include <fmt/format.h>

#include <cmath>
#include <map>

#include "aapat/core/filter_catalog.h"
#include "aapat/core/overloaded.h"
#include "aapat/core/text.h"
#include "aapat/render/shape_index.h"

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

// `name:key=value,...` where every key is one of `allowed`; get() falls back to the default.
class SceneParameters {
 public:
  SceneParameters(std::string_view name, std::string_view spec, std::string_view allowed)
      : name_(name) {
    if (spec.empty()) return;
    for (std::string_view item : split(spec)) {
      const auto eq = item.find('=');
      const std::string key(trim(item.substr(0, eq)));
      bool known = false;
      for (std::string_view a : split(allowed)) known = known || a == key;
      if (eq == std::string_view::npos || !known)
        throw Error(
            fmt::format("scene {}: unknown parameter '{}' ({})", name, item,
                        allowed.empty() ? "it takes none" : fmt::format("it takes {}", allowed)));
      values_[key] = parse_number(item.substr(eq + 1), fmt::format("scene {}: {}", name, key));
    }
  }
  // The value of `key`, which must lie in [lo, hi].
  double get(const std::string& key, double fallback, double lo, double hi) const {
    const auto it = values_.find(key);
    const double v = it == values_.end() ? fallback : it->second;
    if (!(v >= lo && v <= hi))
      throw Error(fmt::format("scene {}: {} = {} is outside [{}, {}]", name_, key, v, lo, hi));
    return v;
  }

 private:
  std::string name_;
  std::map<std::string, double> values_;
};

}  // namespace

Vec2 View::to_scene(Vec2 q) const {
  const double r = radians(rotation_deg), c = std::cos(r), s = std::sin(r);
  const double dx = (q.x - translation.x - pivot.x) / scale,
               dy = (q.y - translation.y - pivot.y) / scale;
  return {pivot.x + c * dx + s * dy, pivot.y - s * dx + c * dy};
}

double shade(const Scene& scene, Vec2 image_point) {
  const Vec2 p = scene.view.identity() ? image_point : scene.view.to_scene(image_point);
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
            // Parity in doubles: near the horizon the squares' indices pass any integer type.
            return std::fmod(std::abs(std::floor(gx) + std::floor(gz)), 2.0) == 0 ? 1.0 : 0.0;
          },
          [&](const CirclesScene& s) {
            // Discs on a grid of cells, radius growing from 0.3 pixel to most of a cell.
            const int cols = static_cast<int>(std::ceil(std::sqrt(double(s.count))));
            const double cw = s.width / cols, ch = s.height / cols;
            const double fi = std::floor(p.x / cw), fj = std::floor(p.y / ch);
            if (!(fi >= 0 && fj >= 0 && fi < cols && fj < cols)) return 0.0;  // before any cast
            const int ci = static_cast<int>(fi), cj = static_cast<int>(fj);
            const int idx = cj * cols + ci;
            if (idx >= s.count) return 0.0;
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
          },
          [&](const ShapesScene& s) {
            if (s.index) {
              const int top = s.index->top_shape_at(s.shapes, p);
              return top < 0 ? s.background : s.shapes[top].grey;
            }
            for (auto it = s.shapes.rbegin(); it != s.shapes.rend(); ++it) {
              const bool inside = it->polygon.empty() ? std::hypot(p.x - it->centre.x,
                                                                   p.y - it->centre.y) <= it->radius
                                                      : in_polygon(p, it->polygon);
              if (inside) return it->grey;
            }
            return s.background;
          }},
      scene.shape);
}

void index_shapes(ShapesScene& scene) {
  scene.index = std::make_shared<const ShapeIndex>(scene.shapes);
}

Scene make_scene(std::string_view spec, int width, int height) {
  const auto colon = spec.find(':');
  const std::string_view name = spec.substr(0, colon);
  const std::string_view rest = colon == std::string_view::npos ? "" : spec.substr(colon + 1);
  const double w = width, h = height, side = std::min(w, h);
  const Vec2 centre{(w - 1) / 2, (h - 1) / 2};
  for (const SceneInfo& info : scene_catalog()) {
    if (info.name != name) continue;
    const SceneParameters q(name, rest, info.parameters);
    if (name == "halfplane")
      return HalfPlaneScene{centre, q.get("angle", 30, -360, 360), q.get("offset", 0, -1e6, 1e6)};
    if (name == "checkerboard")
      return CheckerboardScene{w,
                               h,
                               q.get("horizon", 0.8, 0.05, 2),
                               q.get("focal", 1, 0.01, 100),
                               q.get("eye", 1, 0.01, 1000),
                               q.get("rotation", 20, -360, 360)};
    if (name == "circles") return CirclesScene{w, h, static_cast<int>(q.get("count", 16, 1, 4096))};
    if (name == "sliver")
      return SliverScene{{0.03 * w, 0.04 * h}, {0.97 * w, 0.16 * h}, {0.97 * w, 0.21 * h}};
    if (name == "spiral")
      return SpiralScene{centre, q.get("turns", 6, 0.01, 1000), 0.47 * side,
                         q.get("arm", 0.35, 0.01, 0.99)};
    if (name == "zoneplate")
      return ZonePlateScene{centre, q.get("k", 1, 1e-6, 1e6) / std::max(w, h)};
    if (name == "disc") return DiscScene{centre, q.get("radius", 0.3, 1e-6, 10) * side};
  }
  std::string known;
  for (const auto& s : scene_catalog()) known += (known.empty() ? "" : ", ") + s.name;
  throw Error(
      fmt::format("unknown scene '{}': known scenes are {} (or a .json scene file)", name, known));
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
      {"checkerboard", "horizon,focal,eye,rotation",
       "infinite flat-shaded checkerboard in perspective (Goss & Wu Sec. 3.1); horizon row as a "
       "fraction of the height (0.8), focal length in widths (1), eye height in squares (1), "
       "rotation in degrees (20)"},
      {"circles", "count", "white discs from 0.3 pixel to large (Laine & Aila Fig. 7); count (16)"},
      {"sliver", "", "a thin triangle, sub-pixel at its tip (Hasselgren Fig. 4)"},
      {"spiral", "turns,arm", "a spiral arm (Hasselgren Fig. 5); turns (6), white fraction (0.35)"},
      {"zoneplate", "k",
       "0.5 + 0.5 cos(pi k r^2 / size): k = 1 reaches Nyquist at the edge (k = 1)"},
      {"disc", "radius", "a white disc; radius as a fraction of the smaller side (0.3)"},
      {"halfplane", "angle,offset",
       "white where (p - centre) . (cos a, sin a) <= offset; angle (30), offset (0)"},
  };
  return kInfo;
}

std::string canonical_text(const Scene& scene) {
  std::string t;
  auto num = [&](double v) { t += fmt::format("{:.17g} ", v); };
  auto pt = [&](Vec2 v) {
    num(v.x);
    num(v.y);
  };
  t += fmt::format("kind {} view ", scene.shape.index());
  pt(scene.view.pivot);
  num(scene.view.rotation_deg);
  num(scene.view.scale);
  pt(scene.view.translation);
  t += "scene ";
  std::visit(
      Overloaded{
          [&](const HalfPlaneScene& s) {
            pt(s.origin);
            num(s.angle_deg);
            num(s.offset);
          },
          [&](const CheckerboardScene& s) {
            for (double v : {s.width, s.height, s.horizon, s.focal, s.eye_height, s.rotation_deg})
              num(v);
          },
          [&](const CirclesScene& s) {
            num(s.width);
            num(s.height);
            num(s.count);
          },
          [&](const SliverScene& s) {
            for (Vec2 v : {s.a, s.b, s.c}) pt(v);
          },
          [&](const SpiralScene& s) {
            pt(s.centre);
            for (double v : {s.turns, s.max_radius, s.arm}) num(v);
          },
          [&](const ZonePlateScene& s) {
            pt(s.centre);
            num(s.k);
          },
          [&](const DiscScene& s) {
            pt(s.centre);
            num(s.radius);
          },
          [&](const TriangleScene& s) {
            for (Vec2 v : {s.a, s.b, s.c}) pt(v);
          },
          [&](const ShapesScene& s) {
            num(s.background);
            for (const Shape& sh : s.shapes) {
              t += sh.polygon.empty() ? "circle " : "polygon ";
              for (Vec2 v : sh.polygon) pt(v);
              pt(sh.centre);
              num(sh.radius);
              num(sh.grey);
            }
          }},
      scene.shape);
  return t;
}

}  // namespace aapat

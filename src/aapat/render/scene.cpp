#include "aapat/render/scene.h"

#include <fmt/format.h>

#include <cmath>
#include <map>
#include <random>

#include "aapat/core/filter_catalog.h"
#include "aapat/core/overloaded.h"
#include "aapat/core/text.h"
#include "aapat/generate/unit_random.h"
#include "aapat/render/mesh.h"
#include "aapat/render/shape_index.h"
#include "aapat/render/surface.h"
#include "aapat/render/texture_filter.h"
#include "aapat/render/thin_geometry.h"

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

View::Inverse View::inverse() const {
  const double r = radians(rotation_deg);
  return {pivot, translation, scale, std::cos(r), std::sin(r)};
}

Vec2 View::to_scene(Vec2 q) const {
  return inverse()(q);
}

namespace {

// The grey level of each analytic scene kind: shader_of(scene) is a function
// of the scene point, with what does not depend on the point (the cosines of
// a rotation, say) computed once, before a batch of points.
auto shader_of(const HalfPlaneScene& s) {
  const double a = radians(s.angle_deg), c = std::cos(a), sn = std::sin(a);
  return [&s, c, sn](Vec2 p) {
    return (p.x - s.origin.x) * c + (p.y - s.origin.y) * sn <= s.offset ? 1.0 : 0.0;
  };
}
auto shader_of(const CheckerboardScene& s) {
  const double r = radians(s.rotation_deg), c = std::cos(r), sn = std::sin(r);
  return [&s, c, sn](Vec2 p) {
    // A ray through the image point meets the ground plane (below the
    // horizon) at depth z = eye / drop; the squares are unit sized.
    const double f = s.focal * s.width;
    const double u = (p.x - s.width / 2) / f;
    const double drop = (s.horizon * s.height - p.y) / f;
    if (drop <= 0) return 0.75;  // sky
    const double z = s.eye_height / drop, x = u * z;
    const double gx = x * c - z * sn, gz = x * sn + z * c;
    // Parity in doubles: near the horizon the squares' indices pass any integer type.
    return std::fmod(std::abs(std::floor(gx) + std::floor(gz)), 2.0) == 0 ? 1.0 : 0.0;
  };
}
auto shader_of(const CirclesScene& s) {
  // Discs on a grid of cells, radius growing from 0.3 pixel to most of a cell.
  const int cols = static_cast<int>(std::ceil(std::sqrt(double(s.count))));
  const double cw = s.width / cols, ch = s.height / cols;
  return [&s, cols, cw, ch](Vec2 p) {
    const double fi = std::floor(p.x / cw), fj = std::floor(p.y / ch);
    if (!(fi >= 0 && fj >= 0 && fi < cols && fj < cols)) return 0.0;  // before any cast
    const int ci = static_cast<int>(fi), cj = static_cast<int>(fj);
    const int idx = cj * cols + ci;
    if (idx >= s.count) return 0.0;
    const double t = s.count > 1 ? double(idx) / (s.count - 1) : 1.0;
    const double r = 0.3 + t * (0.45 * std::min(cw, ch) - 0.3);
    return vector_length(p.x - (ci + 0.5) * cw, p.y - (cj + 0.5) * ch) <= r ? 1.0 : 0.0;
  };
}
auto shader_of(const SliverScene& s) {
  return [&s](Vec2 p) { return in_triangle(p, s.a, s.b, s.c) ? 1.0 : 0.0; };
}
auto shader_of(const SpiralScene& s) {
  return [&s](Vec2 p) {
    const double dx = p.x - s.centre.x, dy = p.y - s.centre.y, r = vector_length(dx, dy);
    if (r > s.max_radius) return 0.0;
    // The arm is the set where the winding phase minus the radius phase falls in [0, arm).
    const double phase = std::atan2(dy, dx) / (2 * kPi) - r * s.turns / s.max_radius;
    return phase - std::floor(phase) < s.arm ? 1.0 : 0.0;
  };
}
auto shader_of(const DiscScene& s) {
  return [&s](Vec2 p) {
    return vector_length(p.x - s.centre.x, p.y - s.centre.y) <= s.radius ? 1.0 : 0.0;
  };
}
auto shader_of(const TriangleScene& s) {
  return [&s](Vec2 p) { return in_triangle(p, s.a, s.b, s.c) ? 1.0 : 0.0; };
}
auto shader_of(const ZonePlateScene& s) {
  return [&s](Vec2 p) {
    const double r2 =
        (p.x - s.centre.x) * (p.x - s.centre.x) + (p.y - s.centre.y) * (p.y - s.centre.y);
    return 0.5 + 0.5 * std::cos(kPi * s.k * r2);
  };
}
auto shader_of(const ShapesScene& s) {
  return [&s](Vec2 p) {
    const int top = top_shape_at(s, p);
    return top < 0 ? s.background : s.shapes[static_cast<size_t>(top)].grey;
  };
}
auto shader_of(const MeshScene&) {
  return [](Vec2) { return 0.0; };  // shaded per primitive
}

// Shaded primitive by primitive (shade_primitive), not by the shape alone.
bool shaded_per_primitive(const Scene& scene) {
  return has_texture(scene) || std::holds_alternative<MeshScene>(scene.shape);
}

}  // namespace

double shade(const Scene& scene, Vec2 image_point) {
  if (shaded_per_primitive(scene)) {
    // The exact texel of a textured primitive, the grey of the others.
    static const TextureFilter kExact;
    return shade_primitive(scene, primitive_at(scene, image_point), image_point, kExact);
  }
  const Vec2 p = scene.view.identity() ? image_point : scene.view.to_scene(image_point);
  return std::visit([&](const auto& s) { return shader_of(s)(p); }, scene.shape);
}

void shade_points(const Scene& scene, const Vec2* points, size_t n, double* out) {
  if (shaded_per_primitive(scene)) {
    for (size_t k = 0; k < n; ++k) out[k] = shade(scene, points[k]);
    return;
  }
  const bool identity = scene.view.identity();
  std::visit(
      [&](const auto& s) {
        const auto shader = shader_of(s);
        if (identity) {
          for (size_t k = 0; k < n; ++k) out[k] = shader(points[k]);
        } else {
          const View::Inverse to_scene = scene.view.inverse();
          for (size_t k = 0; k < n; ++k) out[k] = shader(to_scene(points[k]));
        }
      },
      scene.shape);
}

void index_shapes(ShapesScene& scene) {
  scene.index = std::make_shared<const ShapeIndex>(scene.shapes);
  scene.textured = false;
  for (const Shape& s : scene.shapes) scene.textured = scene.textured || s.texture != nullptr;
}

namespace {

// Where a scene of a width x height image is centred and how large it is.
struct Frame {
  double w, h, side;
  Vec2 centre;
};
Frame frame_of(int width, int height) {
  const double w = width, h = height;
  return {w, h, std::min(w, h), {(w - 1) / 2, (h - 1) / 2}};
}

}  // namespace

Scene random_shapes(int count, uint64_t seed, int width, int height) {
  // mt19937_64's raw draws and aapat's own mapping to [0, 1) (unit_random.h),
  // not the standard distributions, whose output differs between standard
  // libraries: the same scene natively and in WebAssembly.
  std::mt19937_64 rng(seed);
  const auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * unit_double(rng); };
  const auto grey = [&] { return std::round(unit_double(rng) * 1000) / 1000; };
  const double w = width, h = height, side = std::min(w, h);
  ShapesScene scene;
  scene.background = grey();
  for (int i = 0; i < count; ++i) {
    Shape shape;
    if (unit_double(rng) < 0.5) {
      const double cx = uniform(0, w), cy = uniform(0, h), r = uniform(side / 8, side / 2);
      const int corners = 3 + static_cast<int>(unit_double(rng) * 4);  // 3 to 6
      for (int k = 0; k < corners; ++k)
        shape.polygon.push_back({cx + uniform(-r, r), cy + uniform(-r, r)});
    } else {
      shape.centre = {uniform(0, w), uniform(0, h)};
      shape.radius = uniform(side / 20, side / 4);
    }
    shape.grey = grey();
    scene.shapes.push_back(std::move(shape));
  }
  index_shapes(scene);
  return Scene{std::move(scene)};
}

const SceneRegistry& scene_registry() {
  static const SceneRegistry kRegistry(
      "scene",
      {{{"checkerboard",
         "infinite flat-shaded checkerboard in perspective",
         "Goss & Wu 2000, Sec. 3.1",
         {{"horizon", "0.8", "horizon row as a fraction of the height"},
          {"focal", "1", "focal length in image widths"},
          {"eye", "1", "eye height in squares"},
          {"rotation", "20", "rotation of the board in degrees"},
          {"period", "8", "with --texture: squares per repeat of the texture on the ground"}}},
        [](const Spec& s, int width, int height) -> Scene {
          const Frame f = frame_of(width, height);
          return CheckerboardScene{f.w,
                                   f.h,
                                   s.in_range("horizon", 0.05, 2),
                                   s.in_range("focal", 0.01, 100),
                                   s.in_range("eye", 0.01, 1000),
                                   s.in_range("rotation", -360, 360),
                                   nullptr,
                                   s.in_range("period", 1e-3, 1e6)};
        }},
       {{"circles",
         "white discs from 0.3 pixel to large",
         "Laine & Aila 2006, Fig. 7",
         {{"count", "16", "discs"}}},
        [](const Spec& s, int width, int height) -> Scene {
          const Frame f = frame_of(width, height);
          return CirclesScene{f.w, f.h, s.whole("count", 1, 4096)};
        }},
       {{"sliver", "a thin triangle, sub-pixel at its tip", "Hasselgren et al. 2005, Fig. 4", {}},
        [](const Spec&, int width, int height) -> Scene {
          const Frame f = frame_of(width, height);
          return SliverScene{
              {0.03 * f.w, 0.04 * f.h}, {0.97 * f.w, 0.16 * f.h}, {0.97 * f.w, 0.21 * f.h}};
        }},
       {{"spiral",
         "a white spiral arm on black",
         "Hasselgren et al. 2005, Fig. 5",
         {{"turns", "6", "turns of the arm"}, {"arm", "0.35", "white fraction of a turn"}}},
        [](const Spec& s, int width, int height) -> Scene {
          const Frame f = frame_of(width, height);
          return SpiralScene{f.centre, s.in_range("turns", 0.01, 1000), 0.47 * f.side,
                             s.in_range("arm", 0.01, 0.99)};
        }},
       {{"zoneplate",
         "0.5 + 0.5 cos(pi k r^2 / size): k = 1 reaches Nyquist at the edge",
         "aapat: the classic zone plate",
         {{"k", "1", "frequency scale"}}},
        [](const Spec& s, int width, int height) -> Scene {
          const Frame f = frame_of(width, height);
          return ZonePlateScene{f.centre, s.in_range("k", 1e-6, 1e6) / std::max(f.w, f.h)};
        }},
       {{"disc",
         "a white disc",
         "Hasselgren et al. 2005, Sec. 6.1",
         {{"radius", "0.3", "radius as a fraction of the smaller side"}}},
        [](const Spec& s, int width, int height) -> Scene {
          const Frame f = frame_of(width, height);
          return DiscScene{f.centre, s.in_range("radius", 1e-6, 10) * f.side};
        }},
       {{"random-shapes",
         "count random polygons and circles in random greys over a random background, the same "
         "for the same seed on every platform: unseen scenes for studies",
         "aapat: generated test content",
         {{"count", "6", "shapes, 1 to 4096"}, {"seed", "1", "random seed"}}},
        [](const Spec& s, int width, int height) -> Scene {
          return random_shapes(s.whole("count", 1, 4096),
                               static_cast<uint64_t>(s.whole("seed", 0, 2147483647)), width,
                               height);
        }},
       {{"thin-geometry",
         "count thin features (wires, fences, tufts of grass, dots) in greys that contrast with "
         "a dark or light background, the same for the same seed on every platform: unseen thin "
         "content for studies",
         "aapat: generated test content (render/thin_geometry.h)",
         {{"count", "12", "features, 1 to 4096"}, {"seed", "1", "random seed"}}},
        [](const Spec& s, int width, int height) -> Scene {
          return thin_geometry(s.whole("count", 1, 4096),
                               static_cast<uint64_t>(s.whole("seed", 0, 2147483647)), width,
                               height);
        }},
       {{"halfplane",
         "white where (p - centre) . (cos a, sin a) <= offset",
         "aapat: one straight edge",
         {{"angle", "30", "edge normal in degrees"}, {"offset", "0", "distance from the centre"}}},
        [](const Spec& s, int width, int height) -> Scene {
          const Frame f = frame_of(width, height);
          return HalfPlaneScene{f.centre, s.in_range("angle", -360, 360),
                                s.in_range("offset", -1e6, 1e6)};
        }}});
  return kRegistry;
}

Scene make_scene(std::string_view spec, int width, int height) {
  const SceneRegistry& registry = scene_registry();
  if (!registry.contains(spec))
    throw Error(fmt::format("unknown scene '{}': known scenes are {} (or a .json scene file)",
                            split_spec(spec).first, registry.names()));
  return registry.make(spec, width, height);
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

std::vector<std::string> scene_warnings(const Scene& scene) {
  std::vector<std::string> out;
  if (const auto* mesh = std::get_if<MeshScene>(&scene.shape))
    for (const std::string& w : mesh->view->mesh().warnings)
      out.push_back(fmt::format("model '{}': {}", mesh->view->mesh().name, w));
  return out;
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
            if (s.texture) {
              t += fmt::format("texture {:016x} ", s.texture->texture.content_hash());
              num(s.period);
            }
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
              if (sh.texture) {
                t += fmt::format("texture {:016x} ", sh.texture->texture.content_hash());
                for (Vec2 v : sh.uv) pt(v);
                for (double w : sh.w) num(w);
              }
            }
          },
          // The channel is not part of it: a mesh scene renders all three.
          [&](const MeshScene& s) { t += s.view->key(); }},
      scene.shape);
  return t;
}

}  // namespace aapat

#include "aapat/render/motion.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <optional>

#include "aapat/core/geometry.h"
#include "aapat/render/mesh.h"

namespace aapat {
namespace {

// q = A p + t with A = [a -b; b a] (a similarity): a view, a motion step.
struct Similarity {
  double a = 1, b = 0;
  Vec2 t{0, 0};
  Vec2 apply(Vec2 p) const { return {a * p.x - b * p.y + t.x, b * p.x + a * p.y + t.y}; }
};

Similarity of_view(const View& v) {
  const double r = radians(v.rotation_deg);
  Similarity s{v.scale * std::cos(r), v.scale * std::sin(r), {0, 0}};
  const Vec2 ap = s.apply(v.pivot);
  s.t = {v.pivot.x + v.translation.x - ap.x, v.pivot.y + v.translation.y - ap.y};
  return s;
}

// `steps` steps of the motion (negative: backwards).
Similarity of_motion(const Motion& m, double steps) {
  const double r = radians(m.degrees * steps);
  Similarity s{std::cos(r), std::sin(r), {0, 0}};
  const Vec2 rc = s.apply(m.centre);
  s.t = {m.centre.x - rc.x + steps * m.pan.x, m.centre.y - rc.y + steps * m.pan.y};
  return s;
}

Similarity compose(const Similarity& outer, const Similarity& inner) {
  Similarity s{outer.a * inner.a - outer.b * inner.b, outer.a * inner.b + outer.b * inner.a, {}};
  s.t = outer.apply(inner.t);
  return s;
}

}  // namespace

const MotionRegistry& motion_registry() {
  static const MotionRegistry kRegistry(
      "motion",
      {{{"static", "no motion: frame 0's scene every frame", "aapat", {}},
        [](const Spec& s, int, int) {
          Motion m;
          m.spec = s.canonical();
          return m;
        }},
       {{"pan",
         "the image moves by (dx, dy) display pixels per frame",
         "aapat",
         {{"dx", "0.5", "pixels per frame in x"}, {"dy", "0.25", "pixels per frame in y"}}},
        [](const Spec& s, int, int) {
          Motion m;
          m.pan = {s.in_range("dx", -1e4, 1e4), s.in_range("dy", -1e4, 1e4)};
          m.spec = s.canonical();
          return m;
        }},
       {{"rotate",
         "the image turns by deg degrees per frame about (cx, cy)",
         "aapat",
         {{"deg", "1", "degrees per frame"},
          {"cx", "", "centre x (default: the image centre)"},
          {"cy", "", "centre y (default: the image centre)"}}},
        [](const Spec& s, int width, int height) {
          Motion m;
          m.degrees = s.in_range("deg", -180, 180);
          m.centre = {s.optional_number("cx").value_or((width - 1) / 2.0),
                      s.optional_number("cy").value_or((height - 1) / 2.0)};
          if (!std::isfinite(m.centre.x) || !std::isfinite(m.centre.y) ||
              std::abs(m.centre.x) > 1e6 || std::abs(m.centre.y) > 1e6)
            throw ParameterError("motion rotate", ": cx and cy must be finite, within 1e6");
          m.spec = s.canonical();
          return m;
        }},
       {{"orbit",
         "a mesh scene's camera turns deg degrees per frame about its target, around its up axis",
         "aapat",
         {{"deg", "0.5", "degrees per frame"}}},
        [](const Spec& s, int, int) {
          Motion m;
          m.orbit_deg = s.in_range("deg", -45, 45);
          m.spec = s.canonical();
          return m;
        }}});
  return kRegistry;
}

Motion make_motion(std::string_view spec, int width, int height) {
  const MotionRegistry& registry = motion_registry();
  if (!registry.contains(spec)) registry.unknown(split_spec(spec).first);
  Motion m = registry.make(spec, width, height);
  // The largest step of any image point: the corners are the farthest from
  // any centre of rotation, and a pan moves every point alike.
  const Similarity step = of_motion(m, 1);
  double largest = 0;
  for (const Vec2 c : {Vec2{-0.5, -0.5}, Vec2{width - 0.5, -0.5}, Vec2{-0.5, height - 0.5},
                       Vec2{width - 0.5, height - 0.5}}) {
    const Vec2 d = step.apply(c) - c;
    largest = std::max(largest, std::hypot(d.x, d.y));
  }
  const double limit = kMaxMotionPerFrame * std::min(width, height);
  if (!(largest < limit))
    throw ParameterError(
        "motion", fmt::format(" '{}': moves a point {:.4g} pixels per frame, at least half the "
                              "{}x{} image ({:.4g}): no pixel keeps its history",
                              spec, largest, width, height, limit));
  return m;
}

namespace {

// The mesh scene with its camera turned `degrees` about its target (Rodrigues).
Scene orbited(const Scene& scene, double degrees) {
  const auto* mesh = std::get_if<MeshScene>(&scene.shape);
  if (!mesh)
    throw Error(
        "motion orbit turns a mesh scene's camera: give a mesh scene file (or pan, "
        "rotate for any scene)");
  const MeshView& v = *mesh->view;
  MeshCamera c = v.camera();
  const double len = std::sqrt(dot(c.up, c.up));
  const Vec3 k = (1 / len) * c.up, d = c.eye - c.target;
  const double a = radians(degrees), cs = std::cos(a), sn = std::sin(a);
  c.eye = c.target + (cs * d + sn * cross(k, d) + (1 - cs) * dot(k, d) * k);
  Scene out = scene;
  out.shape =
      MeshScene{make_mesh_view(v.mesh_ptr(), c, v.light(), v.width(), v.height()), mesh->channel};
  return out;
}

}  // namespace

Scene moved_scene(const Scene& scene, const Motion& motion, int frame) {
  if (!motion.moving() || frame == 0) return scene;
  if (motion.orbit_deg != 0) return orbited(scene, motion.orbit_deg * frame);
  const Similarity s = compose(of_motion(motion, frame), of_view(scene.view));
  Scene moved = scene;
  moved.view = View{{0, 0}, std::atan2(s.b, s.a) * 180 / kPi, std::hypot(s.a, s.b), s.t};
  return moved;
}

Vec2 previous_point(const Motion& motion, Vec2 p) {
  if (!motion.moving()) return p;
  return of_motion(motion, -1).apply(p);
}

Vec2 previous_point(const Motion& motion, const Scene& now, const Scene& before, Vec2 p) {
  if (motion.orbit_deg == 0) return previous_point(motion, p);
  const auto* a = std::get_if<MeshScene>(&now.shape);
  const auto* b = std::get_if<MeshScene>(&before.shape);
  if (!a || !b) throw Error("motion orbit: the scenes are not meshes");
  const std::optional<Vec3> x = a->view->surface_point(p);
  if (!x) return p;  // the background: uniform, any history of it is the same
  const std::optional<Vec2> q = b->view->project(*x);
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  if (!q) return {kNaN, kNaN};
  // Visible then? The earlier camera's surface point there must be this one.
  const std::optional<Vec3> y = b->view->surface_point(*q);
  const Vec3 eye = b->view->camera().eye, gap = y ? *y - *x : Vec3{1e300, 0, 0};
  const Vec3 to_eye = *x - eye;
  if (!y || dot(gap, gap) > 1e-6 * dot(to_eye, to_eye)) return {kNaN, kNaN};
  return *q;
}

}  // namespace aapat

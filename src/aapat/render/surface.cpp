#include "aapat/render/surface.h"

#include <algorithm>
#include <cmath>

#include "aapat/render/mesh.h"
#include "aapat/render/shape_index.h"

#include "aapat/core/overloaded.h"

namespace aapat {
namespace {

// A function's derivatives in scene coordinates, carried to image
// coordinates through the view (scene = pivot + R (image - translation -
// pivot) / scale).
void to_image(const View& v, double& d_dx, double& d_dy) {
  if (v.identity()) return;
  const double r = radians(v.rotation_deg), c = std::cos(r), s = std::sin(r);
  const double gx = d_dx, gy = d_dy;
  d_dx = (gx * c - gy * s) / v.scale;
  d_dy = (gx * s + gy * c) / v.scale;
}

// Where the checkerboard's camera ray through scene point p meets the
// ground, in squares, and the derivatives of (gx, gz) by p; none in the sky.
struct GroundPoint {
  double gx, gz, dgx_dx, dgx_dy, dgz_dx, dgz_dy;
};
std::optional<GroundPoint> ground_point(const CheckerboardScene& s, Vec2 p) {
  const double f = s.focal * s.width;
  const double u = (p.x - s.width / 2) / f;
  const double drop = (s.horizon * s.height - p.y) / f;
  if (drop <= 0) return std::nullopt;
  const double z = s.eye_height / drop, x = u * z;
  const double dz_dy = s.eye_height / (drop * drop * f);  // dz/dx = 0
  const double dx_dx = z / f, dx_dy = u * dz_dy;
  const double r = radians(s.rotation_deg), c = std::cos(r), sn = std::sin(r);
  return GroundPoint{x * c - z * sn,         x * sn + z * c, c * dx_dx,
                     c * dx_dy - sn * dz_dy, sn * dx_dx,     sn * dx_dy + c * dz_dy};
}

// A textured polygon's (u, v) at scene point p and their derivatives by p:
// the fan triangle (0, k, k+1) that holds p (or comes nearest), its
// barycentric coordinates l_i, and u = sum(l_i u_i / w_i) / sum(l_i / w_i).
struct Interpolated {
  double u, v, du_dx, du_dy, dv_dx, dv_dy;
};
Interpolated interpolate(const Shape& shape, Vec2 p) {
  const std::vector<Vec2>& P = shape.polygon;
  size_t best = 1;
  double best_margin = -INFINITY;
  double l[3] = {1, 0, 0}, grad[3][2] = {{0, 0}, {0, 0}, {0, 0}};
  for (size_t k = 1; k + 1 < P.size(); ++k) {
    const Vec2 a = P[0], b = P[k], c = P[k + 1];
    const double den = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    if (den == 0) continue;
    const double beta = ((p.x - a.x) * (c.y - a.y) - (p.y - a.y) * (c.x - a.x)) / den;
    const double gamma = ((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x)) / den;
    const double margin = std::min({1 - beta - gamma, beta, gamma});
    if (margin > best_margin) {
      best_margin = margin;
      best = k;
      l[0] = 1 - beta - gamma;
      l[1] = beta;
      l[2] = gamma;
      grad[1][0] = (c.y - a.y) / den;
      grad[1][1] = -(c.x - a.x) / den;
      grad[2][0] = -(b.y - a.y) / den;
      grad[2][1] = (b.x - a.x) / den;
      grad[0][0] = -grad[1][0] - grad[2][0];
      grad[0][1] = -grad[1][1] - grad[2][1];
    }
    if (margin >= 0) break;
  }
  const size_t vertex[3] = {0, best, best + 1};
  double nu = 0, nv = 0, d = 0, dnu[2] = {0, 0}, dnv[2] = {0, 0}, dd[2] = {0, 0};
  for (int i = 0; i < 3; ++i) {
    const double inv_w = 1 / shape.w[vertex[i]];
    const Vec2 uv = shape.uv[vertex[i]];
    nu += l[i] * uv.x * inv_w;
    nv += l[i] * uv.y * inv_w;
    d += l[i] * inv_w;
    for (int a = 0; a < 2; ++a) {
      dnu[a] += grad[i][a] * uv.x * inv_w;
      dnv[a] += grad[i][a] * uv.y * inv_w;
      dd[a] += grad[i][a] * inv_w;
    }
  }
  auto derivative = [&](double n, const double* dn, int a) {
    return (dn[a] * d - n * dd[a]) / (d * d);
  };
  return {nu / d,
          nv / d,
          derivative(nu, dnu, 0),
          derivative(nu, dnu, 1),
          derivative(nv, dnv, 0),
          derivative(nv, dnv, 1)};
}

// A mesh triangle's texture coordinates (in repeats) and their derivatives
// by image x and y, from its vertices' perspective-correct weights.
Interpolated mesh_uv(const MeshView& view, int triangle, Vec2 p) {
  const MeshView::Weights w = view.weights(triangle, p);
  const auto& tri = view.mesh().triangles[view.triangles()[static_cast<size_t>(triangle)].source];
  Interpolated out{};
  for (int m = 0; m < 3; ++m) {
    const Vec2 uv = view.mesh().uv[tri[m]];
    out.u += w.w[m] * uv.x;
    out.v += w.w[m] * uv.y;
    out.du_dx += w.dx[m] * uv.x;
    out.du_dy += w.dy[m] * uv.x;
    out.dv_dx += w.dx[m] * uv.y;
    out.dv_dy += w.dy[m] * uv.y;
  }
  return out;
}

const TexturedSurface* texture_of(const Scene& scene, int primitive) {
  if (const auto* board = std::get_if<CheckerboardScene>(&scene.shape))
    return primitive == 1 ? board->texture.get() : nullptr;
  if (const auto* shapes = std::get_if<ShapesScene>(&scene.shape))
    return primitive >= 1 && static_cast<size_t>(primitive) <= shapes->shapes.size()
               ? shapes->shapes[static_cast<size_t>(primitive - 1)].texture.get()
               : nullptr;
  if (const auto* mesh = std::get_if<MeshScene>(&scene.shape))
    return primitive >= 1 && !mesh->view->mesh().uv.empty()
               ? mesh->view->material(primitive - 1)
                     .texture[static_cast<size_t>(mesh->channel)]
                     .get()
               : nullptr;
  return nullptr;
}

// A mesh's colour at p on `primitive`: the material's base times the vertex
// colour times the texture, times the triangle's light.
Rgb shade_mesh(const Scene& scene, const MeshScene& mesh, int primitive, Vec2 image_point,
               const TextureFilter& filter, double footprint, int* lookups);

}  // namespace

int top_shape_at(const ShapesScene& s, Vec2 p) {
  if (s.index) return s.index->top_shape_at(s.shapes, p);
  for (size_t k = s.shapes.size(); k-- > 0;) {
    const Shape& sh = s.shapes[k];
    const bool inside = sh.polygon.empty()
                            ? vector_length(p.x - sh.centre.x, p.y - sh.centre.y) <= sh.radius
                            : in_polygon(p, sh.polygon);
    if (inside) return static_cast<int>(k);
  }
  return -1;
}

int primitive_at(const Scene& scene, Vec2 image_point) {
  if (const auto* mesh = std::get_if<MeshScene>(&scene.shape)) {
    const Vec2 p = scene.view.identity() ? image_point : scene.view.to_scene(image_point);
    return mesh->view->hit(p).triangle + 1;
  }
  if (const auto* board = std::get_if<CheckerboardScene>(&scene.shape)) {
    const Vec2 p = scene.view.identity() ? image_point : scene.view.to_scene(image_point);
    if (board->texture) return ground_point(*board, p) ? 1 : 0;
    const double v = shade(scene, image_point);
    return v == 1.0 ? 1 : v == 0.0 ? 2 : 0;
  }
  if (const auto* shapes = std::get_if<ShapesScene>(&scene.shape)) {
    const Vec2 p = scene.view.identity() ? image_point : scene.view.to_scene(image_point);
    return top_shape_at(*shapes, p) + 1;
  }
  if (std::holds_alternative<ZonePlateScene>(scene.shape)) return 1;
  return shade(scene, image_point) == 1.0 ? 1 : 0;  // the flat scenes: white or black
}

std::optional<TextureCoordinates> texture_coordinates(const Scene& scene, int primitive,
                                                      Vec2 image_point) {
  const TexturedSurface* surface = texture_of(scene, primitive);
  if (!surface) return std::nullopt;
  const Vec2 p = scene.view.identity() ? image_point : scene.view.to_scene(image_point);
  const double w = surface->texture.width, h = surface->texture.height;
  TextureCoordinates c;
  if (const auto* board = std::get_if<CheckerboardScene>(&scene.shape)) {
    const auto g = ground_point(*board, p);
    if (!g) return std::nullopt;  // a sample in the sky shaded as ground (multisampling's centre)
    const double ks = w / board->period, kt = h / board->period;
    c = {g->gx * ks, g->gz * kt, {g->dgx_dx * ks, g->dgz_dx * kt, g->dgx_dy * ks, g->dgz_dy * kt}};
  } else {
    const auto* mesh = std::get_if<MeshScene>(&scene.shape);
    const Interpolated i =
        mesh
            ? mesh_uv(*mesh->view, primitive - 1, p)
            : interpolate(
                  std::get<ShapesScene>(scene.shape).shapes[static_cast<size_t>(primitive - 1)], p);
    c = {i.u * w, i.v * h, {i.du_dx * w, i.dv_dx * h, i.du_dy * w, i.dv_dy * h}};
  }
  to_image(scene.view, c.j.dsdx, c.j.dsdy);
  to_image(scene.view, c.j.dtdx, c.j.dtdy);
  return c;
}

double shade_primitive(const Scene& scene, int primitive, Vec2 image_point,
                       const TextureFilter& filter, double footprint, int* lookups) {
  if (const auto* mesh = std::get_if<MeshScene>(&scene.shape))
    return shade_mesh(scene, *mesh, primitive, image_point, filter, footprint,
                      lookups)[static_cast<size_t>(mesh->channel)];
  if (const TexturedSurface* surface = texture_of(scene, primitive)) {
    const double grey =
        std::holds_alternative<ShapesScene>(scene.shape)
            ? std::get<ShapesScene>(scene.shape).shapes[static_cast<size_t>(primitive - 1)].grey
            : 1.0;
    auto c = texture_coordinates(scene, primitive, image_point);
    if (!c) {
      // The plane shaded at a point in the sky: the horizon's value, the
      // texture's mean (what its coarsest level holds).
      if (lookups) ++*lookups;
      return grey * surface->box.levels.back().texels[0];
    }
    c->j = {c->j.dsdx * footprint, c->j.dtdx * footprint, c->j.dsdy * footprint,
            c->j.dtdy * footprint};
    return grey * filtered_value(*surface, filter, c->s, c->t, c->j, lookups);
  }
  return std::visit(Overloaded{[&](const CheckerboardScene&) {
                                 return primitive == 1 ? 1.0 : primitive == 2 ? 0.0 : 0.75;
                               },
                               [&](const ShapesScene& s) {
                                 return primitive == 0
                                            ? s.background
                                            : s.shapes[static_cast<size_t>(primitive - 1)].grey;
                               },
                               [&](const ZonePlateScene&) { return shade(scene, image_point); },
                               [&](const auto&) { return primitive == 1 ? 1.0 : 0.0; }},
                    scene.shape);
}

namespace {

Rgb shade_mesh(const Scene& scene, const MeshScene& mesh, int primitive, Vec2 image_point,
               const TextureFilter& filter, double footprint, int* lookups) {
  const MeshView& view = *mesh.view;
  if (primitive <= 0) return view.light().background;
  const MeshMaterial& material = view.material(primitive - 1);
  const double light = view.triangles()[static_cast<size_t>(primitive - 1)].light;
  Rgb value{material.base[0] * light, material.base[1] * light, material.base[2] * light};
  if (!view.mesh().colours.empty()) {
    const Vec2 p = scene.view.identity() ? image_point : scene.view.to_scene(image_point);
    const MeshView::Weights w = view.weights(primitive - 1, p);
    const auto& tri =
        view.mesh().triangles[view.triangles()[static_cast<size_t>(primitive - 1)].source];
    for (size_t c = 0; c < 3; ++c) {
      double colour = 0;
      for (int m = 0; m < 3; ++m) colour += w.w[m] * view.mesh().colours[tri[m]][c];
      value[c] *= colour;
    }
  }
  if (!view.mesh().uv.empty() && material.texture[0]) {
    auto t = texture_coordinates(scene, primitive, image_point);
    t->j = {t->j.dsdx * footprint, t->j.dtdx * footprint, t->j.dsdy * footprint,
            t->j.dtdy * footprint};
    for (size_t c = 0; c < 3; ++c)
      value[c] *= filtered_value(*material.texture[c], filter, t->s, t->t, t->j,
                                 c == 0 ? lookups : nullptr);
  }
  for (double& v : value) v = std::clamp(v, 0.0, 1.0);
  return value;
}

}  // namespace

Rgb shade_primitive_colour(const Scene& scene, int primitive, Vec2 p, const TextureFilter& filter,
                           double footprint, int* lookups) {
  if (const auto* mesh = std::get_if<MeshScene>(&scene.shape))
    return shade_mesh(scene, *mesh, primitive, p, filter, footprint, lookups);
  const double v = shade_primitive(scene, primitive, p, filter, footprint, lookups);
  return {v, v, v};
}

Rgb shade_colour(const Scene& scene, Vec2 p) {
  static const TextureFilter kExact;
  if (std::holds_alternative<MeshScene>(scene.shape))
    return shade_primitive_colour(scene, primitive_at(scene, p), p, kExact);
  const double v = shade(scene, p);
  return {v, v, v};
}

bool has_texture(const Scene& scene) {
  if (const auto* mesh = std::get_if<MeshScene>(&scene.shape))
    return !mesh->view->mesh().uv.empty() &&
           std::any_of(mesh->view->mesh().materials.begin(), mesh->view->mesh().materials.end(),
                       [](const MeshMaterial& m) { return m.texture[0] != nullptr; });
  if (const auto* board = std::get_if<CheckerboardScene>(&scene.shape))
    return board->texture != nullptr;
  if (const auto* shapes = std::get_if<ShapesScene>(&scene.shape)) return shapes->textured;
  return false;
}

bool has_shading(const Scene& scene) {
  if (const auto* mesh = std::get_if<MeshScene>(&scene.shape))
    return has_texture(scene) || !mesh->view->mesh().colours.empty();
  return has_texture(scene) || std::holds_alternative<ZonePlateScene>(scene.shape);
}

}  // namespace aapat

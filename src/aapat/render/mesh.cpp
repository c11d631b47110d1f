#include "aapat/render/mesh.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace aapat {
namespace {

bool finite(Vec3 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Twice the signed area of (a, b, p): positive when p is left of a -> b.
// Computed from the edge's lower endpoint (x, then y) whichever way it runs,
// so that two triangles sharing the edge get exactly opposite values: a
// point on it is inside one of them or both, never in a crack.
double edge(Vec2 a, Vec2 b, Vec2 p) {
  if (b.x < a.x || (b.x == a.x && b.y < a.y))
    return -((a.x - b.x) * (p.y - b.y) - (a.y - b.y) * (p.x - b.x));
  return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

struct Fnv {
  uint64_t h = 1469598103934665603ull;
  void bytes(const void* data, size_t n) {
    const auto* b = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 1099511628211ull;
  }
  void number(double v) { bytes(&v, sizeof v); }
};

// A vertex in the camera's frame (x right, y up, z the depth ahead) with
// its weights over the source triangle's three vertices.
struct CameraVertex {
  Vec3 c;
  std::array<double, 3> blend;
};

// The polygon left of triangle `in` in front of the plane z = near
// (Sutherland-Hodgman against one plane): 0, 3 or 4 vertices.
int clip_near(const std::array<CameraVertex, 3>& in, double near,
              std::array<CameraVertex, 4>& out) {
  int n = 0;
  for (int k = 0; k < 3; ++k) {
    const CameraVertex& a = in[k];
    const CameraVertex& b = in[(k + 1) % 3];
    const bool a_in = a.c.z >= near, b_in = b.c.z >= near;
    if (a_in) out[n++] = a;
    if (a_in != b_in) {
      const double t = (near - a.c.z) / (b.c.z - a.c.z);
      CameraVertex m;
      m.c = a.c + t * (b.c - a.c);
      m.c.z = near;
      for (int q = 0; q < 3; ++q) m.blend[q] = a.blend[q] + t * (b.blend[q] - a.blend[q]);
      out[n++] = m;
    }
  }
  return n;
}

}  // namespace

Vec3 normalized(Vec3 v) {
  const double n = std::sqrt(dot(v, v));
  if (!(n > 0) || !std::isfinite(n)) throw Error("a direction must be a finite, non-zero vector");
  return (1 / n) * v;
}

void validate(const Mesh& m, const std::string& what) {
  if (m.triangles.empty()) throw Error(fmt::format("{}: the model has no triangles", what));
  if (m.triangles.size() > kMaxMeshTriangles)
    throw Error(fmt::format("{}: {} triangles exceed the limit of {}", what, m.triangles.size(),
                            kMaxMeshTriangles));
  if (m.positions.size() > kMaxMeshVertices)
    throw Error(fmt::format("{}: {} vertices exceed the limit of {}", what, m.positions.size(),
                            kMaxMeshVertices));
  if (m.materials.empty() || m.materials.size() > kMaxMeshMaterials)
    throw Error(fmt::format("{}: {} materials (1 to {} expected)", what, m.materials.size(),
                            kMaxMeshMaterials));
  if (!m.uv.empty() && m.uv.size() != m.positions.size())
    throw Error(fmt::format("{}: {} texture coordinates for {} vertices", what, m.uv.size(),
                            m.positions.size()));
  if (!m.colours.empty() && m.colours.size() != m.positions.size())
    throw Error(fmt::format("{}: {} vertex colours for {} vertices", what, m.colours.size(),
                            m.positions.size()));
  if (m.material.size() != m.triangles.size())
    throw Error(fmt::format("{}: {} material indices for {} triangles", what, m.material.size(),
                            m.triangles.size()));
  for (size_t i = 0; i < m.positions.size(); ++i)
    if (!finite(m.positions[i]))
      throw Error(fmt::format("{}: vertex {} is not finite ({}, {}, {})", what, i, m.positions[i].x,
                              m.positions[i].y, m.positions[i].z));
  for (size_t i = 0; i < m.uv.size(); ++i)
    if (!std::isfinite(m.uv[i].x) || !std::isfinite(m.uv[i].y))
      throw Error(fmt::format("{}: the texture coordinates of vertex {} are not finite", what, i));
  for (size_t i = 0; i < m.colours.size(); ++i)
    for (double c : m.colours[i])
      if (!(c >= 0 && c <= 1))
        throw Error(fmt::format("{}: vertex {} has a colour outside [0, 1]", what, i));
  for (size_t t = 0; t < m.triangles.size(); ++t) {
    for (uint32_t v : m.triangles[t])
      if (v >= m.positions.size())
        throw Error(
            fmt::format("{}: triangle {} names vertex {} of {}", what, t, v, m.positions.size()));
    if (m.material[t] >= m.materials.size())
      throw Error(fmt::format("{}: triangle {} names material {} of {}", what, t, m.material[t],
                              m.materials.size()));
  }
  size_t texels = 0;
  for (const MeshMaterial& mat : m.materials) {
    for (double c : mat.base)
      if (!(c >= 0 && c <= 1))
        throw Error(
            fmt::format("{}: material '{}' has a base colour outside [0, 1]", what, mat.name));
    if (mat.texture[0])
      texels += static_cast<size_t>(mat.texture[0]->texture.width) *
                static_cast<size_t>(mat.texture[0]->texture.height);
  }
  if (texels > kMaxMeshTextureTexels)
    throw Error(fmt::format("{}: its textures hold {} texels, over the limit of {}", what, texels,
                            kMaxMeshTextureTexels));
  if (m.camera) validate(*m.camera, what + ": its camera");
}

Bounds bounding_sphere(const Mesh& m) {
  Vec3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  for (const auto& t : m.triangles)
    for (uint32_t v : t) {
      const Vec3 p = m.positions[v];
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
  Bounds b{0.5 * (lo + hi), 0};
  for (const auto& t : m.triangles)
    for (uint32_t v : t) {
      const Vec3 d = m.positions[v] - b.centre;
      b.radius = std::max(b.radius, std::sqrt(dot(d, d)));
    }
  if (!(b.radius > 0)) b.radius = 1;  // a model that is a point: any scale frames it
  return b;
}

MeshCamera orbit_camera(const Mesh& mesh, double yaw_deg, double pitch_deg, double fov_deg) {
  if (!std::isfinite(yaw_deg)) throw ParameterError("yaw_deg", ": must be finite");
  if (!(pitch_deg > -90 && pitch_deg < 90))
    throw ParameterError("pitch_deg", fmt::format(" {}: expected -90 < pitch < 90", pitch_deg));
  if (!(fov_deg >= 1 && fov_deg <= 170))
    throw ParameterError("fov_deg", fmt::format(" {}: expected 1 to 170 degrees", fov_deg));
  const Bounds b = bounding_sphere(mesh);
  const double distance = b.radius / std::sin(radians(fov_deg) / 2);
  const double yaw = radians(yaw_deg), pitch = radians(pitch_deg);
  const Vec3 toward_eye{std::cos(pitch) * std::sin(yaw), std::sin(pitch),
                        std::cos(pitch) * std::cos(yaw)};
  return {b.centre + distance * toward_eye, b.centre, {0, 1, 0}, fov_deg};
}

void validate(const MeshCamera& c, const std::string& what) {
  if (!finite(c.eye) || !finite(c.target) || !finite(c.up))
    throw Error(fmt::format("{}: eye, target and up must be finite", what));
  if (!(c.fov_deg >= 1 && c.fov_deg <= 170))
    throw Error(fmt::format("{}: field of view {} outside 1 to 170 degrees", what, c.fov_deg));
  const Vec3 f = c.target - c.eye;
  if (!(dot(f, f) > 0)) throw Error(fmt::format("{}: the eye is at the target", what));
  const Vec3 side = cross(f, c.up);
  if (!(dot(side, side) > 1e-24 * dot(f, f) * dot(c.up, c.up)))
    throw Error(fmt::format("{}: up is zero or along the line of sight", what));
}

std::shared_ptr<const MeshView> make_mesh_view(std::shared_ptr<const Mesh> mesh,
                                               const MeshCamera& camera, const MeshLight& light,
                                               int width, int height) {
  validate(camera, "camera");
  if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide)
    throw ParameterError(
        "size", fmt::format(": {}x{} is out of range 1..{}", width, height, kMaxImageSide));
  auto view = std::make_shared<MeshView>();
  view->mesh_ = mesh;
  view->light_ = light;
  view->camera_ = camera;
  view->width_ = width;
  view->height_ = height;
  const Vec3 forward = normalized(camera.target - camera.eye);
  const Vec3 right = normalized(cross(forward, camera.up));
  const Vec3 up = cross(right, forward);
  const Vec3 toward_light = normalized(light.direction.x * right + light.direction.y * up +
                                       (-light.direction.z) * forward);
  const double focal = 0.5 * height / std::tan(radians(camera.fov_deg) / 2);
  const double cx = 0.5 * (width - 1), cy = 0.5 * (height - 1);
  const double near = 1e-3 * std::sqrt(dot(camera.target - camera.eye, camera.target - camera.eye));
  view->right_ = right;
  view->up_ = up;
  view->forward_ = forward;
  view->focal_ = focal;
  view->near_ = near;
  auto to_camera = [&](Vec3 p) {
    const Vec3 d = p - camera.eye;
    return Vec3{dot(d, right), dot(d, up), dot(d, forward)};
  };
  const Mesh& m = *mesh;
  for (size_t t = 0; t < m.triangles.size(); ++t) {
    const auto& tri = m.triangles[t];
    const Vec3 a = m.positions[tri[0]], b = m.positions[tri[1]], c = m.positions[tri[2]];
    Vec3 n = cross(b - a, c - a);
    const double len = std::sqrt(dot(n, n));
    if (!(len > 0) || !std::isfinite(len)) continue;  // no area: covers nothing
    n = (1 / len) * n;
    if (dot(n, camera.eye - a) < 0) n = -1 * n;  // both sides lit: the side the eye sees
    const double lit = light.ambient + (1 - light.ambient) * std::max(0.0, dot(n, toward_light));
    std::array<CameraVertex, 3> in{
        {{to_camera(a), {1, 0, 0}}, {to_camera(b), {0, 1, 0}}, {to_camera(c), {0, 0, 1}}}};
    std::array<CameraVertex, 4> poly;
    const int count = clip_near(in, near, poly);
    for (int k = 1; k + 1 < count; ++k) {  // the clipped polygon's fan
      ScreenTriangle s;
      s.source = static_cast<uint32_t>(t);
      s.light = lit;
      const CameraVertex* v[3] = {&poly[0], &poly[k], &poly[k + 1]};
      for (int q = 0; q < 3; ++q) {
        s.p[q] = {cx + focal * v[q]->c.x / v[q]->c.z, cy + focal * v[q]->c.y / v[q]->c.z};
        s.inv_z[q] = 1 / v[q]->c.z;
        s.blend[q] = v[q]->blend;
      }
      if (edge(s.p[0], s.p[1], s.p[2]) == 0) continue;  // seen edge-on
      view->triangles_.push_back(s);
    }
  }
  // Bins over the image and a margin for the filters' reach, about two
  // triangles' widths on a side where the model is dense, 2 to 32 pixels.
  constexpr double kMargin = 16;
  const double area = (width + 2 * kMargin) * (height + 2 * kMargin);
  view->bin_ = std::clamp(
      std::round(2 * std::sqrt(area / std::max<size_t>(1, view->triangles_.size()))), 2.0, 32.0);
  view->x0_ = -0.5 - kMargin;
  view->y0_ = -0.5 - kMargin;
  view->columns_ = static_cast<int>(std::ceil((width + 2 * kMargin) / view->bin_));
  view->rows_ = static_cast<int>(std::ceil((height + 2 * kMargin) / view->bin_));
  const size_t bins = static_cast<size_t>(view->columns_) * static_cast<size_t>(view->rows_);
  std::vector<uint32_t> count(bins + 1, 0);
  auto for_bins = [&](const ScreenTriangle& s, auto&& f) {
    double lo_x = INFINITY, hi_x = -INFINITY, lo_y = INFINITY, hi_y = -INFINITY;
    for (const Vec2& p : s.p) {
      lo_x = std::min(lo_x, p.x), hi_x = std::max(hi_x, p.x);
      lo_y = std::min(lo_y, p.y), hi_y = std::max(hi_y, p.y);
    }
    auto cell = [&](double v, double origin, int n) {
      return static_cast<int>(std::clamp(std::floor((v - origin) / view->bin_), -1.0, double(n)));
    };
    const int i0 = std::max(0, cell(lo_x, view->x0_, view->columns_)),
              i1 = std::min(view->columns_ - 1, cell(hi_x, view->x0_, view->columns_));
    const int j0 = std::max(0, cell(lo_y, view->y0_, view->rows_)),
              j1 = std::min(view->rows_ - 1, cell(hi_y, view->y0_, view->rows_));
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) f(static_cast<size_t>(j) * view->columns_ + i);
  };
  for (const ScreenTriangle& s : view->triangles_) for_bins(s, [&](size_t b) { ++count[b + 1]; });
  for (size_t b = 0; b < bins; ++b) count[b + 1] += count[b];
  view->bin_start_ = count;
  view->bin_items_.resize(count[bins]);
  for (uint32_t k = 0; k < view->triangles_.size(); ++k) {
    const ScreenTriangle& s = view->triangles_[k];
    const double nearest = std::max({s.inv_z[0], s.inv_z[1], s.inv_z[2]});
    for_bins(s, [&](size_t b) { view->bin_items_[count[b]++] = {nearest, k}; });
  }
  for (size_t b = 0; b < bins; ++b)
    std::sort(view->bin_items_.begin() + view->bin_start_[b],
              view->bin_items_.begin() + view->bin_start_[b + 1],
              [](const MeshView::BinItem& x, const MeshView::BinItem& y) {
                return x.nearest_inv_z > y.nearest_inv_z ||
                       (x.nearest_inv_z == y.nearest_inv_z && x.triangle < y.triangle);
              });
  view->key_ = fmt::format(
      "mesh {:016x} eye {:.17g} {:.17g} {:.17g} target {:.17g} {:.17g} {:.17g} up {:.17g} "
      "{:.17g} {:.17g} fov {:.17g} light {:.17g} {:.17g} {:.17g} {:.17g} background {:.17g} "
      "{:.17g} {:.17g} size {} {}",
      m.hash != 0 ? m.hash : content_hash(m), camera.eye.x, camera.eye.y, camera.eye.z,
      camera.target.x, camera.target.y, camera.target.z, camera.up.x, camera.up.y, camera.up.z,
      camera.fov_deg, light.direction.x, light.direction.y, light.direction.z, light.ambient,
      light.background[0], light.background[1], light.background[2], width, height);
  return view;
}

std::optional<Vec3> MeshView::surface_point(Vec2 p) const {
  const MeshHit h = hit(p);
  if (h.triangle < 0) return std::nullopt;
  const Weights w = weights(h.triangle, p);
  const auto& tri = mesh_->triangles[triangles_[static_cast<size_t>(h.triangle)].source];
  Vec3 x;
  for (int k = 0; k < 3; ++k) x = x + w.w[k] * mesh_->positions[tri[static_cast<size_t>(k)]];
  return x;
}

std::optional<Vec2> MeshView::project(Vec3 world) const {
  const Vec3 d = world - camera_.eye;
  const Vec3 c{dot(d, right_), dot(d, up_), dot(d, forward_)};
  if (!(c.z > near_)) return std::nullopt;
  return Vec2{0.5 * (width_ - 1) + focal_ * c.x / c.z, 0.5 * (height_ - 1) + focal_ * c.y / c.z};
}

MeshHit MeshView::hit(Vec2 p) const {
  MeshHit best;
  double nearest = 0;  // 1/z of the nearest hit (larger: nearer)
  auto test = [&](uint32_t k) {
    const ScreenTriangle& s = triangles_[k];
    const double w0 = edge(s.p[1], s.p[2], p), w1 = edge(s.p[2], s.p[0], p),
                 w2 = edge(s.p[0], s.p[1], p);
    const double area = w0 + w1 + w2;
    const bool inside =
        area > 0 ? (w0 >= 0 && w1 >= 0 && w2 >= 0) : (w0 <= 0 && w1 <= 0 && w2 <= 0);
    if (!inside || area == 0) return;
    const double l0 = w0 / area, l1 = w1 / area, l2 = w2 / area;
    const double inv_z = l0 * s.inv_z[0] + l1 * s.inv_z[1] + l2 * s.inv_z[2];
    if (inv_z > nearest || (inv_z == nearest && static_cast<int>(k) < best.triangle)) {
      nearest = inv_z;
      best.triangle = static_cast<int>(k);
      best.l[0] = l0, best.l[1] = l1, best.l[2] = l2;
    }
  };
  const double fx = std::floor((p.x - x0_) / bin_), fy = std::floor((p.y - y0_) / bin_);
  if (fx >= 0 && fy >= 0 && fx < columns_ && fy < rows_) {
    const size_t b = static_cast<size_t>(fy) * columns_ + static_cast<size_t>(fx);
    for (uint32_t q = bin_start_[b]; q < bin_start_[b + 1]; ++q) {
      if (bin_items_[q].nearest_inv_z < nearest) break;  // it and the rest lie behind the hit
      test(bin_items_[q].triangle);
    }
  } else {
    for (uint32_t k = 0; k < triangles_.size(); ++k) test(k);
  }
  return best;
}

MeshView::Weights MeshView::weights(int t, Vec2 p) const {
  const ScreenTriangle& s = triangles_[static_cast<size_t>(t)];
  const double area = edge(s.p[0], s.p[1], s.p[2]);
  const double l[3] = {edge(s.p[1], s.p[2], p) / area, edge(s.p[2], s.p[0], p) / area,
                       edge(s.p[0], s.p[1], p) / area};
  // d(edge(a, b, p))/dx = -(b.y - a.y), /dy = b.x - a.x.
  const double lx[3] = {-(s.p[2].y - s.p[1].y) / area, -(s.p[0].y - s.p[2].y) / area,
                        -(s.p[1].y - s.p[0].y) / area};
  const double ly[3] = {(s.p[2].x - s.p[1].x) / area, (s.p[0].x - s.p[2].x) / area,
                        (s.p[1].x - s.p[0].x) / area};
  // Perspective-correct: q_k = l_k / z_k / sum(l_j / z_j).
  double d = 0, ddx = 0, ddy = 0;
  for (int k = 0; k < 3; ++k) {
    d += l[k] * s.inv_z[k];
    ddx += lx[k] * s.inv_z[k];
    ddy += ly[k] * s.inv_z[k];
  }
  Weights out{};
  for (int k = 0; k < 3; ++k) {
    const double q = l[k] * s.inv_z[k] / d;
    const double qx = (lx[k] * s.inv_z[k] * d - l[k] * s.inv_z[k] * ddx) / (d * d);
    const double qy = (ly[k] * s.inv_z[k] * d - l[k] * s.inv_z[k] * ddy) / (d * d);
    for (int m = 0; m < 3; ++m) {
      out.w[m] += q * s.blend[k][m];
      out.dx[m] += qx * s.blend[k][m];
      out.dy[m] += qy * s.blend[k][m];
    }
  }
  return out;
}

const MeshMaterial& MeshView::material(int t) const {
  return mesh_->materials[mesh_->material[triangles_[static_cast<size_t>(t)].source]];
}

uint64_t content_hash(const Mesh& m) {
  Fnv h;
  auto size = [&](size_t n) { h.bytes(&n, sizeof n); };
  size(m.positions.size());
  for (const Vec3& p : m.positions) h.number(p.x), h.number(p.y), h.number(p.z);
  size(m.uv.size());
  for (const Vec2& p : m.uv) h.number(p.x), h.number(p.y);
  size(m.colours.size());
  for (const Rgb& c : m.colours) h.bytes(c.data(), sizeof c);
  size(m.triangles.size());
  for (size_t t = 0; t < m.triangles.size(); ++t) {
    h.bytes(m.triangles[t].data(), sizeof m.triangles[t]);
    h.bytes(&m.material[t], sizeof m.material[t]);
  }
  size(m.materials.size());
  for (const MeshMaterial& mat : m.materials) {
    h.bytes(mat.base.data(), sizeof mat.base);
    for (const auto& s : mat.texture) {
      const uint64_t th = s ? s->texture.content_hash() : 0;
      h.bytes(&th, sizeof th);
    }
  }
  return h.h;
}

}  // namespace aapat

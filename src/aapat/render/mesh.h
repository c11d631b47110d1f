// Triangle meshes seen through a pinhole camera: the 3D half of the test
// renderer. A Mesh is what a model file holds (io/mesh_file.h): triangles,
// texture coordinates, vertex colours and base-colour materials. A MeshView
// is that mesh projected for one image size and camera, with a bin grid over
// the image, so that the triangle a sample sees (the nearest one covering
// it, a depth test per sample) and its colour can be asked at any point of
// the image plane, exactly, like any analytic scene.
//
// Shading: base colour (material factor x vertex colour x texture) x
// (ambient + (1 - ambient) max(0, n . l)) with the face normal turned toward
// the eye (both sides lit) and one directional light, in display values
// like the grey scenes' levels.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "aapat/core/geometry.h"
#include "aapat/render/scene.h"
#include "aapat/render/texture_filter.h"

namespace aapat {

struct Vec3 {
  double x = 0, y = 0, z = 0;
  friend Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
  friend Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
  friend Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
  friend bool operator==(Vec3 a, Vec3 b) = default;
};
inline double dot(Vec3 a, Vec3 b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
Vec3 normalized(Vec3 v);  // v / |v|; refuses a zero or non-finite vector

// Limits of a model (docs/limits.md), checked before any work.
inline constexpr size_t kMaxMeshTriangles = 4'000'000;
inline constexpr size_t kMaxMeshVertices = 12'000'000;
inline constexpr size_t kMaxMeshMaterials = 65'536;
inline constexpr size_t kMaxMeshTextureTexels = size_t{1} << 26;  // all textures together

struct MeshMaterial {
  std::string name;
  Rgb base{1, 1, 1};  // display values in [0, 1]
  // The base-colour texture, one grey surface per channel (R, G, B), so that
  // every texture filter applies unchanged; none when the material has none.
  std::array<std::shared_ptr<const TexturedSurface>, 3> texture;
  std::string texture_name;
};

struct MeshCamera {
  Vec3 eye, target, up{0, 1, 0};
  double fov_deg = 45;  // vertical field of view
};

struct Mesh {
  std::string name;  // the file it came from
  std::vector<Vec3> positions;
  std::vector<Vec2> uv;      // empty, or one per position (1 = one repeat of the texture)
  std::vector<Rgb> colours;  // empty, or one per position
  std::vector<std::array<uint32_t, 3>> triangles;
  std::vector<uint32_t> material;  // per triangle
  std::vector<MeshMaterial> materials;
  std::optional<MeshCamera> camera;   // a camera stored in the file
  std::vector<std::string> warnings;  // what was read but not used (reported, not fatal)
  // content_hash(*this) once the mesh is final (io/mesh_file.h sets it); 0:
  // computed when a view needs it.
  uint64_t hash = 0;
};

// Checks the limits, that every index is in range and every value finite;
// `what` names the mesh in errors.
void validate(const Mesh& mesh, const std::string& what);

// The centre and radius of a sphere holding every vertex (the box's centre
// and the farthest vertex from it).
struct Bounds {
  Vec3 centre;
  double radius = 0;
};
Bounds bounding_sphere(const Mesh& mesh);

// A camera on a sphere around the model, looking at its centre: yaw about
// the vertical (+y), pitch above the horizon, at the distance where the
// bounding sphere fills the vertical field of view.
MeshCamera orbit_camera(const Mesh& mesh, double yaw_deg, double pitch_deg, double fov_deg);
void validate(const MeshCamera& camera, const std::string& what);

struct MeshLight {
  Vec3 direction{-0.4, 0.8,
                 0.45};  // toward the light, in the camera's frame (x right, y up, z back)
  double ambient = 0.35;
  Rgb background{0.2, 0.2, 0.2};
};

class MeshView;
// The mesh projected for a width x height image. Triangles are clipped
// against a near plane in front of the eye.
std::shared_ptr<const MeshView> make_mesh_view(std::shared_ptr<const Mesh> mesh,
                                               const MeshCamera& camera, const MeshLight& light,
                                               int width, int height);

// A projected triangle: screen positions, 1/z per vertex, its attribute
// source vertices and weights (a clipped triangle's vertices are blends of
// the original ones), and its flat light factor.
struct ScreenTriangle {
  std::array<Vec2, 3> p;
  std::array<double, 3> inv_z;
  std::array<std::array<double, 3>, 3> blend;  // vertex k = sum_m blend[k][m] original[m]
  uint32_t source = 0;                         // the mesh triangle
  double light = 1;
};

struct MeshHit {
  int triangle = -1;        // index into the view's triangles; -1: the background
  double l[3] = {0, 0, 0};  // screen barycentric coordinates
};

class MeshView {
 public:
  const Mesh& mesh() const { return *mesh_; }
  const std::vector<ScreenTriangle>& triangles() const { return triangles_; }
  const MeshLight& light() const { return light_; }
  // The nearest triangle covering p (edges included; equal depths: the lower index).
  MeshHit hit(Vec2 p) const;
  // The perspective-correct weights of screen triangle t's three source
  // vertices at p (mesh.triangles[source]) and their derivatives by x and y.
  struct Weights {
    double w[3], dx[3], dy[3];
  };
  Weights weights(int t, Vec2 p) const;
  const MeshMaterial& material(int t) const;
  // Every input of the view, exactly: keys the reference cache.
  const std::string& key() const { return key_; }
  // What it was made from (a camera orbit remakes it, render/motion.h).
  const std::shared_ptr<const Mesh>& mesh_ptr() const { return mesh_; }
  const MeshCamera& camera() const { return camera_; }
  int width() const { return width_; }
  int height() const { return height_; }
  // The world point under screen point p (none: the background), and a
  // world point's screen position (none: at or behind the near plane):
  // the exact motion vectors of a moving camera.
  std::optional<Vec3> surface_point(Vec2 p) const;
  std::optional<Vec2> project(Vec3 world) const;

 private:
  friend std::shared_ptr<const MeshView> make_mesh_view(std::shared_ptr<const Mesh>,
                                                        const MeshCamera&, const MeshLight&, int,
                                                        int);
  std::shared_ptr<const Mesh> mesh_;
  MeshLight light_;
  MeshCamera camera_;
  int width_ = 0, height_ = 0;
  Vec3 right_, up_, forward_;
  double focal_ = 1, near_ = 0;
  std::vector<ScreenTriangle> triangles_;
  // Square bins over the image and a margin, sized to the triangles' density;
  // a point outside them scans every triangle. Each bin lists its triangles
  // nearest first (by the largest 1/z of their vertices), so that a search
  // stops at the first one that cannot be nearer than the hit it holds.
  double x0_ = 0, y0_ = 0, bin_ = 8;
  int columns_ = 0, rows_ = 0;
  struct BinItem {
    double nearest_inv_z;
    uint32_t triangle;
  };
  std::vector<uint32_t> bin_start_;
  std::vector<BinItem> bin_items_;
  std::string key_;
};

// FNV-1a over the mesh's geometry, attributes and materials (textures by
// their content hashes).
uint64_t content_hash(const Mesh& mesh);

}  // namespace aapat

// Analytic test scenes: a grey level in [0, 1] at any point of the image
// plane, exactly, so that any sampling can be compared with any other.
//
// Image coordinates: pixel (i, j) is [i - 1/2, i + 1/2] x [j - 1/2, j + 1/2],
// its centre (i, j); x grows right and y up, row 0 at the bottom.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include "aapat/core/geometry.h"
#include "aapat/core/spec.h"

namespace aapat {

struct HalfPlaneScene {  // white where p . n <= offset, n = (cos a, sin a)
  Vec2 origin;
  double angle_deg = 30, offset = 0;
};
struct TexturedSurface;
struct CheckerboardScene {  // Goss & Wu Sec. 3.1: infinite flat-shaded checkerboard in perspective
  double width = 256, height = 256;
  double horizon = 0.8;      // horizon row as a fraction of the height
  double focal = 1.0;        // focal length in image widths
  double eye_height = 1;     // camera height over the plane, in squares
  double rotation_deg = 20;  // the board's rotation about the vertical
  // A texture on the ground instead of the squares (render/surface.h): it
  // repeats every `period` squares, so checker:cells=8 at period 8 is the
  // checkerboard itself.
  std::shared_ptr<const TexturedSurface> texture;
  double period = 8;
};
struct CirclesScene {  // Laine-Aila Fig. 7: white discs of growing radius on black
  double width = 256, height = 256;
  int count = 12;
};
struct SliverScene {  // Hasselgren Fig. 4: a thin triangle, thinner than a pixel at its tip
  Vec2 a{8, 10}, b{250, 40}, c{250, 52};
};
struct SpiralScene {  // Hasselgren Fig. 5: a white spiral arm on black
  Vec2 centre{128, 128};
  double turns = 6, max_radius = 120, arm = 0.35;  // arm: white fraction of each turn
};
struct DiscScene {  // Hasselgren Sec. 6.1: the translating circle
  Vec2 centre{64, 64};
  double radius = 20;
};
struct TriangleScene {  // Hasselgren Sec. 6.1: the rotating triangle
  Vec2 a, b, c;
};
struct ZonePlateScene {  // 0.5 + 0.5 cos(pi k r^2): frequency grows with radius
  Vec2 centre{128, 128};
  double k = 0.004;
};
// A scene file's content: polygons (even-odd rule) and circles, each with its
// grey level, painted in order over a background.
struct Shape {
  std::vector<Vec2> polygon;  // empty for a circle
  Vec2 centre;
  double radius = 0;
  double grey = 1;
  // A textured convex polygon: texture coordinates per vertex (1 = one
  // repeat of the texture) and the vertices' clip w (1: affine), interpolated
  // perspective-correctly over the fan from vertex 0; its value is grey x
  // the texture's.
  std::shared_ptr<const TexturedSurface> texture;
  std::vector<Vec2> uv;
  std::vector<double> w;
};
class ShapeIndex;
struct ShapesScene {
  double background = 0;
  std::vector<Shape> shapes;
  // Built by index_shapes(); without it shade() scans every shape.
  std::shared_ptr<const ShapeIndex> index;
  bool textured = false;  // some shape has a texture (set by index_shapes)
};
// Builds the scene's spatial index (render/shape_index.h) once its shapes are
// final, and notes whether any is textured.
void index_shapes(ShapesScene& scene);
// The last shape in painting order that holds scene point p, or -1.
int top_shape_at(const ShapesScene& scene, Vec2 p);

// A triangle mesh through a camera (render/mesh.h), in colour: render()
// gives its three channels at once (one coverage test and one interpolation
// per sample for all three); the grey functions (shade, shade_primitive)
// give `channel` (0 red, 1 green, 2 blue).
class MeshView;
using Rgb = std::array<double, 3>;  // display values in [0, 1]
struct MeshScene {
  std::shared_ptr<const MeshView> view;
  int channel = 0;
};

using SceneShape =
    std::variant<HalfPlaneScene, CheckerboardScene, CirclesScene, SliverScene, SpiralScene,
                 ZonePlateScene, DiscScene, TriangleScene, ShapesScene, MeshScene>;

// Where the scene sits in the image: rotated by rotation_deg and scaled by
// `scale` about `pivot`, then moved by `translation` (pixels).
struct View {
  Vec2 pivot;
  double rotation_deg = 0, scale = 1;
  Vec2 translation{0, 0};
  bool identity() const {
    return rotation_deg == 0 && scale == 1 && translation.x == 0 && translation.y == 0;
  }
  Vec2 to_scene(Vec2 image_point) const;  // the inverse map: where an image point reads the scene
  // to_scene with the rotation's cosine and sine computed once, for many points.
  struct Inverse {
    Vec2 pivot, translation;
    double scale, cos, sin;
    Vec2 operator()(Vec2 q) const {
      const double dx = (q.x - translation.x - pivot.x) / scale,
                   dy = (q.y - translation.y - pivot.y) / scale;
      return {pivot.x + cos * dx + sin * dy, pivot.y - sin * dx + cos * dy};
    }
  };
  Inverse inverse() const;
};

struct Scene {
  SceneShape shape;
  View view;
  template <class T>
  requires std::is_constructible_v<SceneShape, T> Scene(T s)
      : shape(std::move(s)) {}  // NOLINT: any scene kind is a Scene
};

// The grey level of the scene at p (textures at their exact texel values).
double shade(const Scene& scene, Vec2 p);
// out[k] = shade(scene, points[k]) for k < n, the scene's kind looked up once.
void shade_points(const Scene& scene, const Vec2* points, size_t n, double* out);

// What reading the scene's files used but could not take (a model's missing
// texture): each line names the file; the faces show them as warnings.
std::vector<std::string> scene_warnings(const Scene& scene);

// Every field of the scene, exactly (%.17g): equal texts, equal images. Keys the reference cache.
std::string canonical_text(const Scene& scene);

// `checkerboard`, `circles`, `sliver`, `spiral`, `zoneplate`, `disc` or
// `halfplane`, with optional parameters (`checkerboard:horizon=0.7,rotation=35`),
// laid out for a width x height image. scene_registry() lists the parameters.
Scene make_scene(std::string_view spec, int width, int height);

// Frame f of `frames` of an animation: `circle` (a disc of radius 0.3 x the
// smaller side translating diagonally by 5 pixels over the animation) or
// `triangle` (a triangle rotating a full turn about the image centre).
Scene animation_frame(std::string_view animation, int width, int height, int frame, int frames);

// Every built-in scene with its parameters (core/spec.h), built for a width x height image.
// `count` polygons (3 to 6 corners around a random centre) and circles in
// random greys over a random background, laid out on width x height from the
// seed (the `random-shapes` spec): the same scene for the same arguments on
// every platform.
Scene random_shapes(int count, uint64_t seed, int width, int height);
using SceneRegistry = Registry<Scene, int, int>;
const SceneRegistry& scene_registry();

}  // namespace aapat

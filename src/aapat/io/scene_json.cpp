#include "aapat/io/scene_json.h"

#include <fmt/format.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>

#include "aapat/io/atomic_file.h"
#include "aapat/io/mesh_scene.h"
#include "aapat/io/scene_fields.h"
#include "aapat/io/texture_file.h"

namespace aapat {
namespace {

using scene_fields::fail;
using scene_fields::json;
using scene_fields::number;

constexpr double kFar = 1e7;  // coordinates beyond this many pixels are a mistake

Vec2 point(const json& v, std::string_view source, const std::string& field) {
  if (!v.is_array() || v.size() != 2) fail(source, field + ": expected [x, y]");
  return {number(v[0], source, field + "[0]", -kFar, kFar),
          number(v[1], source, field + "[1]", -kFar, kFar)};
}

// Twice the signed area of the triangle abc.
double cross(Vec2 a, Vec2 b, Vec2 c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// A polygon's texture: "uv" per vertex, "w" per vertex (positive; default
// 1), "texture" a PNG file or procedural spec (or --texture later). The
// coordinates are interpolated over the fan from vertex 0, so the polygon
// must be convex.
void read_texture_fields(const json& s, std::string_view source, const std::string& field,
                         Shape& shape) {
  if (!s.contains("uv")) {
    if (s.contains("w") || s.contains("texture"))
      fail(source, field + ": \"w\" and \"texture\" need texture coordinates \"uv\"");
    return;
  }
  if (shape.polygon.empty()) fail(source, field + ": texture coordinates need a polygon");
  const json& uv = s["uv"];
  if (!uv.is_array() || uv.size() != shape.polygon.size())
    fail(source, fmt::format("{}.uv: expected {} [u, v] pairs, one per vertex", field,
                             shape.polygon.size()));
  for (size_t k = 0; k < uv.size(); ++k)
    shape.uv.push_back(point(uv[k], source, fmt::format("{}.uv[{}]", field, k)));
  shape.w.assign(shape.polygon.size(), 1.0);
  if (s.contains("w")) {
    const json& w = s["w"];
    if (!w.is_array() || w.size() != shape.polygon.size())
      fail(source,
           fmt::format("{}.w: expected {} numbers, one per vertex", field, shape.polygon.size()));
    for (size_t k = 0; k < w.size(); ++k)
      shape.w[k] = number(w[k], source, fmt::format("{}.w[{}]", field, k), 1e-6, 1e6);
  }
  const std::vector<Vec2>& P = shape.polygon;
  int sign = 0;
  for (size_t k = 0; k < P.size(); ++k) {
    const double c = cross(P[k], P[(k + 1) % P.size()], P[(k + 2) % P.size()]);
    const int here = c > 0 ? 1 : c < 0 ? -1 : 0;
    if (here != 0 && sign != 0 && here != sign)
      fail(source, field +
                       ".polygon: a textured polygon must be convex (its texture coordinates "
                       "are interpolated over the fan from its first vertex)");
    if (here != 0) sign = here;
  }
  if (sign == 0) fail(source, field + ".polygon: a textured polygon needs an area");
  if (s.contains("texture")) {
    if (!s["texture"].is_string())
      fail(source, field + ".texture: expected a PNG file or a texture spec such as \"checker\"");
    try {
      shape.texture = load_texture(s["texture"].get<std::string>());
    } catch (const Error& e) {
      fail(source, fmt::format("{}.texture: {}", field, e.what()));
    }
  }
}

}  // namespace

ShapesScene scene_from_json(std::string_view text, std::string_view source) {
  return scene_from_document(scene_fields::parse(text, source), source);
}

ShapesScene scene_from_document(const nlohmann::json& doc, std::string_view source) {
  if (!doc.is_object()) fail(source, "expected an object with \"shapes\"");
  for (const auto& [key, value] : doc.items())
    if (key != "format" && key != "background" && key != "shapes")
      fail(source, fmt::format("unknown field '{}' (expected format, background, shapes)", key));
  if (doc.contains("format") && doc["format"] != "aapat-scene")
    fail(source, "format: expected \"aapat-scene\"");
  ShapesScene scene;
  if (doc.contains("background"))
    scene.background = number(doc["background"], source, "background", 0, 1);
  if (!doc.contains("shapes") || !doc["shapes"].is_array())
    fail(source, "shapes: expected a list of polygons and circles");
  const json& shapes = doc["shapes"];
  if (shapes.size() > kMaxSceneShapes)
    fail(source,
         fmt::format("shapes: {} shapes exceed the limit of {}", shapes.size(), kMaxSceneShapes));
  size_t vertices = 0;
  for (size_t i = 0; i < shapes.size(); ++i) {
    const json& s = shapes[i];
    const std::string field = fmt::format("shapes[{}]", i);
    if (!s.is_object()) fail(source, field + ": expected an object");
    Shape shape;
    for (const auto& [key, value] : s.items())
      if (key != "polygon" && key != "circle" && key != "radius" && key != "grey" &&
          key != "texture" && key != "uv" && key != "w")
        fail(source, fmt::format("{}: unknown field '{}' (expected polygon or circle and radius, "
                                 "grey, and for a textured polygon texture, uv and w)",
                                 field, key));
    if (s.contains("polygon") == s.contains("circle"))
      fail(source, field + ": give either \"polygon\" or \"circle\"");
    if (s.contains("polygon")) {
      const json& poly = s["polygon"];
      if (!poly.is_array() || poly.size() < 3)
        fail(source, field + ".polygon: expected a list of 3 or more [x, y] vertices");
      if (poly.size() > kMaxPolygonVertices)
        fail(source, fmt::format("{}.polygon: {} vertices exceed the limit of {} per polygon",
                                 field, poly.size(), kMaxPolygonVertices));
      vertices += poly.size();
      if (vertices > kMaxSceneVertices)
        fail(source, fmt::format("{}.polygon: the scene's polygons have more than {} vertices in "
                                 "all, the limit",
                                 field, kMaxSceneVertices));
      if (s.contains("radius")) fail(source, field + ": a polygon has no radius");
      for (size_t k = 0; k < poly.size(); ++k)
        shape.polygon.push_back(point(poly[k], source, fmt::format("{}.polygon[{}]", field, k)));
    } else {
      shape.centre = point(s["circle"], source, field + ".circle");
      if (!s.contains("radius")) fail(source, field + ": a circle needs a radius");
      shape.radius = number(s["radius"], source, field + ".radius", 0, kFar);
    }
    if (s.contains("grey")) shape.grey = number(s["grey"], source, field + ".grey", 0, 1);
    read_texture_fields(s, source, field, shape);
    scene.shapes.push_back(std::move(shape));
  }
  index_shapes(scene);
  return scene;
}

Scene resolve_scene(const std::string& spec_or_path, int width, int height,
                    const std::string& texture) {
  std::optional<Scene> read;
  if (spec_or_path.ends_with(".json")) {
    // Parsed once; "mesh" says which kind of scene file it is.
    const json doc = scene_fields::parse(read_file(spec_or_path, "scene file"), spec_or_path);
    if (doc.is_object() && doc.contains("mesh")) {
      if (!texture.empty())
        fail(spec_or_path, "a mesh scene takes its textures from its model, not --texture");
      return make_mesh_scene(mesh_scene_from_document(doc, spec_or_path), width, height);
    }
    read.emplace(scene_from_document(doc, spec_or_path));
  }
  Scene scene = read ? std::move(*read) : make_scene(spec_or_path, width, height);
  if (!texture.empty()) scene = with_texture(std::move(scene), texture);
  if (const auto* shapes = std::get_if<ShapesScene>(&scene.shape))
    for (size_t k = 0; k < shapes->shapes.size(); ++k)
      if (!shapes->shapes[k].uv.empty() && !shapes->shapes[k].texture)
        throw Error(
            fmt::format("scene file {}: shapes[{}] has texture coordinates but no "
                        "texture: give it \"texture\" or give --texture",
                        spec_or_path, k));
  return scene;
}

}  // namespace aapat

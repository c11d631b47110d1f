#include "aapat/io/scene_json.h"

#include <fmt/format.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "aapat/io/atomic_file.h"

namespace aapat {
namespace {

using json = nlohmann::json;

[[noreturn]] void fail(std::string_view source, const std::string& message) {
  throw Error(fmt::format("scene file {}: {}", source, message));
}

double number(const json& v, std::string_view source, const std::string& field, double lo,
              double hi) {
  if (!v.is_number()) fail(source, field + ": expected a number");
  const double x = v.get<double>();
  if (!std::isfinite(x) || x < lo || x > hi)
    fail(source, fmt::format("{}: {} is outside [{}, {}]", field, x, lo, hi));
  return x;
}

constexpr double kFar = 1e7;  // coordinates beyond this many pixels are a mistake

Vec2 point(const json& v, std::string_view source, const std::string& field) {
  if (!v.is_array() || v.size() != 2) fail(source, field + ": expected [x, y]");
  return {number(v[0], source, field + "[0]", -kFar, kFar),
          number(v[1], source, field + "[1]", -kFar, kFar)};
}

}  // namespace

ShapesScene scene_from_json(std::string_view text, std::string_view source) {
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::exception& e) {  // parse errors, invalid UTF-8 and number overflow
    fail(source, fmt::format("not valid JSON ({})", e.what()));
  }
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
      if (key != "polygon" && key != "circle" && key != "radius" && key != "grey")
        fail(source, fmt::format("{}: unknown field '{}' (expected polygon or circle and radius, "
                                 "and grey)",
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
    scene.shapes.push_back(std::move(shape));
  }
  index_shapes(scene);
  return scene;
}

Scene resolve_scene(const std::string& spec_or_path, int width, int height) {
  if (spec_or_path.ends_with(".json"))
    return scene_from_json(read_file(spec_or_path, "scene file"), spec_or_path);
  return make_scene(spec_or_path, width, height);
}

}  // namespace aapat

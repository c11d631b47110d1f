#include "aapat/io/mesh_scene.h"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "aapat/io/mesh_file.h"
#include "aapat/io/scene_fields.h"

namespace aapat {
namespace {

using scene_fields::fail;
using scene_fields::json;
using scene_fields::number;

// The orbit camera's defaults: a three-quarter view from a little above.
constexpr double kDefaultYawDeg = 30, kDefaultPitchDeg = 20, kDefaultFovDeg = 40;

void only(const json& object, std::string_view source, const std::string& field,
          std::initializer_list<std::string_view> keys) {
  for (const auto& [key, value] : object.items())
    if (std::find(keys.begin(), keys.end(), key) == keys.end()) {
      std::string list;
      for (std::string_view k : keys) list += (list.empty() ? "" : ", ") + std::string(k);
      fail(source, fmt::format("{}unknown field '{}' (expected {})",
                               field.empty() ? "" : field + ": ", key, list));
    }
}

Vec3 vec3(const json& v, std::string_view source, const std::string& field) {
  constexpr double kFar = 1e12;
  if (!v.is_array() || v.size() != 3) fail(source, field + ": expected [x, y, z]");
  return {number(v[0], source, field + "[0]", -kFar, kFar),
          number(v[1], source, field + "[1]", -kFar, kFar),
          number(v[2], source, field + "[2]", -kFar, kFar)};
}

MeshCamera camera(const json& c, const Mesh& mesh, std::string_view source) {
  if (c.is_string()) {
    if (c != "file") fail(source, "camera: expected \"file\" or an object");
    if (!mesh.camera)
      fail(source, fmt::format("camera: \"file\", but {} has no camera", mesh.name));
    return *mesh.camera;
  }
  if (!c.is_object()) fail(source, "camera: expected an object or \"file\"");
  const double fov = c.contains("fov_deg") ? number(c["fov_deg"], source, "camera.fov_deg", 1, 170)
                                           : kDefaultFovDeg;
  if (c.contains("eye") || c.contains("target")) {
    only(c, source, "camera", {"eye", "target", "up", "fov_deg"});
    if (!c.contains("eye") || !c.contains("target"))
      fail(source, "camera: give both \"eye\" and \"target\"");
    MeshCamera cam{vec3(c["eye"], source, "camera.eye"), vec3(c["target"], source, "camera.target"),
                   c.contains("up") ? vec3(c["up"], source, "camera.up") : Vec3{0, 1, 0}, fov};
    try {
      validate(cam, "camera");
    } catch (const Error& e) {
      fail(source, e.what());
    }
    return cam;
  }
  only(c, source, "camera", {"yaw_deg", "pitch_deg", "fov_deg"});
  const double yaw = c.contains("yaw_deg")
                         ? number(c["yaw_deg"], source, "camera.yaw_deg", -3600, 3600)
                         : kDefaultYawDeg;
  const double pitch = c.contains("pitch_deg")
                           ? number(c["pitch_deg"], source, "camera.pitch_deg", -89.9, 89.9)
                           : kDefaultPitchDeg;
  return orbit_camera(mesh, yaw, pitch, fov);
}

}  // namespace

MeshSceneSpec mesh_scene_from_json(std::string_view text, const std::string& source) {
  return mesh_scene_from_document(scene_fields::parse(text, source), source);
}

MeshSceneSpec mesh_scene_from_document(const nlohmann::json& doc, const std::string& source) {
  if (!doc.is_object()) fail(source, "expected an object with \"mesh\"");
  only(doc, source, "", {"format", "mesh", "camera", "light", "background"});
  if (doc.contains("format") && doc["format"] != "aapat-scene")
    fail(source, "format: expected \"aapat-scene\"");
  if (!doc.contains("mesh") || !doc["mesh"].is_string() || doc["mesh"].get<std::string>().empty())
    fail(source, "mesh: expected the model's file name");
  const std::filesystem::path model =
      std::filesystem::path(source).parent_path() / doc["mesh"].get<std::string>();
  MeshSceneSpec spec;
  try {
    spec.mesh = read_mesh(model.string());
  } catch (const Error& e) {
    fail(source, fmt::format("mesh: {}", e.what()));
  }
  spec.camera = camera(doc.contains("camera") ? doc["camera"] : json::object(), *spec.mesh, source);
  if (doc.contains("light")) {
    const json& l = doc["light"];
    if (!l.is_object()) fail(source, "light: expected an object");
    only(l, source, "light", {"direction", "ambient"});
    if (l.contains("direction")) {
      spec.light.direction = vec3(l["direction"], source, "light.direction");
      if (dot(spec.light.direction, spec.light.direction) == 0)
        fail(source, "light.direction: must not be zero");
    }
    if (l.contains("ambient"))
      spec.light.ambient = number(l["ambient"], source, "light.ambient", 0, 1);
  }
  if (doc.contains("background")) {
    const json& b = doc["background"];
    if (b.is_number()) {
      const double g = number(b, source, "background", 0, 1);
      spec.light.background = {g, g, g};
    } else if (b.is_array() && b.size() == 3) {
      for (size_t c = 0; c < 3; ++c)
        spec.light.background[c] = number(b[c], source, fmt::format("background[{}]", c), 0, 1);
    } else {
      fail(source, "background: expected a grey level or [r, g, b]");
    }
  }
  return spec;
}

Scene make_mesh_scene(const MeshSceneSpec& spec, int width, int height) {
  return Scene(MeshScene{make_mesh_view(spec.mesh, spec.camera, spec.light, width, height), 0});
}

}  // namespace aapat

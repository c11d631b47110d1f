// The mesh scene file: a model (io/mesh_file.h) seen through a camera, in
// JSON beside the polygon scene files (io/scene_json.h). Layout
// (docs/renderer.md):
//
//   {"mesh": "truck.gltf",                    // relative to the scene file
//    "camera": {"yaw_deg": 30, "pitch_deg": 20, "fov_deg": 40},
//    "light": {"direction": [-0.4, 0.8, 0.45], "ambient": 0.35},
//    "background": [0.2, 0.2, 0.2]}
//
// The camera is an orbit that frames the model's bounding sphere (yaw about
// +y, pitch above the horizon), or {"eye", "target", "up", "fov_deg"}, or
// "file" for the first camera stored in the model. Every field but "mesh"
// is optional (the orbit's defaults above).
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "aapat/render/mesh.h"
#include "aapat/render/scene.h"

namespace aapat {

struct MeshSceneSpec {
  std::shared_ptr<const Mesh> mesh;
  MeshCamera camera;
  MeshLight light;
};

// Parses and validates the file's text; `source` is its path (the model is
// found beside it). Throws Error naming the file and the field.
MeshSceneSpec mesh_scene_from_json(std::string_view text, const std::string& source);
// The same from the parsed file (resolve_scene parses a scene file once).
MeshSceneSpec mesh_scene_from_document(const nlohmann::json& doc, const std::string& source);

// The scene for a width x height image: its red channel (render/color_render.h
// renders all three).
Scene make_mesh_scene(const MeshSceneSpec& spec, int width, int height);

}  // namespace aapat

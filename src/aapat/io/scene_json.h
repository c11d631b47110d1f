// The scene file: polygons and circles with grey levels, in JSON, so that a
// user can build a test scene without writing code. Layout: docs/renderer.md.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "aapat/render/scene.h"

namespace aapat {

// Limits of a scene file (docs/limits.md).
inline constexpr size_t kMaxSceneShapes = 1'000'000;
inline constexpr size_t kMaxPolygonVertices = 100'000;
inline constexpr size_t kMaxSceneVertices = 1'000'000;

// `source` names the text in error messages (a file name). Validates.
ShapesScene scene_from_json(std::string_view text, std::string_view source);
// The same from the parsed file.
ShapesScene scene_from_document(const nlohmann::json& doc, std::string_view source);

// A scene file (a path ending in .json) or a built-in scene spec
// (make_scene), with `texture` (io/texture_file.h) on what takes one; every
// shape with texture coordinates must end up with a texture.
Scene resolve_scene(const std::string& spec_or_path, int width, int height,
                    const std::string& texture = "");

}  // namespace aapat

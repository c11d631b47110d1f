// The fields of a scene file, read one way by both kinds (polygons,
// io/scene_json.h; a model through a camera, io/mesh_scene.h): the file is
// parsed once, and every error names the file and the field.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace aapat::scene_fields {

using json = nlohmann::json;

// Throws Error "scene file SOURCE: MESSAGE".
[[noreturn]] void fail(std::string_view source, const std::string& message);

// The text as JSON; a parse error (invalid UTF-8, number overflow) is
// "not valid JSON (...)".
json parse(std::string_view text, std::string_view source);

// A finite number in [lo, hi]; `field` names it in the error.
double number(const json& v, std::string_view source, const std::string& field, double lo,
              double hi);

}  // namespace aapat::scene_fields

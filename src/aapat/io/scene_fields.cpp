#include "aapat/io/scene_fields.h"

#include <fmt/format.h>

#include <cmath>

#include "aapat/core/geometry.h"
#include "aapat/core/json_depth.h"

namespace aapat::scene_fields {

void fail(std::string_view source, const std::string& message) {
  throw Error(fmt::format("scene file {}: {}", source, message));
}

json parse(std::string_view text, std::string_view source) {
  const int depth = json_depth(text);  // before the parser's recursion
  if (depth > kMaxJsonDepth)
    fail(source, fmt::format("nested {} deep, past the limit of {} (docs/limits.md)", depth,
                             kMaxJsonDepth));
  try {
    return json::parse(text);
  } catch (const json::exception& e) {  // parse errors, invalid UTF-8 and number overflow
    fail(source, fmt::format("not valid JSON ({})", e.what()));
  }
}

double number(const json& v, std::string_view source, const std::string& field, double lo,
              double hi) {
  if (!v.is_number()) fail(source, field + ": expected a number");
  const double x = v.get<double>();
  if (!std::isfinite(x) || x < lo || x > hi)
    fail(source, fmt::format("{}: {} is outside [{}, {}]", field, x, lo, hi));
  return x;
}

}  // namespace aapat::scene_fields

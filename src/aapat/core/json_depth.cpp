#include "aapat/core/json_depth.h"

#include <fmt/format.h>

#include <algorithm>

#include "aapat/core/geometry.h"

namespace aapat {

int json_depth(std::string_view text) {
  int depth = 0, deepest = 0;
  bool in_string = false, escaped = false;
  for (const char c : text) {
    if (in_string) {
      if (escaped)
        escaped = false;
      else if (c == '\\')
        escaped = true;
      else if (c == '"')
        in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      deepest = std::max(deepest, ++depth);
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return deepest;
}

void check_json_depth(std::string_view text, std::string_view what) {
  const int depth = json_depth(text);
  if (depth > kMaxJsonDepth)
    throw Error(fmt::format("{}: nested {} deep, past the limit of {} (docs/limits.md)", what,
                            depth, kMaxJsonDepth));
}

}  // namespace aapat

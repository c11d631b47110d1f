// How deeply JSON text nests, counted without recursion: nlohmann-json's
// parser recurses once per array or object, so a pattern file or a link
// nested 100,000 deep overflows the stack before any check of ours runs.
// Every reader of JSON input checks the depth first (docs/limits.md).
#pragma once

#include <string_view>

namespace aapat {

// Deeper than any aapat file, scene or request needs (a pattern file nests
// four deep, a scene file five), far below what the parser's recursion takes.
inline constexpr int kMaxJsonDepth = 256;

// The deepest nesting of arrays and objects in `text`, brackets inside
// strings (escapes included) not counted; malformed text is counted as far
// as it goes (the parser names its faults).
int json_depth(std::string_view text);

// Throws Error "WHAT: nested N deep, past the limit of kMaxJsonDepth" when
// `text` nests deeper than kMaxJsonDepth.
void check_json_depth(std::string_view text, std::string_view what);

}  // namespace aapat

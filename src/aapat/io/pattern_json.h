// The pattern file: human-readable JSON that round-trips byte for byte.
// Layout and rules: docs/pattern-format.md.
#pragma once

#include <string>
#include <string_view>

#include "aapat/core/pattern.h"

namespace aapat {

std::string pattern_to_json(const Pattern& p);
// `source` names the text in error messages (a file name). Validates.
Pattern pattern_from_json(std::string_view text, std::string_view source);

// A pattern file: .xyw is Laine's "x y weight" text (io/pattern_text.h), any
// other name aapat's JSON.
bool is_pattern_path(std::string_view path);  // .json or .xyw
Pattern load_pattern_file(const std::string& path);
void save_pattern_file(const Pattern& p, const std::string& path);

// A catalog name or a path to a pattern file (anything ending in .json or
// naming an existing file).
Pattern resolve_pattern(const std::string& name_or_path);
// A catalog or aapat catalog pattern by name, no file read (the page's
// names); the same message as resolve_pattern for a name that is neither.
Pattern named_pattern(const std::string& name);

}  // namespace aapat

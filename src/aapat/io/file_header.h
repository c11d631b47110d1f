// What aapat's pattern and sequence files share (docs/pattern-format.md,
// docs/temporal.md): the header fields format, version, name and
// description, a closing provenance object of strings, and the rule that a
// field the reader does not know is an error. Errors read "KIND SOURCE:
// FIELD: what is wrong", KIND naming the file ("pattern file").
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace aapat {

using Provenance = std::vector<std::pair<std::string, std::string>>;

struct FileHeader {
  std::string_view kind;                // "pattern file", in errors
  std::string_view format;              // "aapat-pattern"
  int version = 1;                      // the one this aapat reads and writes
  std::vector<std::string_view> known;  // every field, in the order written
  std::vector<std::string_view> required;
};

[[noreturn]] void file_error(std::string_view kind, std::string_view source,
                             const std::string& message);

// `text` parsed (keys in the file's order) and its top level checked: an
// object, no unknown field, every required one there, the format and the
// version this aapat reads.
nlohmann::ordered_json parse_file(const FileHeader& header, std::string_view text,
                                  std::string_view source);

// The name (required, a string) and the optional description.
std::pair<std::string, std::string> read_name_and_description(const FileHeader& header,
                                                              const nlohmann::ordered_json& doc,
                                                              std::string_view source);

// The optional provenance object, every value a string.
Provenance read_provenance(const FileHeader& header, const nlohmann::ordered_json& doc,
                           std::string_view source);

// A JSON string literal; bytes that are not UTF-8 are replaced.
std::string json_quoted(std::string_view text);

// The writer's first lines ("{", format, version, name, description) and
// its last (the provenance object and the closing brace).
std::string header_json(const FileHeader& header, std::string_view name,
                        std::string_view description);
std::string provenance_json(const Provenance& provenance);

}  // namespace aapat

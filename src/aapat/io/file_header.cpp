#include "aapat/io/file_header.h"

#include <fmt/format.h>

#include <algorithm>

#include "aapat/core/geometry.h"
#include "aapat/core/json_depth.h"
#include "aapat/core/text.h"

namespace aapat {

void file_error(std::string_view kind, std::string_view source, const std::string& message) {
  throw Error(fmt::format("{} {}: {}", kind, source, message));
}

nlohmann::ordered_json parse_file(const FileHeader& header, std::string_view text,
                                  std::string_view source) {
  const auto fail = [&](const std::string& message) { file_error(header.kind, source, message); };
  nlohmann::ordered_json doc;
  const int depth = json_depth(text);  // before the parser's recursion
  if (depth > kMaxJsonDepth)
    fail(
        fmt::format("nested {} deep, past the limit of {} (docs/limits.md)", depth, kMaxJsonDepth));
  try {
    doc = nlohmann::ordered_json::parse(text);
  } catch (const nlohmann::ordered_json::exception& e) {  // parse errors and number overflow
    fail(fmt::format("not valid JSON: {}", e.what()));
  }
  if (!doc.is_object()) fail("expected a JSON object at the top level");
  for (const auto& [key, value] : doc.items())
    if (std::find(header.known.begin(), header.known.end(), key) == header.known.end())
      fail(fmt::format("{}: unknown field (known: {})", key, fmt::join(header.known, ", ")));
  for (const std::string_view key : header.required)
    if (!doc.contains(key)) fail(fmt::format("{}: missing", key));
  if (doc["format"] != header.format)
    fail(fmt::format("format: expected \"{}\", got {}", header.format, doc["format"].dump()));
  if (doc["version"] != header.version)
    fail(fmt::format("version: {} is not supported (this aapat reads version {})",
                     doc["version"].dump(), header.version));
  return doc;
}

namespace {

// A name, description or provenance entry is one line of text (exporters
// write them into comments): a control character is refused with its place.
void check_one_line(const FileHeader& header, std::string_view field, std::string_view text,
                    std::string_view source) {
  const size_t at = control_character_at(text);
  if (at != std::string_view::npos)
    file_error(header.kind, source,
               fmt::format("{}: control character U+{:04X} at byte {} (it must be one line of "
                           "text)",
                           field, static_cast<unsigned char>(text[at]), at));
}

}  // namespace

std::pair<std::string, std::string> read_name_and_description(const FileHeader& header,
                                                              const nlohmann::ordered_json& doc,
                                                              std::string_view source) {
  if (!doc.contains("name") || !doc.at("name").is_string())
    file_error(header.kind, source, "name: expected a string");
  std::string description;
  if (doc.contains("description")) {
    if (!doc.at("description").is_string())
      file_error(header.kind, source, "description: expected a string");
    description = doc.at("description").get<std::string>();
  }
  const std::string name = doc.at("name").get<std::string>();
  check_one_line(header, "name", name, source);
  check_one_line(header, "description", description, source);
  return {name, description};
}

Provenance read_provenance(const FileHeader& header, const nlohmann::ordered_json& doc,
                           std::string_view source) {
  Provenance out;
  if (!doc.contains("provenance")) return out;
  const nlohmann::ordered_json& prov = doc.at("provenance");
  if (!prov.is_object())
    file_error(header.kind, source, "provenance: expected an object of strings");
  for (const auto& [key, value] : prov.items()) {
    if (!value.is_string())
      file_error(header.kind, source, fmt::format("provenance.{}: expected a string", key));
    check_one_line(header, fmt::format("provenance key '{}'", one_line(key)), key, source);
    check_one_line(header, fmt::format("provenance.{}", one_line(key)), value.get<std::string>(),
                   source);
    out.emplace_back(key, value.get<std::string>());
  }
  return out;
}

std::string json_quoted(std::string_view text) {
  return nlohmann::ordered_json(std::string(text))
      .dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

std::string header_json(const FileHeader& header, std::string_view name,
                        std::string_view description) {
  return fmt::format(
      "{{\n  \"format\": {},\n  \"version\": {},\n  \"name\": {},\n  \"description\": {},\n",
      json_quoted(header.format), header.version, json_quoted(name), json_quoted(description));
}

std::string provenance_json(const Provenance& provenance) {
  std::string out = "  \"provenance\": {";
  for (size_t i = 0; i < provenance.size(); ++i)
    out += fmt::format("{}\n    {}: {}", i ? "," : "", json_quoted(provenance[i].first),
                       json_quoted(provenance[i].second));
  out += provenance.empty() ? "}\n}\n" : "\n  }\n}\n";
  return out;
}

}  // namespace aapat

#include "aapat/temporal/sequence/sequence_json.h"

#include "aapat/core/nearest_name.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <tuple>

#include "aapat/io/atomic_file.h"
#include "aapat/io/catalog_clash.h"
#include "aapat/io/file_header.h"
#include "aapat/io/pattern_json.h"
#include "aapat/temporal/sequence/sequence_generators.h"

namespace aapat::embedded {
extern const std::vector<std::pair<std::string_view, std::string_view>> kAapatSequences;
}  // namespace aapat::embedded

namespace aapat {
namespace {

using json = nlohmann::ordered_json;

const FileHeader kHeader{
    "sequence file",
    "aapat-sequence",
    1,
    {"format", "version", "name", "description", "family", "jitter", "frames", "provenance"},
    {"format", "version", "name"}};

[[noreturn]] void fail(std::string_view source, const std::string& message) {
  file_error(kHeader.kind, source, message);
}

bool is_jitter(const Sequence& s) {
  for (const Pattern& p : s.frames)
    if (p.set_count() != 1 || p.footprint.size != 1 || p.footprint.plus || p.sets[0].size() != 1 ||
        p.weights[0].size() != 1 || p.weights[0][0] != 1.0 || !p.provenance.empty())
      return false;
  return true;
}

std::string frame_name(const std::string& sequence, size_t f) {
  return fmt::format("{} frame {}", sequence, f);
}

// The pattern file's text, indented to sit in the frames array.
std::string indented(const std::string& text) {
  std::string out = "    ";
  for (size_t i = 0; i < text.size(); ++i) {
    out += text[i];
    if (text[i] == '\n' && i + 1 < text.size()) out += "    ";
  }
  while (!out.empty() && out.back() == '\n') out.pop_back();
  return out;
}

}  // namespace

std::string sequence_to_json(const Sequence& s) {
  validate(s);
  std::string out = header_json(kHeader, s.name, s.description);
  out += fmt::format("  \"family\": {},\n", json_quoted(family(s.frames[0])));
  if (is_jitter(s)) {
    out += "  \"jitter\": [";
    for (size_t f = 0; f < s.frames.size(); ++f) {
      const Vec2 v = s.frames[f].sets[0][0];
      out += fmt::format("{}[{}, {}]", f == 0 ? "\n    " : (f % 4 == 0 ? ",\n    " : ", "),
                         json(v.x).dump(), json(v.y).dump());
    }
    out += "\n  ],\n";
  } else {
    out += "  \"frames\": [\n";
    for (size_t f = 0; f < s.frames.size(); ++f)
      out += indented(pattern_to_json(s.frames[f])) + (f + 1 < s.frames.size() ? ",\n" : "\n");
    out += "  ],\n";
  }
  return out + provenance_json(s.provenance);
}

Sequence sequence_from_json(std::string_view text, std::string_view source) {
  json doc = parse_file(kHeader, text, source);
  if (doc.contains("jitter") == doc.contains("frames"))
    fail(source,
         "give the frames as exactly one of \"jitter\" (one offset per frame) and "
         "\"frames\" (a pattern per frame)");
  Sequence s;
  std::tie(s.name, s.description) = read_name_and_description(kHeader, doc, source);
  const std::string_view list = doc.contains("jitter") ? "jitter" : "frames";
  const json& frames = doc[std::string(list)];
  if (!frames.is_array() || frames.empty())
    fail(source, fmt::format("{}: expected a non-empty array", list));
  if (frames.size() > static_cast<size_t>(kMaxSequenceFrames))
    fail(source, fmt::format("{}: {} frames exceed the limit of {}", list, frames.size(),
                             kMaxSequenceFrames));
  for (size_t f = 0; f < frames.size(); ++f) {
    const std::string field = fmt::format("{}[{}]", list, f);
    if (list == "jitter") {
      const json& v = frames[f];
      if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number())
        fail(source, field + ": expected [x, y], the offset in pixels");
      s.frames.push_back(
          jitter_frame({v[0].get<double>(), v[1].get<double>()}, frame_name(s.name, f)));
    } else {
      if (!frames[f].is_object()) fail(source, field + ": expected a pattern object");
      json frame = frames[f];
      // A frame needs no format header of its own inside a sequence file.
      if (!frame.contains("format")) frame["format"] = "aapat-pattern";
      if (!frame.contains("version")) frame["version"] = 1;
      if (!frame.contains("name")) frame["name"] = frame_name(s.name, f);
      s.frames.push_back(pattern_from_json(frame.dump(), fmt::format("{} {}", source, field)));
    }
  }
  s.provenance = read_provenance(kHeader, doc, source);
  try {
    validate(s);
  } catch (const Error& e) {
    fail(source, e.what());
  }
  if (doc.contains("family")) {
    if (!doc["family"].is_string()) fail(source, "family: expected a string such as \"P(1,1,1)\"");
    if (doc["family"].get<std::string>() != family(s.frames[0]))
      fail(source, fmt::format("family: the file says {} but its frames make {}",
                               doc["family"].get<std::string>(), family(s.frames[0])));
  }
  return s;
}

Sequence load_sequence_file(const std::string& path) {
  Sequence s = sequence_from_json(read_file(path, "sequence file"), path);
  // An optimized sequence's name on other frames is read under the file's own name.
  const auto taken = [](std::string_view n) {
    for (const auto& entry : embedded::kAapatSequences)
      if (entry.first == n) return true;
    return false;
  };
  for (const auto& [name, text] : embedded::kAapatSequences) {
    if (name != s.name) continue;
    const Sequence entry = sequence_from_json(text, fmt::format("data/sequences/{}.json", name));
    const bool same =
        entry.period() == s.period() &&
        std::equal(entry.frames.begin(), entry.frames.end(), s.frames.begin(), same_samples);
    if (!same) s.name = name_off_the_catalog(s.name, path, taken, "sequence file");
  }
  return s;
}

void save_sequence_file(const Sequence& s, const std::string& path) {
  write_file_atomically(path, sequence_to_json(s));
}

std::vector<SpecInfo> sequence_catalog() {
  std::vector<SpecInfo> out;
  for (const auto& [name, text] : embedded::kAapatSequences) {
    const json doc = json::parse(text);
    out.push_back({std::string(name),
                   doc.value("description", ""),
                   fmt::format("aapat: data/sequences/{}.json", name),
                   {}});
  }
  return out;
}

Sequence resolve_sequence(const std::string& spec_or_path, const std::optional<Pattern>& pattern) {
  for (const auto& [name, text] : embedded::kAapatSequences)
    if (name == spec_or_path)
      return sequence_from_json(text, fmt::format("data/sequences/{}.json", name));
  std::error_code ec;
  if (spec_or_path.ends_with(".json") || std::filesystem::is_regular_file(spec_or_path, ec))
    return load_sequence_file(spec_or_path);
  if (!sequence_registry().contains(spec_or_path)) {
    // Neither a generator nor a file: name the generators, the optimized
    // sequences and the nearest of both.
    std::vector<std::string> names, optimized;
    for (const auto& e : sequence_registry().entries()) names.push_back(e.info.name);
    for (const auto& entry : embedded::kAapatSequences) optimized.emplace_back(entry.first);
    names.insert(names.end(), optimized.begin(), optimized.end());
    const std::string name(split_spec(spec_or_path).first);
    throw Error(fmt::format(
        "unknown sequence '{}'{}: not a sequence file (.json), a generator ({}) nor an optimized "
        "sequence ({})",
        name, did_you_mean(name, names), sequence_registry().names(), fmt::join(optimized, ", ")));
  }
  return make_sequence(spec_or_path, pattern);
}

Sequence resolve_sequence_for_ratio(const std::string& spec_or_path, double ratio,
                                    std::string* warning) {
  const int rule = upscaler_phase_count(ratio);
  std::string spec = spec_or_path;
  const bool generator =
      sequence_registry().contains(spec_or_path) && !std::filesystem::is_regular_file(spec_or_path);
  if (generator) {
    const auto* entry = sequence_registry().find(split_spec(spec_or_path).first);
    const bool takes_frames = std::any_of(entry->info.params.begin(), entry->info.params.end(),
                                          [](const ParamInfo& p) { return p.key == "frames"; });
    const std::string params(split_spec(spec_or_path).second);
    const bool given =
        params.starts_with("frames=") || params.find(",frames=") != std::string::npos;
    if (takes_frames && !given)
      spec = fmt::format("{}:{}frames={}", split_spec(spec_or_path).first,
                         params.empty() ? "" : params + ",", rule);
  }
  Sequence s = resolve_sequence(spec);
  if (warning) *warning = upscaler_rule_warning(s.name, s.period(), ratio);
  return s;
}

}  // namespace aapat

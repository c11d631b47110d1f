#include "aapat/io/pattern_json.h"

#include "aapat/io/aapat_catalog.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <tuple>

#include "aapat/core/hardware_layout.h"
#include "aapat/core/nearest_name.h"
#include "aapat/generate/catalog.h"
#include "aapat/io/atomic_file.h"
#include "aapat/io/catalog_clash.h"
#include "aapat/io/file_header.h"
#include "aapat/io/pattern_text.h"

namespace aapat {
namespace {

using json = nlohmann::ordered_json;  // keeps the file's key order

const FileHeader kHeader{"pattern file",
                         "aapat-pattern",
                         1,
                         {"format", "version", "name", "description", "family", "tile", "footprint",
                          "sets", "kernels", "provenance"},
                         {"format", "version", "name", "tile", "footprint", "sets", "kernels"}};
constexpr int kPerLine = 4;  // samples (or 2 x weights) per line

std::string number(double v) {
  return json(v).dump();
}

[[noreturn]] void fail(std::string_view source, const std::string& message) {
  file_error(kHeader.kind, source, message);
}

double get_number(const json& v, std::string_view source, const std::string& field) {
  if (!v.is_number()) fail(source, field + ": expected a number");
  return v.get<double>();
}

}  // namespace

std::string pattern_to_json(const Pattern& p) {
  std::string out = header_json(kHeader, p.name, p.description);
  out += fmt::format("  \"family\": {},\n", json_quoted(family(p)));
  out += fmt::format("  \"tile\": [{}, {}],\n", p.tile_w, p.tile_h);
  out += fmt::format("  \"footprint\": {},\n", json_quoted(p.footprint.text()));
  out += "  \"sets\": [\n";
  for (size_t k = 0; k < p.sets.size(); ++k) {
    out += "    [";
    for (size_t i = 0; i < p.sets[k].size(); ++i) {
      if (i > 0) out += i % kPerLine == 0 ? ",\n     " : ", ";
      out += fmt::format("[{}, {}]", number(p.sets[k][i].x), number(p.sets[k][i].y));
    }
    out += k + 1 < p.sets.size() ? "],\n" : "]\n";
  }
  out += "  ],\n  \"kernels\": [\n";
  for (size_t k = 0; k < p.weights.size(); ++k) {
    out += "    [";
    for (size_t i = 0; i < p.weights[k].size(); ++i) {
      if (i > 0) out += i % (2 * kPerLine) == 0 ? ",\n     " : ", ";
      out += number(p.weights[k][i]);
    }
    out += k + 1 < p.weights.size() ? "],\n" : "]\n";
  }
  out += "  ],\n" + provenance_json(p.provenance);
  return out;
}

Pattern pattern_from_json(std::string_view text, std::string_view source) {
  json doc = parse_file(kHeader, text, source);
  Pattern p;
  std::tie(p.name, p.description) = read_name_and_description(kHeader, doc, source);
  const json& tile = doc["tile"];
  if (!tile.is_array() || tile.size() != 2 || !tile[0].is_number_integer() ||
      !tile[1].is_number_integer())
    fail(source, "tile: expected [width, height] in pixels");
  // Range-check before narrowing: a huge integer must not wrap into a valid size.
  for (int i = 0; i < 2; ++i)
    if (tile[i].get<long long>() < 0 || tile[i].get<long long>() > 1'000'000)
      fail(source, fmt::format("tile: {}x{} is not a tile size: each side must be 1 to 128 pixels",
                               tile[0].dump(), tile[1].dump()));
  p.tile_w = tile[0].get<int>();
  p.tile_h = tile[1].get<int>();
  if (!doc["footprint"].is_string()) fail(source, "footprint: expected a string such as \"1+\"");
  try {
    p.footprint = parse_footprint(doc["footprint"].get<std::string>());
  } catch (const Error& e) {
    fail(source, e.what());
  }
  const json& sets = doc["sets"];
  if (!sets.is_array()) fail(source, "sets: expected an array of sample sets");
  // Sizes before copying: validate() names the exact rule later.
  if (sets.size() > static_cast<size_t>(kMaxTileSide) * kMaxTileSide)
    fail(source, fmt::format("sets: {} sets exceed the largest tile, {}x{}", sets.size(),
                             kMaxTileSide, kMaxTileSide));
  for (size_t k = 0; k < sets.size(); ++k) {
    if (!sets[k].is_array()) fail(source, fmt::format("sets[{}]: expected an array of [x, y]", k));
    if (sets[k].size() > kMaxSamplesPerSet)
      fail(source, fmt::format("sets[{}]: {} samples exceed the limit of {} per pixel", k,
                               sets[k].size(), kMaxSamplesPerSet));
    std::vector<Vec2> set;
    for (size_t i = 0; i < sets[k].size(); ++i) {
      const json& s = sets[k][i];
      const std::string field = fmt::format("sets[{}][{}]", k, i);
      if (!s.is_array() || s.size() != 2) fail(source, field + ": expected [x, y]");
      set.push_back(
          {get_number(s[0], source, field + ".x"), get_number(s[1], source, field + ".y")});
    }
    p.sets.push_back(std::move(set));
  }
  const json& kernels = doc["kernels"];
  if (!kernels.is_array()) fail(source, "kernels: expected an array of weight lists");
  if (kernels.size() > sets.size())
    fail(source, fmt::format("kernels: {} kernels for {} sets (one per pixel)", kernels.size(),
                             sets.size()));
  for (size_t k = 0; k < kernels.size(); ++k) {
    if (!kernels[k].is_array())
      fail(source, fmt::format("kernels[{}]: expected an array of weights", k));
    if (kernels[k].size() > 16 * kMaxSamplesPerSet)
      fail(source, fmt::format("kernels[{}]: {} weights exceed what any kernel reads", k,
                               kernels[k].size()));
    std::vector<double> w;
    for (size_t i = 0; i < kernels[k].size(); ++i)
      w.push_back(get_number(kernels[k][i], source, fmt::format("kernels[{}][{}]", k, i)));
    p.weights.push_back(std::move(w));
  }
  p.provenance = read_provenance(kHeader, doc, source);
  try {
    validate(p);
  } catch (const Error& e) {
    fail(source, e.what());
  }
  if (doc.contains("family")) {
    if (!doc["family"].is_string()) fail(source, "family: expected a string such as \"P(4,1+,2)\"");
    const std::string computed = family(p);
    if (doc["family"].get<std::string>() != computed)
      fail(source, fmt::format("family: the file says {} but its samples make {}",
                               doc["family"].get<std::string>(), computed));
  }
  return p;
}

bool is_pattern_path(std::string_view path) {
  return path.ends_with(".json") || path.ends_with(".xyw");
}

Pattern load_pattern_file(const std::string& path) {
  const std::string text = read_file(path, "pattern file");
  Pattern p =
      path.ends_with(".xyw") ? pattern_from_text(text, path) : pattern_from_json(text, path);
  // A catalog name on other samples is read under the file's own name.
  const auto taken = [](std::string_view n) {
    return pattern_registry().find(n) != nullptr || in_aapat_catalog(n);
  };
  if (taken(p.name)) {
    const Pattern entry =
        in_aapat_catalog(p.name) ? aapat_catalog_pattern(p.name) : catalog_pattern(p.name);
    if (!same_samples(p, entry)) p.name = name_off_the_catalog(p.name, path, taken, "pattern file");
  }
  return p;
}

void save_pattern_file(const Pattern& p, const std::string& path) {
  validate(p);
  write_file_atomically(path, path.ends_with(".xyw") ? pattern_to_text(p) : pattern_to_json(p));
}

Pattern resolve_pattern(const std::string& name_or_path) {
  std::error_code ec;
  if (std::filesystem::is_directory(name_or_path, ec))
    throw Error(fmt::format("pattern '{}': it is a folder, not a pattern file", name_or_path));
  if (is_pattern_path(name_or_path) || std::filesystem::is_regular_file(name_or_path, ec))
    return load_pattern_file(name_or_path);
  return named_pattern(name_or_path);
}

Pattern named_pattern(const std::string& name_or_path) {
  if (in_aapat_catalog(name_or_path)) return aapat_catalog_pattern(name_or_path);
  if (pattern_registry().find(name_or_path) || name_or_path.starts_with("grid-"))
    return catalog_pattern(name_or_path);
  // Neither: name both catalogs, and the nearest name of either.
  std::vector<std::string> names, free;
  for (const auto& e : pattern_registry().entries()) names.push_back(e.info.name);
  for (const SpecInfo& e : aapat_catalog()) {
    names.push_back(e.name);
    // The free designs: no API profile's name as a suffix (aapat-8, not aapat-8-vulkan).
    const auto& profiles = profile_registry().entries();
    if (std::none_of(profiles.begin(), profiles.end(),
                     [&](const auto& p) { return e.name.ends_with("-" + p.info.name); }))
      free.push_back(e.name);
  }
  throw Error(fmt::format(
      "unknown pattern '{}'{}: not a pattern file, a catalog name ({}) nor an aapat catalog "
      "name ({}; each also on an API's lattice, e.g. aapat-8-d3d12-tier1; `aapat list`)",
      name_or_path, did_you_mean(name_or_path, names), pattern_registry().names(),
      fmt::join(free, ", ")));
}

}  // namespace aapat

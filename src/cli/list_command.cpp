// `aapat list`: every registry of specs (core/spec.h), one line per entry:
// the catalog patterns, filters, point generators, acuity tables, scenes and
// API profiles, with their parameters and defaults.
#include <fmt/format.h>

#include <memory>
#include <ostream>

#include "aapat/core/acuity.h"
#include "aapat/core/filter_catalog.h"
#include "aapat/core/hardware_layout.h"
#include "aapat/core/objective.h"
#include "aapat/generate/catalog.h"
#include "aapat/generate/point_generators.h"
#include "aapat/io/aapat_catalog.h"
#include "aapat/io/json_report.h"
#include "aapat/render/scene.h"
#include "aapat/render/texture_filter.h"
#include "aapat/temporal/sequence_generators.h"
#include "aapat/temporal/sequence_json.h"
#include "cli/commands.h"

namespace aapat {
namespace {

// One registry's section: a heading and its entries' infos.
struct Section {
  std::string key, heading;
  std::vector<SpecInfo> infos;
};

template <class R>
Section section(std::string key, std::string heading, const R& registry) {
  Section s{std::move(key), std::move(heading), {}};
  for (const auto& e : registry.entries()) s.infos.push_back(e.info);
  return s;
}

std::vector<Section> sections() {
  Section aapat{"aapat_patterns",
                "the aapat catalog (data/patterns: the best found per budget and API, "
                "docs/catalog.md)",
                aapat_catalog()};
  return {
      Section{"objectives",
              "objectives (--objective; or 'filter=F acuity=A norm=P', starting from "
              "recommended)",
              objective_infos()},
      section("patterns", "patterns", pattern_registry()),
      aapat,
      section("filters", "filters", filter_registry()),
      section("generators", "point generators (aapat generate, spectrum, discrepancy)",
              generator_registry()),
      section("acuity_tables", "acuity tables (or a CSV file of 'edge_angle_deg,weight' rows)",
              acuity_registry()),
      section("scenes", "scenes (aapat render; or a .json scene file, docs/renderer.md)",
              scene_registry()),
      section("textures", "textures (aapat render --texture; or a .png file)", texture_registry()),
      section("texture_filters", "texture filters (aapat render --texture-filter)",
              texture_filter_registry()),
      section("api_profiles", "API profiles (aapat export --api, optimize --api)",
              profile_registry()),
      section("sequences",
              "sequences (aapat sequence, animate --sequence; or a .json sequence file)",
              sequence_registry()),
      Section{"aapat_sequences", "optimized sequences (data/sequences, docs/temporal.md)",
              sequence_catalog()}};
}

JsonObject info_json(const SpecInfo& info) {
  JsonObject params = JsonObject::array();
  for (const ParamInfo& p : info.params)
    params.push_back(
        {{"key", p.key},
         {"default", p.default_text.empty() ? JsonObject() : JsonObject(p.default_text)},
         {"meaning", p.meaning}});
  return {{"name", info.name},
          {"usage", info.usage()},
          {"summary", info.summary},
          {"source", info.source},
          {"parameters", params}};
}

// "spiral:turns=6,arm=0.35", or the family beside a catalog pattern's name.
std::string entry_line(const Section& s, const SpecInfo& info) {
  if (s.key == "patterns") {
    const std::string fam =
        info.name == "grid-NxN" ? "P(1,1,N*N)" : family(catalog_pattern(info.name));
    return fmt::format("  {:<20} {:<13} {} [{}]\n", info.name, fam, info.summary, info.source);
  }
  std::string line = fmt::format("  {:<34} {} [{}]\n", info.usage(), info.summary, info.source);
  for (const ParamInfo& p : info.params)
    line += fmt::format("      {:<10} {}{}\n", p.key, p.meaning,
                        p.default_text.empty() ? "" : fmt::format(" ({})", p.default_text));
  return line;
}

}  // namespace

Action add_list_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "list",
      "list the catalog patterns, filters, generators, acuity tables, scenes and API profiles");
  auto json = std::make_shared<bool>(false);
  cmd->add_flag("--json", *json, "print the registries as JSON (docs/json.md)");
  return [json](std::ostream& out) {
    if (*json) {
      JsonObject doc = json_report("list");
      for (const Section& s : sections()) {
        JsonObject entries = JsonObject::array();
        for (const SpecInfo& info : s.infos) entries.push_back(info_json(info));
        doc[s.key] = std::move(entries);
      }
      out << json_text(doc);
      return;
    }
    for (const Section& s : sections()) {
      out << s.heading << ":\n";
      for (const SpecInfo& info : s.infos) out << entry_line(s, info);
    }
  };
}

}  // namespace aapat

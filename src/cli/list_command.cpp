// `aapat list`: the catalog, the filters and the acuity tables, one line each.
#include <fmt/format.h>

#include <memory>
#include <ostream>

#include "aapat/core/acuity.h"
#include "aapat/core/filter_catalog.h"
#include "aapat/generate/catalog.h"
#include "aapat/generate/point_generators.h"
#include "aapat/io/json_report.h"
#include "aapat/render/scene.h"
#include "cli/commands.h"

namespace aapat {

Action add_list_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "list", "list the catalog patterns, filters, generators, acuity tables and scenes");
  auto json = std::make_shared<bool>(false);
  cmd->add_flag("--json", *json, "print the catalogs as JSON (docs/json.md)");
  return [json](std::ostream& out) {
    if (*json) {
      JsonObject doc = json_report("list");
      JsonObject patterns = JsonObject::array(), filters = JsonObject::array(),
                 generators = JsonObject::array(), acuity = JsonObject::array(),
                 scenes = JsonObject::array();
      for (const auto& e : pattern_catalog())
        patterns.push_back({{"name", e.name}, {"summary", e.summary}, {"source", e.source}});
      for (const auto& f : filter_catalog()) {
        JsonObject params = JsonObject::array();
        for (const auto& p : f.params)
          params.push_back({{"key", p.key}, {"default", p.default_text}, {"meaning", p.meaning}});
        filters.push_back({{"name", f.name},
                           {"summary", f.summary},
                           {"source", f.source},
                           {"parameters", params}});
      }
      for (const auto& g : generator_catalog())
        generators.push_back({{"spec", g.spec}, {"summary", g.summary}, {"source", g.source}});
      for (const auto& a : acuity_catalog())
        acuity.push_back({{"spec", a.spec}, {"summary", a.summary}});
      for (const auto& s : scene_catalog())
        scenes.push_back({{"name", s.name}, {"parameters", s.parameters}, {"summary", s.summary}});
      doc.update(JsonObject{{"patterns", patterns},
                            {"filters", filters},
                            {"generators", generators},
                            {"acuity_tables", acuity},
                            {"scenes", scenes}});
      out << json_text(doc);
      return;
    }
    out << "patterns:\n";
    for (const auto& e : pattern_catalog()) {
      const std::string fam = e.name == "grid-NxN" ? "P(1,1,N*N)" : family(catalog_pattern(e.name));
      out << fmt::format("  {:<20} {:<13} {} [{}]\n", e.name, fam, e.summary, e.source);
    }
    out << "filters:\n";
    for (const auto& f : filter_catalog()) {
      std::string params;
      for (const auto& p : f.params)
        params += fmt::format("{}{}={}", params.empty() ? ":" : ",", p.key, p.default_text);
      out << fmt::format("  {:<34} {} [{}]\n", f.name + params, f.summary, f.source);
    }
    out << "point generators (aapat generate, spectrum, discrepancy):\n";
    for (const auto& g : generator_catalog())
      out << fmt::format("  {:<27} {} [{}]\n", g.spec, g.summary, g.source);
    out << "acuity tables:\n";
    for (const auto& a : acuity_catalog()) out << fmt::format("  {:<27} {}\n", a.spec, a.summary);
    out << "scenes (aapat render; or a .json scene file, docs/renderer.md):\n";
    for (const auto& s : scene_catalog())
      out << fmt::format("  {:<27} {}\n",
                         s.parameters.empty() ? s.name : s.name + ":" + s.parameters, s.summary);
  };
}

}  // namespace aapat

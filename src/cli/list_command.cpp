// `aapat list`: every registry of specs and catalog (registry/spec_registries.h),
// one line per entry, with their parameters and defaults; --json as Python's
// aapat.registry().
#include <fmt/format.h>

#include <memory>
#include <ostream>

#include "aapat/generate/catalog.h"
#include "aapat/io/json_report.h"
#include "aapat/registry/spec_registries.h"
#include "cli/commands.h"
#include "cli/option_modes.h"

namespace aapat {
namespace {

using Section = RegistrySection;

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
      "list the catalog patterns, filters, generators, acuity tables, scenes, API profiles, "
      "motions, sequences and TAA presets");
  auto json = std::make_shared<bool>(false), modes = std::make_shared<bool>(false);
  auto* json_flag = cmd->add_flag("--json", *json, "print the registries as JSON (docs/json.md)");
  cmd->add_flag("--modes", *modes,
                "print instead which options apply in which mode of animate, render and "
                "optimize, as markdown (docs/cli.md)")
      ->excludes(json_flag);
  return [json, modes](std::ostream& out) {
    if (*modes) {
      out << option_modes_markdown();
      return;
    }
    if (*json) {
      JsonObject doc = json_report("list");
      doc.update(registry_json());
      out << json_text(doc);
      return;
    }
    for (const Section& s : registry_sections()) {
      out << s.heading << ":\n";
      for (const SpecInfo& info : s.infos) out << entry_line(s, info);
    }
  };
}

}  // namespace aapat

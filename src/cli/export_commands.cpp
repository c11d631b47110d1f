// `aapat export` and `aapat import`: a lattice pattern as an API's sample
// position arrays and a resolve shader, and such a file read back as a pattern.
#include <fmt/format.h>

#include <memory>
#include <nlohmann/json.hpp>
#include <ostream>
#include <tuple>

#include "aapat/core/filter_catalog.h"
#include "aapat/core/hardware_layout.h"
#include "aapat/core/lattice.h"
#include "aapat/io/api_export.h"
#include "aapat/io/atomic_file.h"
#include "aapat/io/json_report.h"
#include "aapat/io/pattern_json.h"
#include "aapat/study/pattern_studies.h"
#include "cli/commands.h"
#include "cli/metric_options.h"

namespace aapat {

Action add_export_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "export", "write a lattice pattern as API sample positions and a resolve shader");
  struct Options {
    std::string pattern, api = "d3d12-tier1", shader, output, grid;
    MetricOptions metric;
    bool snap = false;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("pattern", o->pattern, "catalog name or pattern file (on the 1/16 lattice)")
      ->required();
  cmd->add_option("--api", o->api, "d3d12-tier1, d3d12-tier2, vulkan, metal or gl")
      ->capture_default_str();
  cmd->add_option("--shader", o->shader, "hlsl, glsl or msl (default: the API's own)");
  cmd->add_option("--grid", o->grid, "pixel grid WxH (vulkan, gl; default: the pattern's tile)");
  cmd->add_flag("--snap", o->snap, "snap the pattern to the lattice first");
  o->metric.add_to(cmd);
  cmd->add_option("-o,--output", o->output, "write here instead of printing");
  return [o](std::ostream& out) {
    const ApiProfile& profile = api_profile(o->api);
    const Objective objective = o->metric.resolve();
    const Pattern original = resolve_pattern(o->pattern);
    int gw = 0, gh = 0;
    if (!o->grid.empty()) {
      std::tie(gw, gh) = parse_size(o->grid, "--grid", profile.max_grid);
      check_export_grid(profile, gw, gh, "--grid");
    }
    const std::string text = export_pattern(
        original, profile, objective,
        o->shader.empty() ? default_shader(profile) : parse_shader_language(o->shader), o->snap, gw,
        gh);
    if (o->output.empty()) {
      out << text;
    } else {
      write_file_atomically(o->output, text);
      out << "wrote " << o->output << "\n";
    }
  };
}

Action add_import_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("import", "read an exported layout back as a pattern file");
  struct Options {
    std::string input, output;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("file", o->input, "a file written by aapat export")->required();
  cmd->add_option("-o,--output", o->output, "the pattern (.json; default: print it)");
  return [o](std::ostream& out) {
    const HardwareLayout L = parse_export(read_file(o->input, "export"), o->input);
    Pattern p;
    try {
      p = pattern_from_layout(L);
    } catch (const Error& e) {
      throw Error(fmt::format("import {}: {}", o->input, e.what()));
    }
    p.provenance = {{"imported", o->input}, {"profile", L.profile}};
    if (o->output.empty()) {
      out << pattern_to_json(p);
    } else {
      if (!is_pattern_path(o->output))
        throw Error(fmt::format("--output: '{}' must end in .json or .xyw", o->output));
      save_pattern_file(p, o->output);
      out << "wrote " << o->output << "\n";
    }
  };
}

}  // namespace aapat

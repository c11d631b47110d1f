// `aapat generate`: a point set from a generator, to stdout or a point file
// in any format, several realizations at once, or a pixel pattern.
#include <fmt/format.h>

#include <memory>
#include <ostream>

#include "aapat/generate/point_generators.h"
#include "aapat/io/json_report.h"
#include "aapat/io/pattern_json.h"
#include "aapat/io/point_set_file.h"
#include "cli/commands.h"
#include "cli/point_options.h"
#include "cli/progress.h"

namespace aapat {
namespace {

// Writes the points (or, with --sets K, K realizations) of `src` to a point
// file or, for .json / .xyw, a one-pixel pattern.
void write_generated(const PointOptions& src, const std::string& output, int sets,
                     std::ostream& out) {
  if (is_pattern_path(output)) {
    if (sets > 1)
      throw Error("--sets: a pattern file holds one pixel's points; write a .dat or .bin");
    const auto points = src.points();
    Pattern p = points_to_pattern(
        points, fmt::format("{}-{}", src.source.substr(0, src.source.find(':')), points.size()));
    p.description = fmt::format("{} points from {}", points.size(), src.source);
    p.provenance = {{"generator", src.source},
                    {"n", std::to_string(points.size())},
                    {"seed", std::to_string(src.seed)}};
    save_pattern_file(p, output);
    out << fmt::format("wrote {} ({} points, {})\n", output, points.size(), family(p));
    return;
  }
  PointSets all;
  {
    Progress bar(sets > 1 ? "sets" : "points");
    all = generate_point_sets(src.source, src.n, src.seed, sets, bar.callback());
  }
  save_point_sets(all, output, src.format);
  out << fmt::format("wrote {} ({} points{})\n", output, all[0].size(),
                     sets > 1 ? fmt::format(" in each of {} sets", sets) : "");
}

}  // namespace

Action add_generate_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("generate", "generate a point set or a pixel pattern");
  auto src = std::make_shared<PointOptions>();
  auto output = std::make_shared<std::string>();
  auto tile = std::make_shared<int>(0);
  auto sets = std::make_shared<int>(1);
  auto json = std::make_shared<bool>(false);
  src->add_to(cmd);
  cmd->add_flag("--json", *json, "print the points as JSON (docs/json.md) instead of CSV");
  cmd->add_option("-o,--output", *output,
                  "a point file (.csv, .dat, .bin, .psa, .f32 or --format) or a pattern (.json, "
                  ".xyw: P(1,1,n)); default: CSV on stdout");
  cmd->add_option("--sets", *sets, "realizations (seeds seed, seed+1, ...) into a .dat or .bin")
      ->capture_default_str()
      ->check(CLI::Range(1, kMaxPointSets));
  cmd->add_option(
      "--tile", *tile,
      "with a .json output: a K x K tile of pixel sets, each generated anew: P(K^2,1,n)");
  return [src, output, tile, sets, json](std::ostream& out) {
    if (src->is_file()) throw Error("generate: give a generator, not a file");
    if (*json && !output->empty())
      throw Error("--json prints the points; it does not go with -o (the file has them)");
    if (*tile > 0) {
      if (!output->ends_with(".json"))
        throw Error("--tile: write the tile as a pattern file (-o file.json)");
      Pattern p = tile_pattern(src->source, src->n, src->seed, *tile);
      p.description = fmt::format("{} x {} tile of {} points per pixel from {}", *tile, *tile,
                                  src->n, src->source);
      p.provenance = {{"generator", src->source},
                      {"n", std::to_string(src->n)},
                      {"seed", std::to_string(src->seed)},
                      {"tile", std::to_string(*tile)}};
      save_pattern_file(p, *output);
      out << fmt::format("wrote {} ({})\n", *output, family(p));
      return;
    }
    if (!output->empty() && *output != "-") return write_generated(*src, *output, *sets, out);
    const auto points = src->points();
    if (!*json) {
      out << format_point_sets(
          {points}, src->format.empty() ? PointFormat::kCsv : point_format("", src->format));
      return;
    }
    JsonObject doc = json_report("generate");
    doc.update(JsonObject{{"source", src->source}, {"n", points.size()}, {"seed", src->seed}});
    JsonObject rows = JsonObject::array();
    for (const Vec2& v : points) rows.push_back({{"x", v.x}, {"y", v.y}});
    doc["rows"] = std::move(rows);
    out << json_text(doc);
  };
}

}  // namespace aapat

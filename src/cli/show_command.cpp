// `aapat show PATTERN [-o file.svg|file.json]`: samples, family, cost, drawing.
#include <fmt/format.h>

#include <memory>
#include <ostream>

#include "aapat/io/json_report.h"
#include "aapat/io/pattern_json.h"
#include "aapat/io/pattern_svg.h"
#include "cli/commands.h"

namespace aapat {

Action add_show_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("show", "print a pattern's samples, family and cost n");
  auto pattern = std::make_shared<std::string>();
  auto output = std::make_shared<std::string>();
  auto json = std::make_shared<bool>(false);
  cmd->add_option("pattern", *pattern, "catalog name or pattern file (.json)")->required();
  cmd->add_option("-o,--output", *output,
                  "write the drawing (.svg) or the pattern file (.json); - for stdout");
  cmd->add_flag("--json", *json, "print the pattern's family, n and file content as JSON");
  return [=](std::ostream& out) {
    const Pattern p = resolve_pattern(*pattern);
    if (!output->empty()) {
      if (output->ends_with(".svg"))
        write_output(*output, pattern_svg(p), out);
      else if (output->ends_with(".json") || *output == "-")
        write_output(*output, pattern_to_json(p), out);
      else
        throw Error(fmt::format("--output: '{}' must end in .svg or .json", *output));
      if (*output == "-") return;
    }
    if (*json) {
      JsonObject doc = json_report("show");
      doc.update(JsonObject{{"name", p.name},
                            {"family", family(p)},
                            {"n", samples_per_pixel(p)},
                            {"pattern", JsonObject::parse(pattern_to_json(p))}});
      out << json_text(doc);
      return;
    }
    out << fmt::format("{}  {}  n = {}  tile {}x{}  footprint {}\n", p.name, family(p),
                       format_cost(samples_per_pixel(p)), p.tile_w, p.tile_h, p.footprint.text());
    if (!p.description.empty()) out << "  " << p.description << "\n";
    for (const auto& [key, value] : p.provenance) out << fmt::format("  {}: {}\n", key, value);
    for (int k = 0; k < p.set_count(); ++k) {
      out << fmt::format("set {} (pixel {},{}):\n", k, k % p.tile_w, k / p.tile_w);
      for (const Vec2& s : p.sets[k])
        out << fmt::format("  {:>10.6f} {:>10.6f}  {}\n", s.x, s.y, site_name(s));
    }
    for (int k = 0; k < p.set_count(); ++k) {
      out << fmt::format("kernel {} weights:", k);
      for (double w : p.weights[k]) out << fmt::format(" {:.6g}", w);
      out << "\n";
    }
    if (!output->empty()) out << "wrote " << *output << "\n";
  };
}

}  // namespace aapat

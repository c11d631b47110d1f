// `aapat limits`: every limit aapat checks (registry/limits_table.h), as text,
// --json (Python's aapat.limits()) or --markdown (docs/limits.md's table).
#include <fmt/format.h>

#include <memory>
#include <ostream>

#include "aapat/registry/limits_table.h"
#include "cli/commands.h"

namespace aapat {

Action add_limits_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "limits", "every limit aapat checks (sizes, counts, threads, files), on every face");
  auto json = std::make_shared<bool>(false), markdown = std::make_shared<bool>(false);
  auto* json_flag = cmd->add_flag("--json", *json, "print the table as JSON (docs/json.md)");
  cmd->add_flag("--markdown", *markdown, "print the table of docs/limits.md")->excludes(json_flag);
  return [json, markdown](std::ostream& out) {
    if (*json) {
      JsonObject doc = json_report("limits");
      doc.update(limits_json());
      out << json_text(doc);
    } else if (*markdown) {
      out << limits_markdown();
    } else {
      for (const Limit& l : limits_table())
        out << fmt::format("{}\n    {}\n    ({})\n", l.what, l.limit, l.defined);
    }
  };
}

}  // namespace aapat

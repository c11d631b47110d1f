#include "cli/app.h"

#include <ostream>

#include "cli/commands.h"
#include "core/geometry.h"
#include "io/atomic_file.h"

namespace aapat {

void write_output(const std::string& path, const std::string& content, std::ostream& out) {
  if (path == "-") {
    out << content;
  } else {
    write_file_atomically(path, content);
  }
}

int run_aapat(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
  CLI::App app{
      "aapat: design antialiasing sample patterns (Laine-Aila E2 metric, Hasselgren schemes)",
      "aapat"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "aapat 0.1.0");
  std::vector<std::pair<CLI::App*, Action>> commands;
  auto add = [&](auto adder) {
    const size_t before = app.get_subcommands({}).size();
    Action action = adder(app);
    commands.emplace_back(app.get_subcommands({})[before], std::move(action));
  };
  add(add_list_command);
  add(add_show_command);
  add(add_eval_command);
  add(add_optimize_command);
  add(add_table3_command);
  add(add_figure10_command);
  add(add_enumerate_command);
  add(add_generate_command);
  add(add_discrepancy_command);
  add(add_spectrum_command);
  add(add_render_command);
  add(add_animate_command);
  add(add_table2_command);
  add(add_snap_command);
  add(add_export_command);
  add(add_import_command);
  add(add_hardware_table_command);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e, out, err);
  }
  try {
    for (auto& [sub, action] : commands)
      if (sub->parsed()) action(out);
  } catch (const Error& e) {
    err << "aapat: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace aapat

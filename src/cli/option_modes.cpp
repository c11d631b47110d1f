#include "cli/option_modes.h"

#include <fmt/format.h>

#include <algorithm>
#include <mutex>
#include <stdexcept>

#include "cli/commands.h"

namespace aapat {
namespace {

std::mutex tables_lock;
std::vector<OptionModes>& tables() {
  static std::vector<OptionModes> t;
  return t;
}

bool listed(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

// The modes an option applies in, for the message: "a pattern (--pattern) or
// temporal accumulation (--sequence)".
std::string modes_taking(const OptionModes& table, const std::string& name) {
  std::vector<std::string> in;
  for (const OptionMode& m : table.modes)
    if (listed(m.options, name)) in.push_back(m.name);
  return fmt::format("{}", fmt::join(in, " or "));
}

}  // namespace

void enforce_option_modes(CLI::App* cmd, const OptionModes& table, std::function<size_t()> choose) {
  for (const CLI::Option* o : cmd->get_options()) {
    const std::string name = o->get_single_name();
    if (!o->nonpositional() || name == "help") continue;
    bool known = listed(table.shared, name);
    for (const OptionMode& m : table.modes) known = known || listed(m.options, name);
    if (!known)
      throw std::logic_error(fmt::format(
          "{}: --{} is in no mode of its option table (cli/option_modes.h)", table.command, name));
  }
  {
    std::lock_guard<std::mutex> hold(tables_lock);
    auto& t = tables();
    const auto same = [&](const OptionModes& x) { return x.command == table.command; };
    t.erase(std::remove_if(t.begin(), t.end(), same), t.end());
    t.push_back(table);
  }
  cmd->parse_complete_callback([cmd, table, choose] {
    const OptionMode& mode = table.modes.at(choose());
    for (const CLI::Option* o : cmd->get_options()) {
      const std::string name = o->get_single_name();
      if (!o->nonpositional() || o->count() == 0 || name == "help") continue;
      if (listed(table.shared, name) || listed(mode.options, name)) continue;
      const auto instead = mode.instead.find(name);
      throw CLI::ValidationError(
          "--" + name,
          fmt::format("does not apply in {}, which would ignore it{}", mode.name,
                      instead != mode.instead.end()
                          ? "; " + instead->second
                          : fmt::format(" (it belongs to {})", modes_taking(table, name))));
    }
  });
}

std::string option_modes_markdown() {
  std::string md;
  for (const OptionModes& t : all_option_mode_tables()) {
    md += fmt::format("`aapat {}`: in every mode --{}; the mode is chosen by --{}.\n\n", t.command,
                      fmt::join(t.shared, ", --"), fmt::join(t.selectors, ", --"));
    md += "| option |";
    for (const OptionMode& m : t.modes) md += " " + m.name + " |";
    md += "\n| --- |";
    for (size_t k = 0; k < t.modes.size(); ++k) md += " --- |";
    md += "\n";
    std::vector<std::string> names;
    for (const OptionMode& m : t.modes)
      for (const std::string& o : m.options)
        if (!listed(names, o) && !listed(t.shared, o)) names.push_back(o);
    std::sort(names.begin(), names.end());
    for (const std::string& o : names) {
      md += "| --" + o + " |";
      for (const OptionMode& m : t.modes) {
        if (listed(m.options, o)) {
          md += " yes |";
          continue;
        }
        if (listed(t.selectors, o)) {
          md += " chooses another mode |";
          continue;
        }
        const auto instead = m.instead.find(o);
        md += instead != m.instead.end() ? " refused: " + instead->second + " |" : " refused |";
      }
      md += "\n";
    }
    md += "\n";
  }
  return md;
}

const std::vector<OptionModes>& option_mode_tables() {
  std::lock_guard<std::mutex> hold(tables_lock);
  return tables();
}

std::vector<OptionModes> all_option_mode_tables() {
  CLI::App scratch;
  add_animate_command(scratch);
  add_render_command(scratch);
  add_optimize_command(scratch);
  std::lock_guard<std::mutex> hold(tables_lock);
  return tables();
}

}  // namespace aapat

// Every (mode, option) pair of every command's option table: an option the
// mode would ignore is a usage error (exit 2) that names the option and the
// mode, before any work; and every option of a command is in its table.
#include "cli/option_modes.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>

#include "cli/commands.h"
#include "testing/cli_run.h"

namespace aapat {
namespace {

using testing::run;

// A value each option's own parser accepts (the refusal must be the mode's).
std::string value_for(const std::string& name) {
  static const std::map<std::string, std::string> special = {
      {"model", "box"}, {"method", "descent"}, {"frame-measure", "worst"}};
  const auto it = special.find(name);
  return it != special.end() ? it->second : "2";
}

bool in(const std::vector<std::string>& list, const std::string& name) {
  return std::find(list.begin(), list.end(), name) != list.end();
}

TEST(OptionModes, EveryOptionAModeIgnoresIsRefusedNamingTheMode) {
  const std::vector<OptionModes> tables = all_option_mode_tables();
  ASSERT_GE(tables.size(), 3u);
  int pairs = 0;
  for (const OptionModes& t : tables) {
    CLI::App scratch;
    add_animate_command(scratch);
    add_render_command(scratch);
    add_optimize_command(scratch);
    const CLI::App* cmd = scratch.get_subcommand(t.command);
    for (const OptionMode& m : t.modes) {
      // The example is in its mode: it parses (whatever the run then says).
      std::vector<std::string> base = {t.command};
      base.insert(base.end(), m.example.begin(), m.example.end());
      for (const CLI::Option* o : cmd->get_options()) {
        const std::string name = o->get_single_name();
        if (!o->nonpositional() || name == "help" || in(t.shared, name) || in(m.options, name) ||
            in(t.selectors, name))
          continue;
        std::vector<std::string> args = base;
        args.push_back("--" + name);
        if (o->get_type_size() != 0) args.push_back(value_for(name));
        const testing::CliRun r = run(args);
        EXPECT_EQ(r.code, 2) << fmt::format("{} --{} in {}: {}", t.command, name, m.name, r.err);
        EXPECT_NE(r.err.find("--" + name + ": does not apply in " + m.name), std::string::npos)
            << "expected --" << name << " in " << m.name << ": " << r.err;
        ++pairs;
      }
    }
  }
  EXPECT_GT(pairs, 100);  // the tables refuse something in every mode
}

// The options a mode takes are not refused: each mode's example with each of
// its own options parses past the table (it may fail later for other reasons,
// but never with the table's message).
TEST(OptionModes, AnOptionItsModeTakesIsNotRefused) {
  for (const OptionModes& t : all_option_mode_tables())
    for (const OptionMode& m : t.modes)
      for (const std::string& name : m.options) {
        std::vector<std::string> args = {t.command};
        args.insert(args.end(), m.example.begin(), m.example.end());
        if (std::find(args.begin(), args.end(), "--" + name) != args.end()) continue;
        args.push_back("--" + name);
        CLI::App scratch;
        add_animate_command(scratch);
        add_render_command(scratch);
        add_optimize_command(scratch);
        const CLI::Option* o = scratch.get_subcommand(t.command)->get_option("--" + name);
        if (o->get_type_size() != 0) args.push_back(value_for(name));
        args.push_back("--help");  // parse, then print help: nothing is run
        const testing::CliRun r = run(args);
        EXPECT_EQ(r.err.find("does not apply in"), std::string::npos)
            << t.command << " --" << name << " in " << m.name << ": " << r.err;
      }
}

}  // namespace
}  // namespace aapat

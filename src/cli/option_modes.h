// Which options apply in which mode of a command: one table per command, so
// that an option the chosen mode would ignore is a usage error (exit 2)
// before any work, naming the option, the mode and what to give instead
// (`animate --taa fsr2 --alpha 0.2`: the preset's blend is --taa-set alpha=).
// The command property test tries every (mode, option) pair of every table.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace aapat {

struct OptionMode {
  std::string name;                  // "the engine TAA mode (--taa)", as messages name it
  std::vector<std::string> options;  // long names, without "--", that apply in it
  // What to give instead of an option that does not apply, by its long name.
  std::map<std::string, std::string> instead;
  // A command line in this mode (after the command word), for the property test.
  std::vector<std::string> example;
};

struct OptionModes {
  std::string command;              // "animate", "sequence pan"
  std::vector<std::string> shared;  // long names that apply in every mode
  std::vector<OptionMode> modes;
  // The options whose presence chooses the mode (given, they change it
  // rather than being ignored in it).
  std::vector<std::string> selectors;
};

// Installs the table on `cmd`: once parsing completes, `choose` names the
// mode (an index into table.modes) and every option given that neither the
// mode nor `shared` lists is refused with CLI::ValidationError. Every option
// of `cmd` must be in the table somewhere (a logic error otherwise, so that a
// new option is classified when it is added).
void enforce_option_modes(CLI::App* cmd, const OptionModes& table, std::function<size_t()> choose);

// Every table installed so far in this process (the property test reads them).
const std::vector<OptionModes>& option_mode_tables();

// The tables of the commands that have modes, installed on a scratch app:
// what the property test and the docs read.
std::vector<OptionModes> all_option_mode_tables();

// Every table as markdown, one per command: a row per option that some mode
// refuses, "yes" where it applies and what to give instead where it does not
// (`aapat list --modes`, docs/cli.md).
std::string option_modes_markdown();

}  // namespace aapat

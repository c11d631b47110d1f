// Each subcommand registers its options on the CLI11 app and returns the
// action to run once parsing succeeded.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <iosfwd>

namespace aapat {

using Action = std::function<void(std::ostream& out)>;

Action add_list_command(CLI::App& app);
Action add_limits_command(CLI::App& app);
Action add_show_command(CLI::App& app);
Action add_eval_command(CLI::App& app);
Action add_optimize_command(CLI::App& app);
Action add_table3_command(CLI::App& app);
Action add_figure10_command(CLI::App& app);
Action add_enumerate_command(CLI::App& app);
Action add_generate_command(CLI::App& app);
Action add_discrepancy_command(CLI::App& app);
Action add_spectrum_command(CLI::App& app);
Action add_render_command(CLI::App& app);
Action add_animate_command(CLI::App& app);
Action add_table2_command(CLI::App& app);
Action add_snap_command(CLI::App& app);
Action add_refine_command(CLI::App& app);
Action add_export_command(CLI::App& app);
Action add_import_command(CLI::App& app);
Action add_hardware_table_command(CLI::App& app);
Action add_study_command(CLI::App& app);
Action add_sequence_command(CLI::App& app);
Action add_diff_command(CLI::App& app);

// `aapat sequence compare` and `aapat sequence search` (rendered_sequence_commands.cpp),
// subcommands of `sequence`.
void add_sequence_compare(CLI::App* parent, std::function<void(std::ostream&)>& action);
void add_sequence_search(CLI::App* parent, std::function<void(std::ostream&)>& action);

// --seed: a whole number from 0 to 2^64 - 1; "-1" is refused, not wrapped.
CLI::Option* add_seed_option(CLI::App* cmd, uint64_t& seed, const std::string& help);

// Writes `content` to `path` whole or not at all; "-" writes to `out`.
void write_output(const std::string& path, const std::string& content, std::ostream& out);

}  // namespace aapat

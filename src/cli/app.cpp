#include "cli/app.h"

#include <fmt/format.h>

#include <tbb/global_control.h>
#include <tbb/info.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <set>
#include <stdexcept>
#include <string_view>

#include "aapat/core/geometry.h"
#include "aapat/core/hash.h"
#include "aapat/core/nearest_name.h"
#include "aapat/core/read_file.h"
#include "aapat/core/text.h"
#include "aapat/io/atomic_file.h"
#include "aapat/version.h"
#include "aapat/work/checkpoint.h"
#include "aapat/work/work_items.h"
#include "cli/commands.h"
#include "cli/progress.h"

namespace aapat {
namespace {

std::ostream* g_warnings = nullptr;

// The message of the exception in flight, whatever its type: library errors
// as they are, the rest named for what they mean to a user.
std::string describe_current_exception_whole() {
  try {
    throw;
  } catch (const ParameterError& e) {
    // The library names its parameter as the flag that gives it is named
    // (family, placement, size, measure, ...): here it is reported as that flag.
    return "--" + e.parameter() + e.detail();
  } catch (const Error& e) {
    return e.what();
  } catch (const std::bad_alloc&) {
    return "out of memory: the job is too large for this machine (see docs/limits.md)";
  } catch (const std::filesystem::filesystem_error& e) {
    return fmt::format("file system: {}", e.what());
  } catch (const nlohmann::json::exception& e) {
    return fmt::format("JSON: {}", e.what());
  } catch (const std::exception& e) {
    return fmt::format("internal error ({}); please report it", e.what());
  } catch (...) {
    return "internal error (unknown exception); please report it";
  }
}

// The message as the terminal shows it: a huge argument echoed is cut.
std::string describe_current_exception() {
  return shortened_message(describe_current_exception_whole());
}

}  // namespace

std::ostream& warnings() {
  return g_warnings ? *g_warnings : std::cerr;
}

CLI::Option* add_seed_option(CLI::App* cmd, uint64_t& seed, const std::string& help) {
  return cmd->add_option("--seed", seed, help)
      ->capture_default_str()
      ->check(CLI::Validator(
          [](const std::string& text) {
            const bool digits =
                !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
            // Compared as text: a larger number would be clamped to 2^64 - 1 on conversion.
            const std::string most = "18446744073709551615";
            const std::string_view value = std::string_view(text).substr(
                std::min(text.find_first_not_of('0'), text.size() - (text.empty() ? 0 : 1)));
            const bool fits =
                value.size() < most.size() || (value.size() == most.size() && value <= most);
            return digits && fits
                       ? std::string()
                       : "a seed is a whole number from 0 to 2^64 - 1, not '" + text + "'";
          },
          "UINT64"));
}

void write_output(const std::string& path, const std::string& content, std::ostream& out) {
  if (path == "-") {
    out << content;
  } else {
    write_file_atomically(path, content);
  }
}

namespace {

// An argument as a shell would need it quoted, so that the joined command
// line is unambiguous: `--csv 'a.csv --seed 2'` is not `--csv a.csv --seed 2`.
std::string shell_quoted(std::string_view arg) {
  if (!arg.empty() && arg.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                            "0123456789-_=.,:/+@%()") == std::string_view::npos)
    return std::string(arg);
  std::string quoted = "'";
  for (char c : arg) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

// What a file argument holds, so that a checkpoint of a command that reads it
// does not resume after the file changed: its size and checksum64, or ""
// for an argument that is not a readable regular file.
std::string file_digest(std::string_view arg) {
  if (const size_t eq = arg.find('='); arg.starts_with("--") && eq != std::string_view::npos)
    arg = arg.substr(eq + 1);  // --acuity=table.csv
  std::error_code e;
  const std::string path(arg);
  if (arg.empty() || !std::filesystem::is_regular_file(path, e)) return "";
  try {
    const std::string bytes = read_file(path, "input file");
    return fmt::format(" [{} bytes, checksum {:016x}]", bytes.size(), checksum64(bytes));
  } catch (const Error&) {  // unreadable or too large: the command itself will say so
    return "";
  }
}

// The command a checkpoint belongs to: the arguments less those that do not
// change a result (--threads, --checkpoint, --fresh-checkpoint,
// --progress-lines), each input file argument's content digest, and the
// version. The files the command writes (`outputs`) are named but not read:
// an old output deleted or rewritten is the same command.
std::string fingerprint(int argc, const char* const* argv, const std::set<std::string>& outputs) {
  std::string text = "aapat " AAPAT_VERSION;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--threads" || arg == "--checkpoint") {
      ++i;
      continue;
    }
    if (arg.starts_with("--threads=") || arg.starts_with("--checkpoint=") ||
        arg == "--fresh-checkpoint" || arg == "--progress-lines" || arg == "--quiet")
      continue;
    text += " ";
    text += shell_quoted(arg);
    const size_t eq = arg.find('=');
    const std::string_view value =
        arg.starts_with("--") && eq != std::string_view::npos ? arg.substr(eq + 1) : arg;
    if (!outputs.contains(std::string(value))) text += file_digest(arg);
  }
  return text;
}

// The options given on the command line to `command` and to the
// subcommands chosen under it (`sequence eval`, ...).
std::vector<const CLI::Option*> given_options(const CLI::App& command) {
  std::vector<const CLI::Option*> given;
  for (const CLI::Option* o : command.get_options())
    if (o->nonpositional() && o->count() > 0) given.push_back(o);
  for (const CLI::App* sub : command.get_subcommands())
    for (const CLI::Option* o : given_options(*sub)) given.push_back(o);
  return given;
}

// Standard output carries one format: --json and an output named `-`, or two
// outputs named `-`, would interleave theirs. "" when they do not.
std::string standard_output_conflict(const CLI::App& command) {
  std::vector<std::string> users;
  for (const CLI::Option* o : given_options(command)) {
    if (o->check_lname("json")) users.push_back(o->get_name());
    for (const std::string& value : o->results())
      if (value == "-") users.push_back(o->get_name() + " -");
  }
  if (users.size() < 2) return "";
  return fmt::format("{} would all write to standard output; give files for all but one",
                     fmt::join(users, " and "));
}

// The options that name output files, in every command (the folders,
// --best-dir and --frames-dir, are checked by their commands).
constexpr std::string_view kOutputOptions[] = {
    "output", "csv",   "svg",       "html",      "gif",           "map",     "table",
    "curve",  "error", "reference", "histogram", "histogram-svg", "profile", "refinement-map"};

bool is_output_option(const CLI::Option& o) {
  for (const std::string_view name : kOutputOptions)
    if (o.check_lname(std::string(name))) return true;
  return false;
}

// Every output file the command line names can be written: checked before
// any work, so that a missing folder is not found after an hour of it.
void check_output_targets(const CLI::App& command) {
  for (const CLI::Option* o : given_options(command)) {
    if (!is_output_option(*o)) continue;
    for (const std::string& value : o->results())
      if (!value.empty() && value != "-") check_file_target(value, o->get_name());
  }
}

// The output files the command line names, as given.
void add_output_files(const CLI::App& command, std::set<std::string>& files) {
  for (const CLI::Option* o : given_options(command))
    if (is_output_option(*o))
      for (const std::string& value : o->results()) files.insert(value);
}

// The command word of a command line that CLI11 could not parse: the first
// argument that is neither an option nor the value of a global one; "" if none.
std::string command_word(int argc, const char* const* argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--threads" || arg == "--checkpoint") {
      ++i;
      continue;
    }
    if (!arg.starts_with("-")) return std::string(arg);
  }
  return "";
}

// Every command, in the order the overview lists them, by the name it adds.
struct CommandEntry {
  std::string_view name;
  Action (*add)(CLI::App&);
};
constexpr std::array kCommands = {
    CommandEntry{"list", add_list_command},
    CommandEntry{"limits", add_limits_command},
    CommandEntry{"show", add_show_command},
    CommandEntry{"eval", add_eval_command},
    CommandEntry{"optimize", add_optimize_command},
    CommandEntry{"table3", add_table3_command},
    CommandEntry{"figure10", add_figure10_command},
    CommandEntry{"enumerate", add_enumerate_command},
    CommandEntry{"generate", add_generate_command},
    CommandEntry{"discrepancy", add_discrepancy_command},
    CommandEntry{"spectrum", add_spectrum_command},
    CommandEntry{"render", add_render_command},
    CommandEntry{"animate", add_animate_command},
    CommandEntry{"table2", add_table2_command},
    CommandEntry{"snap", add_snap_command},
    CommandEntry{"refine", add_refine_command},
    CommandEntry{"export", add_export_command},
    CommandEntry{"import", add_import_command},
    CommandEntry{"hardware-table", add_hardware_table_command},
    CommandEntry{"study", add_study_command},
    CommandEntry{"sequence", add_sequence_command},
    CommandEntry{"diff", add_diff_command},
};

}  // namespace

int run_aapat(int argc, const char* const* argv, std::ostream& out, std::ostream& err,
              WorkEngine* engine) {
  forget_inputs_read();  // a checkpoint binds to this command's inputs alone
  CLI::App app{
      "aapat: design antialiasing sample patterns (Laine-Aila E2 metric, Hasselgren schemes)",
      "aapat"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "aapat " AAPAT_VERSION);
  // Every parallel step of any command (oneTBB); results do not depend on it.
  int threads = 0;
  app.add_option("--threads", threads,
                 "threads for every parallel step, before the command (0: all cores; the "
                 "results are the same for any count)")
      ->check(CLI::Range(0, kMaxThreads));
  // A long run in the background shows how far it got in its log.
  bool progress_lines = false, quiet = false;
  auto* lines_flag = app.add_flag(
      "--progress-lines", progress_lines,
      "print progress on stderr as a line per tenth of the job, terminal or not; before the "
      "command (by default a bar on a terminal, else a line every 5 seconds of a long job)");
  app.add_flag("--quiet", quiet, "no progress on stderr at all; before the command")
      ->excludes(lines_flag);
  // A long run keeps its finished work items, and resumes from them.
  std::string checkpoint_path;
  auto* checkpoint_option =
      app.add_option("--checkpoint", checkpoint_path,
                     "keep every finished work item in FILE and resume from it when run again with "
                     "the same command (the same output as a run that never stopped); before the "
                     "command")
          ->type_name("FILE")
          ->check(CLI::Validator(
              [](const std::string& path) {
                return path.empty() ? std::string("an empty path names no checkpoint file")
                                    : std::string();
              },
              "FILE"));
  // A checkpoint that is refused (another command, changed inputs) or that
  // the user no longer wants is replaced on request, never silently.
  bool fresh_checkpoint = false;
  app.add_flag("--fresh-checkpoint", fresh_checkpoint,
               "with --checkpoint: start afresh and replace FILE, whatever it holds, instead of "
               "resuming from it or refusing it")
      ->needs(checkpoint_option);
  // Only the command named is built (CLI11 checks each new option against
  // every earlier one of its command, so building all 21 is most of a short
  // run's start-up); all of them for the overview, --version and a mistyped name.
  const std::string word = command_word(argc, argv);
  const bool named = std::any_of(kCommands.begin(), kCommands.end(),
                                 [&](const CommandEntry& c) { return c.name == word; });
  std::vector<std::pair<CLI::App*, Action>> commands;
  for (const CommandEntry& c : kCommands) {
    if (named && c.name != word) continue;
    const size_t before = app.get_subcommands({}).size();
    Action action = c.add(app);
    CLI::App* sub = app.get_subcommands({})[before];
    if (sub->get_name() != c.name)
      throw std::logic_error(
          fmt::format("the command table names '{}' for '{}'", c.name, sub->get_name()));
    commands.emplace_back(sub, std::move(action));
  }
  LocalEngine local;
  WorkEngine& items = engine ? *engine : local;
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // A mistyped command is named, with the nearest command.
    std::vector<std::string> names;
    for (const auto& [sub, action] : commands) names.push_back(sub->get_name());
    if (!word.empty() && std::find(names.begin(), names.end(), word) == names.end()) {
      std::string message = fmt::format("unknown command '{}'{}: the commands are {}", word,
                                        did_you_mean(word, names), fmt::join(names, ", "));
      err << "aapat: error: " << message << "\n";
      return items.agree(kExitUsage, message);
    }
    // --help and --version exit 0; every mistake on the command line exits 2.
    const int status = app.exit(e, out, err) == 0 ? kExitOk : kExitUsage;
    std::string message = e.what();
    return items.agree(status, message);  // every process ends here, or none
  } catch (...) {
    std::string message = describe_current_exception();
    err << "aapat: error: " << message << "\n";
    return items.agree(kExitUsage, message);
  }
  for (const auto& [sub, action] : commands) {
    if (!sub->parsed()) continue;
    if (std::string message = standard_output_conflict(*sub); !message.empty()) {
      err << "aapat: error: " << message << "\n";
      return items.agree(kExitUsage, message);
    }
  }
  g_warnings = &err;
  struct ResetWarnings {
    ~ResetWarnings() { g_warnings = nullptr; }
  } reset;
  // Lines for this command only: the next command in the same process (a
  // test, Python) draws its bars as before.
  struct RestoreProgress {
    bool lines = Progress::printing_lines(), quiet = Progress::quieted();
    ~RestoreProgress() {
      Progress::print_lines(lines);
      Progress::quiet(quiet);
    }
  } restore_progress;
  if (progress_lines) Progress::print_lines();
  if (quiet) Progress::quiet();
  // An engine's own threads (an MPI rank's main thread) come on top of --threads.
  std::optional<tbb::global_control> limit;
  if (threads > 0 || items.service_threads() > 0)
    limit.emplace(
        tbb::global_control::max_allowed_parallelism,
        (threads > 0 ? threads : tbb::info::default_concurrency()) + items.service_threads());
  bool agreed = false;
  try {
    for (const auto& [sub, action] : commands)
      if (sub->parsed()) check_output_targets(*sub);
    // A command writes all its files or, when it fails, none.
    OutputTransaction outputs;
    std::unique_ptr<Checkpoint> checkpoint;
    if (!checkpoint_path.empty() && items.root()) {
      if (fresh_checkpoint && std::filesystem::is_regular_file(checkpoint_path))
        std::filesystem::remove(checkpoint_path);
      std::set<std::string> output_files;
      for (const auto& [sub, action] : commands)
        if (sub->parsed()) add_output_files(*sub, output_files);
      checkpoint =
          std::make_unique<Checkpoint>(checkpoint_path, fingerprint(argc, argv, output_files));
    }
    if (checkpoint && checkpoint->restored() > 0)
      err << fmt::format("aapat: resuming from {}: {} work items done\n", checkpoint_path,
                         checkpoint->restored());
    {
      const WorkSession session(items, checkpoint.get());
      for (auto& [sub, action] : commands)
        if (sub->parsed()) action(out);
    }
    // What went to standard output must have arrived (a full disk, a closed
    // pipe): checked before the files are committed, so that a failed run
    // leaves none of them.
    if (!out.flush())
      throw Error(
          "standard output: a write failed (a full disk or a closed pipe?); the output is "
          "incomplete");
    // Every process of the run agrees first: a failure anywhere writes nothing.
    std::string message;
    agreed = true;
    if (items.agree(kExitOk, message) != kExitOk) throw Error(message);
    outputs.commit();
  } catch (...) {
    std::string message = describe_current_exception();
    if (!agreed) items.agree(kExitError, message);
    err << "aapat: error: " << message << "\n";
    return kExitError;
  }
  return kExitOk;
}

}  // namespace aapat

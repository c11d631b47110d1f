// Progress of a long command on stderr, wherever stderr goes:
//  - on a terminal, a one-line bar;
//  - otherwise (a log, a pipe), a line at most every kProgressLineSeconds
//    (AAPAT_PROGRESS_SECONDS), the first once the job has run that long, so
//    that a short command prints nothing and a six-minute one shows how far
//    it got;
//  - a line per tenth of the job, terminal or not, when asked
//    (--progress-lines, or an MPI job's rank 0);
//  - nothing with --quiet.
#pragma once

#include <chrono>
#include <string>

#include "aapat/study/progress.h"

namespace aapat {

inline constexpr double kProgressLineSeconds = 5;

class Progress {
 public:
  explicit Progress(std::string label);
  ~Progress();
  void update(int done, int total, const std::string& note);
  // The bar as a library job's progress callback.
  StudyProgress callback();
  // From now on every bar is printed as lines (one per tenth of the job),
  // terminal or not (`on`), or drawn as a bar again: rank 0 of an MPI job,
  // whose stderr mpirun forwards, and --progress-lines, for a run in the
  // background whose stderr goes to a log.
  static void print_lines(bool on = true);
  static bool printing_lines();
  // --quiet: no progress of any kind (`on`), or progress again.
  static void quiet(bool on = true);
  static bool quieted();

 private:
  enum class Style { kNone, kBar, kTimedLines, kTenths };
  std::string label_;
  Style style_;
  bool drawn_ = false;  // a bar that never drew leaves no empty line
  int tenths_ = -1;     // the last tenth printed as a line
  std::chrono::steady_clock::time_point start_, last_line_;
};

}  // namespace aapat

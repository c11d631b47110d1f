// A one-line progress bar on a terminal's stderr; silent when stderr is not a
// terminal (piped or redirected), so logs and scripts stay clean; lines when
// asked (--progress-lines, or an MPI job's rank 0).
#pragma once

#include <string>

#include "aapat/study/progress.h"

namespace aapat {

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

 private:
  std::string label_;
  bool active_;
  bool drawn_ = false;  // a bar that never drew leaves no empty line
  int tenths_ = -1;     // the last tenth printed as a line
};

}  // namespace aapat

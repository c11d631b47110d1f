// A one-line progress bar on a terminal's stderr; silent when stderr is not a
// terminal (piped or redirected), so logs and scripts stay clean.
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

 private:
  std::string label_;
  bool active_;
};

}  // namespace aapat

// A checkpoint of a long run: the result of every work item that finished
// (work/work_items.h), appended as it arrives, so that a run that was killed
// resumes with the same command and `--checkpoint FILE` where it stopped and
// writes the same files as a run that never stopped.
//
// The file starts with the command it belongs to (its fingerprint); each
// record is one item's exact result bytes with a checksum. A record cut off
// by the kill is dropped on resume and recomputed.
#pragma once

#include <cstdio>
#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace aapat {

class Checkpoint {
 public:
  // Opens `path` for the run described by `fingerprint` (the command line
  // without the options that do not change results): resumes from the items
  // it holds, or starts a new file. Throws Error when the file belongs to
  // another command or is not a checkpoint.
  Checkpoint(std::string path, std::string fingerprint);
  ~Checkpoint();
  Checkpoint(const Checkpoint&) = delete;
  Checkpoint& operator=(const Checkpoint&) = delete;

  // The run's `call`-th set of work items has `count` items: recorded the
  // first time, checked on resume (a run that took another path, or a file
  // from another version, is an Error rather than wrong results). So are the
  // input files read before it began (core/read_file.h: inputs_read), by
  // content: a run does not resume after a file it read changed.
  void begin(int call, int count);
  // Item `item` of the run's `call`-th set of work items, if it finished.
  std::optional<std::string> find(int call, int item) const;
  // Appends a finished item and flushes it to the operating system.
  void record(int call, int item, std::string_view result);
  // How many items the file held when it was opened.
  int restored() const { return restored_; }
  const std::string& path() const { return path_; }

 private:
  // Writes the pieces and flushes them to the operating system; throws Error.
  void append(std::initializer_list<std::string_view> pieces);

  std::string path_;
  std::map<std::pair<int, int>, std::string> items_;
  std::map<int, int> counts_;          // items per set
  std::map<int, std::string> inputs_;  // per set: the input files read before it began
  int restored_ = 0;
  std::FILE* file_ = nullptr;
};

}  // namespace aapat

// A job's work items: the independent pieces a long job is made of (an
// optimizer start, an enumerated configuration, a band of a reference image).
// Item i's result depends on i alone and the caller combines the results in
// item order, so the output is the same wherever and in which order the items
// ran: on this process's cores (oneTBB), on many processes of a cluster (an
// MPI engine, src/cluster), or partly in an earlier run that was killed and
// left a checkpoint.
//
// Results travel as bytes (work/byte_codec.h). Calls made from inside an item
// run their items on the cores of the process that runs the outer item.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace aapat {

// The most threads any face accepts (0 means all cores): the command line's
// --threads and Python's threads= both read it.
inline constexpr int kMaxThreads = 1024;

// Throws Error unless 0 <= threads <= kMaxThreads; `what` names the input.
void check_threads(int threads, std::string_view what);

class Checkpoint;

using ItemWork = std::function<std::string(int item)>;
// (items done, items in all, the result just finished), called one at a time.
using ItemsProgress = std::function<void(int done, int total, const std::string& result)>;

// A long loop's progress as hundredths, (done, 100, ""), calling `progress`
// only when another hundredth is reached; nothing without a callback.
class Hundredths {
 public:
  explicit Hundredths(const ItemsProgress& progress) : progress_(progress) {}
  void at(double fraction) {
    if (!progress_) return;
    const int h = fraction >= 1 ? 100 : fraction > 0 ? static_cast<int>(fraction * 100) : 0;
    if (h <= last_) return;
    last_ = h;
    progress_(h, 100, "");
  }

 private:
  const ItemsProgress& progress_;
  int last_ = -1;
};

// Runs items 0..count-1 and returns their results in item order. An item that
// throws fails the call with the lowest failing item's error. An empty result
// means "not done" (an item a deadline skipped): a checkpoint does not keep
// it, so a resumed run runs the item.
std::vector<std::string> run_work_items(int count, const ItemWork& work,
                                        const ItemsProgress& progress = {});
// One item: a decision every process must share (a cache lookup, say).
std::string run_as_one_item(const std::function<std::string()>& work);

// Where items run.
class WorkEngine {
 public:
  virtual ~WorkEngine() = default;
  using Finished = std::function<void(int item, const std::string& result)>;
  // Fills every empty results[i] with work(i), calling `finished` (one call at
  // a time) as each new result arrives where the outputs are written. Every
  // process of the engine calls run with the same items; each returns with
  // all results (a process other than the root gets them from the root).
  virtual void run(std::vector<std::optional<std::string>>& results, const ItemWork& work,
                   const Finished& finished) = 0;
  // Whether this process writes the outputs and the checkpoint.
  virtual bool root() const { return true; }
  // Threads the engine needs besides those that run items (an MPI engine:
  // the main thread, which talks to the other processes).
  virtual int service_threads() const { return 0; }
  // At the end of a command, on every process: the command's exit status
  // here (0: success) and its error message; returns the status all agree
  // on, and on the root sets `message` to the error to report when another
  // process failed.
  virtual int agree(int status, std::string& message) {
    (void)message;
    return status;
  }
  // What the processes did (a line per process), for the end of a run.
  virtual std::string report() const { return {}; }
};

// Every item on this process's cores, in parallel.
class LocalEngine final : public WorkEngine {
 public:
  void run(std::vector<std::optional<std::string>>& results, const ItemWork& work,
           const Finished& finished) override;
};

// A run of the command line: while a session is open, calls of
// run_work_items made on its thread (and not from inside an item) go through
// its engine, are numbered, and are kept in and restored from its checkpoint.
// Without one, items run on this process's cores.
class WorkSession {
 public:
  WorkSession(WorkEngine& engine, Checkpoint* checkpoint);
  ~WorkSession();
  WorkSession(const WorkSession&) = delete;
  WorkSession& operator=(const WorkSession&) = delete;
};

}  // namespace aapat

// Work items across the processes of an MPI job (mpirun, Slurm's srun):
// the engine of `mpirun -np K aapat ...` (docs/cluster.md).
//
// Every rank runs the same command. At each set of work items
// (work/work_items.h) rank 0 hands items out one at a time to whichever rank
// asks, each rank keeps as many in flight as it has item threads (a oneTBB
// arena, so an item's own parallel loops use that rank's cores too) while its
// main thread talks MPI, and rank 0 sends every result, in item order, to
// every rank; so every rank continues the command from the same state and the
// output does not depend on the number of ranks or threads. Only rank 0
// writes outputs and the checkpoint.
//
// A command that fails on any rank fails on all (agree): rank 0 reports the
// error and no output is written. A rank that dies is the MPI runtime's to
// report: mpirun ends the whole job.
#pragma once

#include <memory>
#include <string>

#include "aapat/work/work_items.h"

namespace aapat {

class MpiEngine final : public WorkEngine {
 public:
  // After MPI_Init_thread (at least MPI_THREAD_FUNNELED), on every rank.
  MpiEngine();
  ~MpiEngine() override;

  void run(std::vector<std::optional<std::string>>& results, const ItemWork& work,
           const Finished& finished) override;
  bool root() const override { return rank_ == 0; }
  // The main thread talks to the other ranks; items run beside it.
  int service_threads() const override { return 1; }
  int agree(int status, std::string& message) override;
  std::string report() const override;

  int rank() const { return rank_; }
  int size() const { return size_; }

 private:
  struct Local;
  void run_root(std::vector<std::optional<std::string>>& results, const ItemWork& work,
                const Finished& finished);
  void run_worker(std::vector<std::optional<std::string>>& results, const ItemWork& work);

  int rank_ = 0, size_ = 1;
  std::unique_ptr<Local> local_;
  // Rank 0: what each rank ran (core-seconds inside items, items), and the
  // wall time spent in sets of items.
  std::vector<double> busy_;
  std::vector<long> items_;
  double wall_ = 0, longest_ = 0;
  // Rank 0: the ranks whose final word (agree) already arrived inside run.
  struct Final {
    int rank = 0, status = 0;
    std::string why;
  };
  std::vector<bool> final_seen_;
  std::vector<Final> finals_;
};

}  // namespace aapat

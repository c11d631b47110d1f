#include "cli/process.h"

#include <cstdlib>
#include <iostream>
#include <sstream>
#include <streambuf>

#include "cli/app.h"
#include "cli/progress.h"

#if AAPAT_HAVE_MPI
#include <mpi.h>

#include "aapat/io/atomic_file.h"
#include "cluster/mpi_engine.h"
#endif

namespace aapat {
namespace {

#if AAPAT_HAVE_MPI
// Whether a launcher started this process as a rank of a job: Open MPI's
// mpirun, or a PMI/PMIx launcher (Slurm's srun, Hydra).
bool launched_as_rank() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
    if (std::getenv(name)) return true;
  return false;
}

// What the other ranks print goes nowhere: rank 0 says it once.
class NullBuffer : public std::streambuf {
 protected:
  int overflow(int c) override { return traits_type::not_eof(c); }
  std::streamsize xsputn(const char*, std::streamsize n) override { return n; }
};

int run_rank(int argc, char** argv) {
  int provided = 0;
  if (MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
    std::cerr << "aapat: error: MPI could not start\n";
    return kExitError;
  }
  int status = kExitError;
  if (provided < MPI_THREAD_FUNNELED) {
    std::cerr << "aapat: error: this MPI does not allow threads (MPI_THREAD_FUNNELED)\n";
  } else {
    MpiEngine engine;
    if (engine.rank() == 0) {
      Progress::print_lines();  // mpirun forwards lines, not a redrawn bar
      status = run_aapat(argc, argv, std::cout, std::cerr, &engine);
      if (status == kExitOk && engine.size() > 1) std::cerr << engine.report();
    } else {
      mute_outputs();
      NullBuffer nowhere;
      std::ostream out(&nowhere);
      std::ostringstream err;
      status = run_aapat(argc, argv, out, err, &engine);
    }
  }
  MPI_Finalize();
  return status;
}
#endif

}  // namespace

int run_process(int argc, char** argv) {
#if AAPAT_HAVE_MPI
  if (launched_as_rank()) return run_rank(argc, argv);
#endif
  return run_aapat(argc, argv, std::cout, std::cerr);
}

}  // namespace aapat

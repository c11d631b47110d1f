// The aapat process: one command, on its own or as one rank of an MPI job
// (mpirun, srun: docs/cluster.md). Under MPI every rank runs the command;
// rank 0 alone prints and writes files.
#pragma once

namespace aapat {

int run_process(int argc, char** argv);

}  // namespace aapat

#pragma once
// `mpirun -n P puncture sweep SPEC.toml -o FILE`: the sweep spread over P processes.  Rank r
// solves the points first + r, first + r + P, ... (SweepOptions::offset, stride) on its own
// threads and sends each row to rank 0, which writes them all in point order to FILE.part:
// the file is the serial run's, byte for byte, whatever P and the threads.  Rank 0 alone reads
// and writes files, prints progress and errors; --resume continues any run with any P.
#include <CLI/CLI.hpp>

#include "command_sweep.hpp"

namespace puncture::cli {

// Started by mpirun (Open MPI's or a PMI launcher's environment).
bool launched_by_mpi();

// Runs the parsed sweep as one rank of the MPI job.  Without MPI support built in (CMake
// PUNCTURE_MPI), throws InputError.
int run_sweep_mpi(const CLI::App& app, const SweepFlags& flags, const OutputFlags& output);

}  // namespace puncture::cli

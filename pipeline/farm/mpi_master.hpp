#pragma once
// Rank 0 of an MPI farm: hands out working sets on request, assembles the
// returned stripes into frames (stored by the FarmRun's writer) and reports
// progress.  It polls with MPI_Iprobe and sleeps a millisecond when idle,
// so a waiting master costs next to no CPU.

#include <cstdint>

#include "farm/event_log.hpp"
#include "farm/farm_run.hpp"
#include "farm/mpi_session.hpp"
#include "farm/progress.hpp"

namespace lc::farm {

struct MasterReport {
  int workers = 0;         // ranks that said hello
  int worker_threads = 0;  // their render threads, summed
};

// Runs until every frame is stored or the run fails (a worker's error, a
// worker that loaded a different job, a failed write) or is interrupted
// (a signal here or on a worker).  Errors end up in run.error(), signals in
// run.interrupted().  The workers are still waiting afterwards:
// stop_mpi_workers.
// Each worker that joins is written to `events` (may be null).
MasterReport run_mpi_master(const MpiSession& mpi, WorkQueue& queue, FarmRun& run, Progress& progress,
                            std::uint64_t digest, EventLog* events = nullptr);

// Tells every worker to stop and waits until each has said goodbye
// (discarding whatever else they send).  Call it once on every way out of
// the master, also when it fails before its loop (a locked directory, a
// refused resume).
void stop_mpi_workers(const MpiSession& mpi);

}  // namespace lc::farm

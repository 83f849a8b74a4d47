#pragma once
// Rank 0 of an MPI farm: hands out working sets on request, assembles the
// returned stripes into frames (stored by the FarmRun's writer) and reports
// progress.  It polls with MPI_Iprobe and sleeps a millisecond when idle,
// so a waiting master costs next to no CPU.

#include <chrono>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "telemetry/event_log.hpp"
#include "schedule/farm_run.hpp"
#include "transport/mpi_session.hpp"
#include "telemetry/progress.hpp"
#include "transport/rank_board.hpp"

namespace lc::farm {

struct MasterReport {
  int workers = 0;         // ranks that said hello
  int worker_threads = 0;  // their render threads, summed
  std::map<int, std::string> hosts;  // each of them: its node
};

// Runs until every frame is stored or the run fails (a worker's error, a
// worker that loaded a different job, a failed write) or is interrupted
// (a signal here or on a worker).  Errors end up in run.error(), signals in
// run.interrupted().  The workers are still waiting afterwards:
// stop_mpi_workers.
// Each worker that joins is written to `events` (may be null), and what
// each holds to `board` (may be null).
MasterReport run_mpi_master(const MpiSession& mpi, WorkQueue& queue, FarmRun& run, Progress& progress,
                            std::uint64_t digest, EventLog* events = nullptr, RankBoard* board = nullptr);

// How long a worker that joined may take to answer the stop before it is
// given up as lost.  Its MPI thread polls every millisecond and says
// goodbye before its render threads finish their sets, so only a dead
// process (or node) stays silent this long.  Short, because a launcher
// that lost a rank gives the others little time: Open MPI 4's mpirun sends
// SIGTERM and then SIGKILL a second later.
inline constexpr std::chrono::milliseconds answer_stop_within{500};

// Once some workers have answered, how long the silent ones have after the
// last answer.  Open MPI 5's launcher (PRRTE 3) sends SIGKILL 35-90 ms after
// SIGTERM (docs/cluster.md, "When things fail"): the workers alive answer
// within a few milliseconds, so the master names the dead one in time.
inline constexpr std::chrono::milliseconds answer_stop_after_others{20};

// Tells every worker to stop and waits until each has said goodbye
// (discarding whatever else they send).  Call it once on every way out of
// the master, also when it fails before its loop (a locked directory, a
// refused resume).  Without `give_up`, waits as long as it takes (a rank
// still loading its job answers when it is ready).  With it, the ranks of
// `give_up->joined` that have not answered within `answer_stop_within`, or
// within `answer_stop_after_others` of the last rank that did, are no
// longer waited for and are returned: lost.
struct GiveUp {
  std::vector<int> joined;
};
std::vector<int> stop_mpi_workers(const MpiSession& mpi, const std::optional<GiveUp>& give_up = std::nullopt);

}  // namespace lc::farm

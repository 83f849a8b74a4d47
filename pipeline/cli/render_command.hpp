#pragma once
// `lightcone render SHOT.lua --out DIR [...]`: renders frames of a shot with
// the farm — threads on every core, or master and workers under mpirun —
// into a resumable frame store (docs/cli.md, docs/cluster.md).

#include "job/render_request.hpp"
#include "transport/mpi_session.hpp"

namespace lc {

int run_render(const RenderRequest& cmd);

// The same within an MPI session the caller holds (the showcase renders
// several shots in one): rank 0, or the only process, is the master and
// returns when the frames are stored (or throws); a worker returns when the
// master is done with it.  Every rank must call it with the same command.
int render_in_session(const RenderRequest& cmd, const farm::MpiSession& mpi);

}  // namespace lc

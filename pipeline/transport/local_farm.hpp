#pragma once
// The farm on one machine without MPI: `threads` threads take working sets
// from the queue and render straight into the frame's canvas (rows are
// disjoint, so no copy and no lock while tracing); the calling thread draws
// progress until the queue is done or an error stops it.

#include "schedule/farm_run.hpp"
#include "telemetry/progress.hpp"
#include "stages/stripe_renderer.hpp"

namespace lc::farm {

// Returns when every thread has stopped; errors are in run.error().  The
// writer is still running (run.close() ends it).
void run_local_farm(WorkQueue& queue, FarmRun& run, StripeRenderer& renderer, int threads, Progress& progress);

}  // namespace lc::farm

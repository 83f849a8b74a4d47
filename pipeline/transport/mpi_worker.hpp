#pragma once
// A worker rank of an MPI farm: asks the master for working sets (keeping
// one in reserve per thread so no thread waits for a round trip), renders
// them with `threads` threads into canvases of its own, and sends each
// set's rows back.  Only the calling thread talks MPI; it sleeps a
// millisecond between polls.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "transport/mpi_session.hpp"
#include "job/stripes.hpp"
#include "stages/stripe_renderer.hpp"

namespace lc::farm {

// Works until the master says stop.  With `setup_error` (this rank could not
// load the job) it reports that instead and only waits for the stop.  A
// render error is sent to the master, which stops the job.  `reserve` is
// how many sets per thread to hold (rendering or waiting): 2 hides the
// round trip to the master behind one set; the farm benchmark, whose sets
// cost nothing, asks for more to keep the master busy.  When
// `signal_received` (may be empty) reports a signal, the worker drops the
// sets it has not begun, asks for no more, tells the master (which stops
// the job and says stop) and returns with the signal; otherwise 0.
int run_mpi_worker(const MpiSession& mpi, StripeRenderer* renderer, const RenderSettings& rs,
                   const StripeLayout& layout, int threads, std::uint64_t digest,
                   const std::optional<std::string>& setup_error, int reserve = 2,
                   const std::function<int()>& signal_received = {});

}  // namespace lc::farm

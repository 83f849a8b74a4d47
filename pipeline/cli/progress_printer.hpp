#pragma once
// Progress of an encode on the command line, shared by `lightcone encode`
// and the showcase.

#include <string>

#include "interrupt.hpp"
#include "video/encode_options.hpp"

namespace lc {

// A ProgressFn printing a line on stderr about once a second
// ("<prefix>: 120/900 frames, 21.5 frames/s"), and the place where a
// Ctrl-C recorded by `guard` turns into Interrupted between frames.  The
// guard must outlive the function.
ProgressFn progress_printer(const InterruptGuard& guard, std::string prefix, std::string unit);

}  // namespace lc

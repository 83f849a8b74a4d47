// The trace and shade stages compiled for the Kerr spacetime: one
// translation unit per spacetime (render/trace.hpp says why).
#include "render/trace_templates.hpp"
#include "spacetime/kerr.hpp"

namespace lc {

template struct TraceStage<Kerr>;

}  // namespace lc

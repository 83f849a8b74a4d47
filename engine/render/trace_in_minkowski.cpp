// The trace and shade stages compiled for the Minkowski spacetime: one
// translation unit per spacetime (render/trace.hpp says why).
#include "render/trace_templates.hpp"
#include "spacetime/minkowski.hpp"

namespace lc {

template struct TraceStage<Minkowski>;

}  // namespace lc

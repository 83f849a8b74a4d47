// The trace and shade stages compiled for the Dihole spacetime: one
// translation unit per spacetime (render/trace.hpp says why).
#include "render/trace_templates.hpp"
#include "spacetime/dihole.hpp"

namespace lc {

template struct TraceStage<Dihole>;

}  // namespace lc

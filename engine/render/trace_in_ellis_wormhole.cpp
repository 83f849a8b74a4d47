// The trace and shade stages compiled for the EllisWormhole spacetime:
// one translation unit per spacetime (render/trace.hpp says why).
#include "render/trace_templates.hpp"
#include "spacetime/ellis_wormhole.hpp"

namespace lc {

template struct TraceStage<EllisWormhole>;

}  // namespace lc

// The trace and shade stages compiled for the InterstellarWormhole spacetime:
// one translation unit per spacetime (render/trace.hpp says why).
#include "render/trace_templates.hpp"
#include "spacetime/interstellar_wormhole.hpp"

namespace lc {

template struct TraceStage<InterstellarWormhole>;

}  // namespace lc

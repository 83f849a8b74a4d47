// The trace and shade stages compiled for the Kottler spacetime:
// one translation unit per spacetime (render/trace.hpp says why).
#include "render/trace_templates.hpp"
#include "spacetime/kottler.hpp"

namespace lc {

template struct TraceStage<Kottler>;

}  // namespace lc

// The trace and shade stages compiled for the MajumdarPapapetrou spacetime:
// one translation unit per spacetime (render/trace.hpp says why).
#include "render/trace_templates.hpp"
#include "spacetime/majumdar_papapetrou.hpp"

namespace lc {

template struct TraceStage<MajumdarPapapetrou>;

}  // namespace lc

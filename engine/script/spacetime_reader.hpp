#pragma once
// Script value -> Spacetime.  The value must come from one of the
// constructors of engine_api (a table tagged with __kind).

#include "lua/table_reader.hpp"
#include "spacetime/spacetime_spec.hpp"

namespace lc {

// Reads a tagged spacetime table (scene parameters; the chart rays are
// traced in is the builder's choice: trace_chart).  Throws lua::FieldError
// naming the context and the problem.
Spacetime read_spacetime(lua::TableReader& t);

}  // namespace lc

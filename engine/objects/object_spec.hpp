#pragma once
// An object a shot asked for (lc.<name>{...}): one registered object kind's
// parameters in a box (core/spec_box.hpp) whose list of kinds
// (objects/object_params.hpp) this header does not include, so that what
// holds, copies or passes on a scene spec is not rebuilt for a new object
// kind (docs/architecture.md, "What a new kind rebuilds").  Made from one
// kind's Params (ObjectSpec{DiskParams{...}}); read back with get<P>() or,
// where the list is included, visited through kinds().

#include "core/spec_box.hpp"

namespace lc {

struct ObjectSpecKinds;  // objects/object_params.hpp
using ObjectSpec = SpecBox<ObjectSpecKinds>;
// Its members are compiled once, beside the list; nowhere else, even where
// core/spec_box_impl.hpp is seen.
extern template class SpecBox<ObjectSpecKinds>;
// Its name, key and JSON: kind_name, kind_key, kind_json (core/spec_box.hpp).

}  // namespace lc

#pragma once
// An object a shot asked for (lc.<name>{...}): one registered object kind's
// parameters in a box (core/spec_box.hpp) whose list of kinds
// (objects/object_params.hpp) this header does not include, so that what
// holds, copies or passes on a scene spec is not rebuilt for a new object
// kind (docs/architecture.md, "What a new kind rebuilds").  Made from one
// kind's Params (ObjectSpec{DiskParams{...}}); read back with get<P>() or,
// where the list is included, visited through kinds().

#include <string>
#include <string_view>

#include "core/spec_box.hpp"

namespace lc {

struct ObjectSpecKinds;  // objects/object_params.hpp
using ObjectSpec = SpecBox<ObjectSpecKinds>;
// Its members are compiled once, beside the list; nowhere else, even where
// core/spec_box_impl.hpp is seen.
extern template class SpecBox<ObjectSpecKinds>;

// Its kind's name (its Lua constructor's: "disk", "sphere", ...).
std::string_view object_name(const ObjectSpec& spec);
// "name field=value ...", exactly (core/registry.hpp, spec_key).
std::string object_key(const ObjectSpec& spec);
// {"kind": "name", <each field>: value}; polar: whether the scene's
// positions are polar (for a field holding one).
std::string object_json(const ObjectSpec& spec, bool polar);

}  // namespace lc

#pragma once
// The list of object kinds' parameters, one line each, in the order of the
// objects' registry (objects/objects.hpp, which checks the two lists
// agree): the variant an ObjectSpec holds (objects/object_spec.hpp).  Only
// what visits every object kind — reads, documents or builds one —
// includes this list (docs/architecture.md, "What a new kind rebuilds").

#include "core/registry.hpp"
#include "objects/disk_params.hpp"
#include "objects/object_spec.hpp"
#include "objects/sphere_params.hpp"

namespace lc {

// Every object kind's parameters, one line each.
using ObjectSpecs = SpecRegistry<DiskParams, SphereParams>;

// The variant itself, as a class so that objects/object_spec.hpp can name
// it before the list.
struct ObjectSpecKinds : ObjectSpecs::Spec {
  using Specs = ObjectSpecs;
  using ObjectSpecs::Spec::Spec;
  ObjectSpecKinds() = default;
  ObjectSpecKinds(const ObjectSpecs::Spec& spec) : ObjectSpecs::Spec(spec) {}
};

}  // namespace lc

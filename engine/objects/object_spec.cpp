#include "objects/object_spec.hpp"

#include "core/spec_box_impl.hpp"
#include "objects/object_params.hpp"

namespace lc {

// The box's members, and for each object kind how a box is made from its
// parameters and read back: one line per kind, as objects/object_params.hpp
// lists them.  A kind missing here is a link error naming
// SpecAccess<ObjectSpecKinds, ItsParams>.
template class SpecBox<ObjectSpecKinds>;
template struct SpecAccess<ObjectSpecKinds, DiskParams>;
template struct SpecAccess<ObjectSpecKinds, SphereParams>;

std::string_view object_name(const ObjectSpec& spec) { return ObjectSpecs::name(spec.kinds()); }

std::string object_key(const ObjectSpec& spec) { return ObjectSpecs::key(spec.kinds()); }

std::string object_json(const ObjectSpec& spec, bool polar) { return ObjectSpecs::json(spec.kinds(), polar); }

}  // namespace lc

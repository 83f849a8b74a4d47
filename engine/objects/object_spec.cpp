#include "objects/object_spec.hpp"

#include "core/spec_box_impl.hpp"
#include "objects/object_params.hpp"

namespace lc {

// The box's members, its name, key and JSON, and for each object kind how a
// box is made from its parameters and read back: one line per kind, as
// objects/object_params.hpp lists them.  A kind missing here is a link error
// naming SpecAccess<ObjectSpecKinds, ItsParams>.
template class SpecBox<ObjectSpecKinds>;
template std::string_view kind_name(const ObjectSpec&);
template std::string kind_key(const ObjectSpec&);
template std::string kind_json(const ObjectSpec&, bool);
template struct SpecAccess<ObjectSpecKinds, DiskParams>;
template struct SpecAccess<ObjectSpecKinds, SphereParams>;

}  // namespace lc

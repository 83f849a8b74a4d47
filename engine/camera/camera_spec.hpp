#pragma once
// The camera a shot asked for (lc.<name>{...}): one registered camera's
// parameters in a box (core/spec_box.hpp) whose list of kinds
// (camera/camera_params.hpp) this header does not include, so that what
// holds, copies or passes on a camera spec — a scene spec, the shot, the
// jobs — is not rebuilt for a new camera kind (docs/architecture.md,
// "What a new kind rebuilds").  Made from one kind's Params
// (CameraSpec{PinholeParams{...}}); read back with get<P>() or, where the
// list is included, visited through kinds().

#include "core/spec_box.hpp"

namespace lc {

struct CameraSpecKinds;  // camera/camera_params.hpp
using CameraSpec = SpecBox<CameraSpecKinds>;
// Its members are compiled once, beside the list; nowhere else, even where
// core/spec_box_impl.hpp is seen.
extern template class SpecBox<CameraSpecKinds>;
// Its name, key and JSON: kind_name, kind_key, kind_json (core/spec_box.hpp).

// Its eyes' `separation` (M), 0 for a kind without one.
double stereo_separation(const CameraSpec& spec);

}  // namespace lc

#pragma once
// A spacetime as a shot gives it (lc.kerr{...}) and as scenes, worldlines
// and geodesic problems hold it: one registered spacetime (the list:
// spacetime/spacetime.hpp) in a box (core/spec_box.hpp) whose list this
// header does not include, so that what holds or passes on a spacetime is
// not rebuilt for a new one (docs/architecture.md, "What a new kind
// rebuilds").  Made from one spacetime (Spacetime{Kerr(1, 0.9)}); read back
// with get<S>() or, where the list is included, visited through kinds().

#include <span>
#include <string>
#include <string_view>

#include "core/spec_box.hpp"
#include "core/tensor.hpp"
#include "spacetime/chart.hpp"
#include "spacetime/ends.hpp"

namespace lc {

struct SpacetimeKinds;  // spacetime/spacetime.hpp
using Spacetime = SpecBox<SpacetimeKinds>;
// Its members are compiled once, beside the list; nowhere else, even where
// core/spec_box_impl.hpp is seen.
extern template class SpecBox<SpacetimeKinds>;

// Its name ("minkowski", "kerr", "dihole"): the Lua constructor's, in
// messages and output.
std::string_view spacetime_name(const Spacetime& s);

// The chart its scene positions are given in.
SceneChart scene_chart(const Spacetime& s);

// Whether its polar scene r is signed (scene_radius_is_signed,
// spacetime/chart.hpp): r <= 0 is then a place like any other.
bool scene_radius_is_signed(const Spacetime& s);

// Its ends (spacetime/ends.hpp), in their order: the far end where the
// scene's sky is first.
std::span<const SpacetimeEnd> spacetime_ends(const Spacetime& s);

// The same spacetime in the chart regular where curves traced in direction
// d go (Kerr: its ingoing or outgoing Kerr–Schild form).
Spacetime for_tracing(const Spacetime& s, TimeDirection d);

// The chart camera rays are traced in: backwards in time.
Spacetime trace_chart(const Spacetime& s);

// Whether scene positions are polar {r, theta, phi}.
bool has_polar_scene(const Spacetime& s);

// {"kind": name, <each declared parameter>: value}.
std::string spacetime_json(const Spacetime& s);

// The names of the registered spacetimes whose scene positions are in
// chart c, ", "-separated ("kerr", "minkowski, dihole").
std::string spacetimes_in_chart(SceneChart c);

// The scene coordinates of the trace-chart event x, and of the vector u at
// it (for what writes paths out; the trace code calls the model's own).
Vec4 scene_from_trace(const Spacetime& s, const Vec4& x);
Vec4 scene_vector(const Spacetime& s, const Vec4& x, const Vec4& u);

// The spacetime and its exact parameters, e.g. "kerr(mass=1, spin=0.9)";
// equal strings mean the same spacetime (hex-float exact with exact = true).
std::string describe(const Spacetime& s, bool exact = false);

}  // namespace lc

#pragma once
// The closed set of spacetimes.  Each alternative is a concrete class with the
// same member set (no virtual dispatch): the ray integrator is instantiated
// per alternative, so the metric inlines into the step.  Members every
// alternative provides:
//   hamiltonian_rhs(x, p, dx, dp)   Hamilton's equations, trace coordinates
//   captured(x), inside_horizon(x)  stop tests
//   metric, inverse_metric, metric_derivatives (∂_alpha g_{mu nu})
//   trace_from_scene, scene_from_trace, scene_vector, scene_time_gradient,
//   polar_basis                     scene <-> trace coordinates
// Scene coordinates are Boyer–Lindquist for Kerr, Cartesian otherwise.

#include <string>
#include <variant>

#include "spacetime/dihole.hpp"
#include "spacetime/kerr.hpp"
#include "spacetime/minkowski.hpp"

namespace lc {

using Spacetime = std::variant<Minkowski, Kerr, Dihole>;

// Short lowercase name ("minkowski", "kerr", "dihole") for messages and output.
std::string spacetime_name(const Spacetime& s);

// The spacetime and its exact parameters, e.g. "kerr(mass=1, spin=0.9)";
// equal strings mean the same spacetime (hex-float exact with exact = true).
std::string describe(const Spacetime& s, bool exact = false);

// True when scene coordinates are Boyer–Lindquist (t, r, theta, phi).
inline bool has_polar_scene(const Spacetime& s) { return std::holds_alternative<Kerr>(s); }

}  // namespace lc

#pragma once
// The registry of spacetimes: every one lightcone knows, one line each in
// the variant below, each a class satisfying SpacetimeModel
// (spacetime/model.hpp) in its own files.  What holds a spacetime holds it
// in a box (Spacetime, spacetime/spacetime_spec.hpp) that does not include
// this list; what visits every spacetime — the Lua constructors
// lc.<name>{...}, the readers, the scene builder, the generic self-test —
// includes it and goes through the variant and the model's members; none
// asks which spacetime it holds.

#include <variant>

#include "core/registry.hpp"
#include "spacetime/dihole.hpp"
#include "spacetime/ellis_wormhole.hpp"
#include "spacetime/interstellar_wormhole.hpp"
#include "spacetime/kerr.hpp"
#include "spacetime/kottler.hpp"
#include "spacetime/majumdar_papapetrou.hpp"
#include "spacetime/minkowski.hpp"
#include "spacetime/spacetime_spec.hpp"

namespace lc {

// Every spacetime, one line each: a registry of the same shape as the
// others (core/registry.hpp), its kinds' variant the list.
using SpacetimeRegistry = Registry<Minkowski, Kerr, Dihole, MajumdarPapapetrou, Kottler, EllisWormhole,
                                   InterstellarWormhole>;
using SpacetimeList = SpacetimeRegistry::Kinds;

// The variant itself, as a class so that spacetime/spacetime_spec.hpp can
// name it before the list.
struct SpacetimeKinds : SpacetimeList {
  using SpacetimeList::SpacetimeList;
  SpacetimeKinds(const SpacetimeList& s) : SpacetimeList(s) {}
};

// One assertion per spacetime: the compiler's notes name the one that fails
// and the requirement it misses.
static_assert(every_kind<SpacetimeRegistry>([]<class S>() {
  static_assert(SpacetimeModel<S>, "a registered spacetime must satisfy SpacetimeModel (spacetime/model.hpp)");
}));


}  // namespace lc

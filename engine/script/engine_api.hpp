#pragma once
// The C++ side of the shot-author API: scene constructors that validate their
// arguments when the script calls them, so an error points at the script
// line that made the bad value.  They are installed as the table
// `__lightcone`, which scripts/lightcone.lua re-exports; authors use
// `local lc = require "lightcone"`.
//
// A constructor returns a plain table tagged with `__kind` (and `__where`,
// the "file:line" that called it); the readers in spacetime_reader.hpp turn
// tagged tables into engine values.

#include <map>
#include <string>
#include <vector>

#include "lua/sandbox.hpp"

namespace lc {

// What the engine's pure functions returned to a shot, kept across the
// sandboxes in which its frames run (script/shot.hpp: each frame runs the
// script afresh): equal arguments give equal results, so a kept result
// cannot make one frame depend on another, and the dihole's lc.apocentres
// (a worldline integrated at the script's top level) is not integrated
// again for every frame.
class EngineMemo {
 public:
  struct Apocentre {
    double t, tau, r;  // scene time, proper time, radius
  };
  // The apocentres of the worldline whose WorldlineSpec::key() is `key`,
  // computed by `compute` the first time.
  template <class F>
  const std::vector<Apocentre>& apocentres(const std::string& key, F&& compute) {
    auto it = apocentres_.find(key);
    if (it == apocentres_.end()) it = apocentres_.emplace(key, compute()).first;
    return it->second;
  }

 private:
  std::map<std::string, std::vector<Apocentre>> apocentres_;
};

// Installs the API in `sandbox`; `memo` (may be null: nothing kept) must
// outlive the sandbox's use of it.
void install_engine_api(lua::Sandbox& sandbox, EngineMemo* memo = nullptr);

}  // namespace lc

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

#include "lua/sandbox.hpp"

namespace lc {

void install_engine_api(lua::Sandbox& sandbox);

}  // namespace lc

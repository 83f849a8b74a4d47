#pragma once
// The reference of every scene constructor lc.<name>{...} (spacetimes,
// cameras, skies, objects) as Markdown tables, made from their declared
// fields: what `lightcone fields` prints and docs/shots.md holds (a test
// checks the two agree).

#include <string>

namespace lc {

std::string constructor_tables();

}  // namespace lc

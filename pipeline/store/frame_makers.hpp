#pragma once
// Who rendered a frame, as its journal line records it (journal.hpp) and
// the work queue gathers it: apart from the journal's header, so the farm's
// loops need nothing of cameras or images to know it.

#include <cstddef>
#include <string>
#include <vector>

namespace lc::farm {

// The ranks whose working sets made a frame (a local farm's threads are
// rank 0), each with its node (its host name), as the journal records
// them.  A frame's stripes may go to many ranks: at most max_listed_ranks
// are listed (those that rendered most of it), `count` says how many there
// were.
struct FrameMakers {
  struct Rank {
    int rank = 0;
    std::string node;
    bool operator==(const Rank&) const = default;
  };
  std::vector<Rank> ranks;  // ascending by rank; empty: not recorded (older journals)
  int count = 0;            // ranks that made it, listed or not
  bool operator==(const FrameMakers&) const = default;
};
inline constexpr std::size_t max_listed_ranks = 16;

}  // namespace lc::farm

#pragma once
// What each MPI worker holds: the working sets the master handed it and it
// has not yet returned.  The master's loop keeps it; the event log's
// progress thread reads it, so a monitor can say what every rank is doing
// (docs/monitor.md).  Thread-safe.

#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "schedule/work_item.hpp"
#include "store/event_file.hpp"

namespace lc::farm {

class RankBoard {
 public:
  // A worker joined: it is listed (holding nothing) from now on.
  void joined(int rank);
  void handed(int rank, const std::vector<WorkItem>& items);
  // A set came back (a result); a set the board does not know is ignored
  // (the work queue is what refuses duplicates).
  void returned(int rank, const WorkItem& item);
  // Every joined worker, ascending by rank.
  std::vector<RankHolding> holdings() const;

 private:
  mutable std::mutex mutex_;
  std::map<int, std::vector<WorkItem>> held_;
};

}  // namespace lc::farm

#pragma once
// What each MPI worker holds: the working sets the master handed it and it
// has not yet returned.  The master's loop keeps it; the event log's
// progress thread reads it, so a monitor can say what every rank is doing
// (docs/monitor.md).  Thread-safe.

#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "schedule/work_queue.hpp"

namespace lc::farm {

// One worker's share of the work at a moment.
struct RankHolding {
  int rank = 0;
  int sets = 0;             // sets handed out and not returned
  std::vector<int> frames;  // the frames they belong to, ascending, each once
  bool operator==(const RankHolding&) const = default;
};

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

// "1:2:3+4,3:1:4" (rank:sets:frames, frames joined by '+'), the event log's
// `held` field, and back; a malformed entry is skipped when read.  Only
// ranks holding sets are written (one not listed holds none), and at most
// `max_chars` of them: an event line must stay under the log's limit on a
// farm of thousands of ranks.  `complete` says whether every one fitted.
std::string format_holdings(const std::vector<RankHolding>& holdings, std::size_t max_chars = 8192,
                            bool* complete = nullptr);
std::vector<RankHolding> parse_holdings(const std::string& text);

}  // namespace lc::farm

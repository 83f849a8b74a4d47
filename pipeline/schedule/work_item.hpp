#pragma once
// A working set: one stripe of one frame, in the preview pass or the full
// one.  What the hand-out gives, a stage renders and a transport carries.

namespace lc::farm {

enum class Pass { preview, full };

struct WorkItem {
  int frame = 0;
  int stripe = 0;
  Pass pass = Pass::full;
  bool operator==(const WorkItem&) const = default;
};

}  // namespace lc::farm

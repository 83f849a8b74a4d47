#pragma once
// Frame ranges as VFX tools write them: "A", "A:B" (inclusive) or "A:B:STEP".

#include <string>
#include <vector>

namespace lc {

struct FrameRange {
  int first = 0, last = 0, step = 1;
  std::vector<int> frames() const;
  // The last frame taken: `last` itself only when it is on the step
  // (0:95:8 takes 0, 8, ..., 88, as VFX frame ranges do).
  int last_taken() const { return last - (last - first) % step; }
};

// Parses `text` for a shot with `count` frames (0 .. count-1).  Throws
// std::invalid_argument naming `flag` and the problem.
FrameRange parse_frame_range(const std::string& text, int count, const std::string& flag);

// The whole shot.
FrameRange all_frames(int count);

}  // namespace lc

#include "store/frame_list.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace lc::farm {

std::string format_frame_list(std::vector<int> frames, int max_items) {
  std::sort(frames.begin(), frames.end());
  std::string out;
  int items = 0;
  for (std::size_t i = 0; i < frames.size();) {
    std::size_t j = i;
    while (j + 1 < frames.size() && frames[j + 1] == frames[j] + 1) ++j;
    if (items++ == max_items) {
      out += fmt::format(", ... ({} frames in all)", frames.size());
      break;
    }
    if (!out.empty()) out += ", ";
    out += j == i ? fmt::format("{}", frames[i]) : fmt::format("{}-{}", frames[i], frames[j]);
    i = j + 1;
  }
  return out;
}

std::string frames_were(const std::vector<int>& frames) {
  return frames.size() == 1 ? fmt::format("frame {} was", frames[0])
                            : fmt::format("frames {} were", format_frame_list(frames));
}

}  // namespace lc::farm

#include "frame_range.hpp"

#include <charconv>
#include <stdexcept>

#include <fmt/format.h>

namespace lc {

std::vector<int> FrameRange::frames() const {
  std::vector<int> out;
  for (int f = first; f <= last; f += step) out.push_back(f);
  return out;
}

FrameRange all_frames(int count) { return {0, count - 1, 1}; }

FrameRange parse_frame_range(const std::string& text, int count, const std::string& flag) {
  std::vector<int> parts;
  std::size_t pos = 0;
  while (true) {
    const std::size_t colon = text.find(':', pos);
    const std::string piece = text.substr(pos, colon == std::string::npos ? std::string::npos : colon - pos);
    int v = 0;
    const auto [end, ec] = std::from_chars(piece.data(), piece.data() + piece.size(), v);
    if (piece.empty() || ec != std::errc() || end != piece.data() + piece.size())
      throw std::invalid_argument(
          fmt::format("{} '{}': expected A, A:B or A:B:STEP with whole numbers (frames are numbered from 0)", flag, text));
    parts.push_back(v);
    if (colon == std::string::npos) break;
    pos = colon + 1;
  }
  if (parts.size() > 3) throw std::invalid_argument(fmt::format("{} '{}': at most A:B:STEP", flag, text));
  FrameRange r{parts[0], parts.size() > 1 ? parts[1] : parts[0], parts.size() > 2 ? parts[2] : 1};
  if (r.step < 1) throw std::invalid_argument(fmt::format("{} '{}': STEP must be >= 1", flag, text));
  if (r.first < 0 || r.last < r.first || r.last >= count)
    throw std::invalid_argument(fmt::format("{} '{}': the shot has frames 0 to {} (ranges are inclusive, A <= B)",
                                            flag, text, count - 1));
  return r;
}

}  // namespace lc

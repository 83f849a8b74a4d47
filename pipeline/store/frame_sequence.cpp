#include "store/frame_sequence.hpp"

#include <algorithm>
#include <numeric>
#include <regex>
#include <stdexcept>
#include <system_error>

#include <fmt/format.h>

namespace lc {

namespace fs = std::filesystem;

std::map<std::string, FrameSequence> find_frame_sequences(const fs::path& dir) {
  // Input: a directory; output: its shots' PNG frames, sorted by number.
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw std::runtime_error(fmt::format("{}: {}", dir.string(), fs::exists(dir, ec) ? "not a directory" : "no such directory"));
  // The frame store writes at least four digits ({:04d}); more once a shot
  // passes frame 9999.  The shot name may itself contain dots.
  static const std::regex name(R"((.+)\.([0-9]{4,})\.png)");
  std::map<std::string, std::map<int, fs::path>> found;
  fs::directory_iterator it(dir, ec);
  if (ec) throw std::runtime_error(fmt::format("cannot list {}: {}", dir.string(), ec.message()));
  for (const fs::directory_entry& entry : it) {
    if (!entry.is_regular_file(ec)) continue;
    const std::string file = entry.path().filename().string();
    std::smatch m;
    if (!std::regex_match(file, m, name)) continue;
    if (m[2].length() > 9) continue;  // not a frame number lightcone writes (and would overflow int)
    found[m[1]][std::stoi(m[2])] = entry.path();
  }
  std::map<std::string, FrameSequence> out;
  for (auto& [shot, frames] : found) {
    FrameSequence s{shot, {}, {}};
    for (auto& [n, p] : frames) {
      s.frames.push_back(n);
      s.files.push_back(p);
    }
    out.emplace(shot, std::move(s));
  }
  return out;
}

namespace {
// "a, b, c" of the map's keys, for messages.
std::string shot_list(const std::map<std::string, FrameSequence>& all) {
  std::string s;
  for (const auto& [shot, seq] : all)
    s += fmt::format("{}{} ({} frames)", s.empty() ? "" : ", ", shot, seq.frames.size());
  return s;
}
}  // namespace

FrameSequence select_frame_sequence(const fs::path& dir, const std::optional<std::string>& shot) {
  // Inputs: the directory and the --shot choice; output: one shot's frames.
  auto all = find_frame_sequences(dir);
  if (all.empty())
    throw std::runtime_error(fmt::format("{}: no frames (expected files named <shot>.<NNNN>.png)", dir.string()));
  if (shot) {
    auto it = all.find(*shot);
    if (it == all.end())
      throw std::runtime_error(
          fmt::format("--shot {}: no frames of that shot in {} (found: {})", *shot, dir.string(), shot_list(all)));
    return std::move(it->second);
  }
  if (all.size() > 1)
    throw std::runtime_error(fmt::format("{} holds the frames of {} shots: {}; choose one with --shot", dir.string(),
                                         all.size(), shot_list(all)));
  return std::move(all.begin()->second);
}

FrameSpacing frame_spacing(const std::vector<int>& frames) {
  // Input: ascending distinct numbers; output: their step and the holes.
  FrameSpacing s;
  const std::size_t n = frames.size();
  // The step of all but the last frame, and of all of them.
  int body = 0;
  for (std::size_t i = 1; i + 1 < n; ++i) body = std::gcd(body, frames[i] - frames[i - 1]);
  const int last_gap = n >= 2 ? frames[n - 1] - frames[n - 2] : 0;
  s.final_off_step = n >= 3 && last_gap < body;
  const int g = s.final_off_step ? body : std::gcd(body, last_gap);
  s.step = g > 0 ? g : 1;
  const std::size_t progression = s.final_off_step ? n - 1 : n;
  for (std::size_t i = 1; i < progression; ++i)
    for (int f = frames[i - 1] + s.step; f < frames[i]; f += s.step) s.missing.push_back(f);
  return s;
}

std::string describe_range(const std::vector<int>& frames, const FrameSpacing& spacing) {
  if (frames.empty()) return "no frames";
  const int end = spacing.final_off_step ? frames[frames.size() - 2] : frames.back();
  std::string out = fmt::format("{}-{}", frames.front(), end);
  if (spacing.step > 1) out += fmt::format(" every {}", spacing.step);
  if (spacing.final_off_step) out += fmt::format(", then {}", frames.back());
  return out;
}

std::string describe_frames(const std::vector<int>& frames, int step, int max_items) {
  // Input: ascending members of a progression with `step`; output: the
  // compact text.  Counting stops at max_items runs so a huge hole list
  // still gives a one-line message.
  std::string out;
  int items = 0;
  for (std::size_t i = 0; i < frames.size();) {
    std::size_t j = i;
    while (j + 1 < frames.size() && frames[j + 1] == frames[j] + step) ++j;
    if (items == max_items) {
      out += fmt::format(", ... ({} frames in all)", frames.size());
      break;
    }
    if (!out.empty()) out += ", ";
    out += j == i ? fmt::format("{}", frames[i]) : fmt::format("{}-{}", frames[i], frames[j]);
    ++items;
    i = j + 1;
  }
  return out;
}

void require_complete(const FrameSequence& sequence, const fs::path& dir, const std::vector<int>& lost) {
  // Input: a found sequence; throws when it has holes, returns otherwise.
  FrameSpacing s = frame_spacing(sequence.frames);
  if (s.missing.empty() && lost.empty()) return;
  if (!lost.empty()) {
    // Lost frames between the members of a step are holes of every frame.
    s.missing.insert(s.missing.end(), lost.begin(), lost.end());
    std::sort(s.missing.begin(), s.missing.end());
    s.missing.erase(std::unique(s.missing.begin(), s.missing.end()), s.missing.end());
    s.step = 1;
    s.final_off_step = false;
  }
  const std::string range = "frames " + describe_range(sequence.frames, s);
  // With a step, "30-50" in the list means 30, 40, 50: the range text
  // before it ("frames 0-890 every 10") says so.
  throw std::runtime_error(fmt::format("{}: shot {}, {}: missing frame{} {} (render them, or encode a complete range)",
                                       dir.string(), sequence.shot, range, s.missing.size() == 1 ? "" : "s",
                                       describe_frames(s.missing, s.step)));
}

}  // namespace lc

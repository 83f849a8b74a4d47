#pragma once
// The frames of one shot as the renderer leaves them in a directory
// (DIR/<shot>.<NNNN>.png), and the check that they form a whole sequence:
// every frame from the first to the last, or every k-th (a preview rendered
// with --frames 0:899:10), with nothing missing in between.

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace lc {

struct FrameSequence {
  std::string shot;
  std::vector<int> frames;                   // ascending frame numbers
  std::vector<std::filesystem::path> files;  // the PNG of each, same order
};

// Every shot with PNG frames directly in `dir`, by name.  Only final names
// count ("<shot>.<digits>.png"; temporaries such as "x.0001.png.tmp-12" and
// subdirectories are skipped).  Throws std::runtime_error naming `dir` when
// it is missing or not a directory.
std::map<std::string, FrameSequence> find_frame_sequences(const std::filesystem::path& dir);

// The sequence to use from `dir`: the one called `shot` if given, else the
// only one there.  Throws std::runtime_error naming the directory when it
// holds no frames, when `shot` has none (listing the shots found), or when
// several shots are there and none was chosen (listing them, suggesting --shot).
FrameSequence select_frame_sequence(const std::filesystem::path& dir, const std::optional<std::string>& shot);

// The spacing of ascending, distinct frame numbers: the step is the greatest
// common divisor of the gaps (1 for one frame), so a sequence rendered every
// k-th frame with a frame lost still shows step k; `missing` lists what the
// progression first, first+step, ..., last lacks.  One exception: a
// progression of at least two frames followed by one frame closer than its
// step (--frames 0:95:8 renders 0, 8, ..., 88; a render of --frames 95 adds
// the shot's last frame) is whole, with `final_off_step` set: a preview
// that ends on the shot's last frame.
struct FrameSpacing {
  int step = 1;
  std::vector<int> missing;
  bool final_off_step = false;  // the last frame follows the progression at less than a step
};
FrameSpacing frame_spacing(const std::vector<int>& frames);

// "0-88 every 8, then 95", "0-9 every 3", "0-11": the sequence's range for
// messages.
std::string describe_range(const std::vector<int>& frames, const FrameSpacing& spacing);

// Missing frames written compactly: runs of consecutive members of the
// progression (a, a+step, ..., b) as "a-b", others alone, comma-separated:
// "12-15, 40".  At most `max_items` items, then ", ... (N frames in all)".
std::string describe_frames(const std::vector<int>& frames, int step, int max_items = 12);

// Throws std::runtime_error when `sequence` has holes, naming the directory,
// the shot, its range and step and the missing frames (describe_frames).
// `lost` adds holes known otherwise (frames the journal says were rendered
// and whose files are gone), which need not lie on the sequence's step.
void require_complete(const FrameSequence& sequence, const std::filesystem::path& dir,
                      const std::vector<int>& lost = {});

}  // namespace lc

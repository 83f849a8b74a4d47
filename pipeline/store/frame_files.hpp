#pragma once
// Where a shot's frames live: DIR/<shot>.<NNNN>.exr (linear float, zip, data
// layers) and DIR/<shot>.<NNNN>.png (8-bit sRGB), and whether those a
// command reads are current by the journal.  Writing them is the frame
// store's job (frame_store.hpp, frame_writer.hpp).

#include <filesystem>
#include <string>
#include <vector>

namespace lc::farm {

// DIR/<shot>.<NNNN>.<extension>: the frame number in four digits or more,
// which the frame sequence reader (store/frame_sequence.hpp) relies on.
std::filesystem::path frame_path(const std::filesystem::path& dir, const std::string& shot, int frame,
                                 const char* extension);

// Checks the PNG frames `frames` of `shot` in `dir` against the shot's
// journal (stale_frames), for the commands that show them together
// (`command`: encode, contact-sheet).  Frames rendered with other settings
// or from an earlier version of the shot than the latest render, or not
// recorded as finished, are refused with std::runtime_error naming them,
// why, and what to do — unless `allow_stale`, when the same is said on
// stderr as a warning.  Returns the frames the journal records like the
// latest render between the first and last of `frames` whose PNG is gone
// (holes that the frame numbers alone may not show).  Without a journal
// (frames made elsewhere) there is nothing to check.
std::vector<int> check_frames_current(const std::filesystem::path& dir, const std::string& shot,
                                      const std::vector<int>& frames, bool allow_stale, const char* command);

}  // namespace lc::farm

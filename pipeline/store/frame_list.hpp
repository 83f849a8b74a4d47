#pragma once
// Frame numbers in sentences: what the journal's refusals, the resume plan
// and the render's summary say about sets of frames.

#include <string>
#include <vector>

namespace lc::farm {

// "0-4, 7, 9-12": a sorted or unsorted list of frame numbers, compactly; at
// most `max_items` runs, then ", ... (N frames in all)" (a preview's frames
// every 10th would otherwise fill the screen).
std::string format_frame_list(std::vector<int> frames, int max_items = 12);

// "frame 3 was" / "frames 0-4, 7 were": the start of a sentence about frames.
std::string frames_were(const std::vector<int>& frames);

}  // namespace lc::farm

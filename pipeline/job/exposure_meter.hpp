#pragma once
// The metering pass of automatic exposure (a shot's `auto_exposure`;
// docs/light.md): frames of the shot rendered small, their light read
// (image/auto_exposure.hpp), the readings kept in DIR/<shot>.meter so that a
// resumed or partial render reads them instead of metering again.
//
// A frame's exposure must not depend on which frames were rendered before
// it, in which run or on which rank: it is a function of the readings of
// the frames its smoothing reaches (auto_exposure.hpp's metered_exposures),
// so exactly those are metered, whichever frames a run renders: the frames
// within the smoothing's reach of each frame asked for, and for a frame
// with no lit frame within reach, those out to the nearest lit one on each
// side (or the shot's end), whose fit it takes.  Each reading depends only
// on its frame's inputs (the script, modules and its sky's files, hashed),
// the meter's size and the camera the shot is delivered through, and its
// rows are rendered exactly as any split would: the same readings
// everywhere, so the same exposures.

#include <cstddef>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "script/shot.hpp"

namespace lc::farm {

// The meter's image: 64 pixels wide, at the frame's aspect.
inline constexpr int meter_width = 64;

struct MeterReadings {
  int width = 0, height = 0;        // the meter's image
  std::map<int, double> readings;   // frame -> luminance_percentile of it, for the frames metered
};

// How the pass reports: `each(done, total)` after each frame metered or
// read back (total grows where a dark frame needs more); it may throw to
// stop the pass (a signal), which still keeps what it metered.
using MeterProgress = std::function<void(std::size_t done, std::size_t total)>;

// The readings the exposures of `frames` (ascending) need, for frames of
// `frame_width` x `frame_height` (the whole frame's, not a --region's):
// read from DIR/<shot>.meter where a frame's line matches its inputs, the
// rest metered on `threads` threads, and the file rewritten durably with
// both.  Throws what the script or a scene throws (naming the frame), or
// std::runtime_error naming the meter file when it cannot be written.
MeterReadings shot_readings(Shot& shot, const std::filesystem::path& dir, int frame_width, int frame_height,
                            int threads, const std::vector<int>& frames, const MeterProgress& each = {});

// Each listed frame's exposure in stops, the metered one plus the shot's
// or the frame's own (`own`: frame -> the frame's `exposure`, where it
// gives one); `meter` must hold the readings shot_readings gave for them.
std::map<int, double> auto_exposures(const ShotInfo& info, const MeterReadings& meter,
                                     const std::map<int, std::optional<double>>& own);

}  // namespace lc::farm

#pragma once
// The metering pass of automatic exposure (a shot's `auto_exposure`;
// docs/light.md): every frame of the shot rendered small, its light read
// (image/auto_exposure.hpp), the readings kept in DIR/<shot>.meter so that a
// resumed or partial render reads them instead of metering again.
//
// Why a pass over the whole shot, not the frames of this run nor the
// journal's neighbours: a frame's exposure must not depend on which frames
// were rendered before it, in which run or on which rank.  The pass
// depends only on the shot (its script, modules and sky files, hashed into
// the file's key), the frame's aspect and the camera it is delivered
// through, and its rows are rendered exactly as any split would: the same
// readings everywhere, so the same exposures.

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "script/shot.hpp"

namespace lc::farm {

// The meter's image: 64 pixels wide, at the frame's aspect.
inline constexpr int meter_width = 64;

struct MeterReadings {
  std::string key;               // 16 hex: what the readings were made from
  int width = 0, height = 0;     // the meter's image
  std::vector<double> readings;  // one a frame of the shot, luminance_percentile of each
};

// The readings of every frame of `shot` for frames of `frame_width` x
// `frame_height` (the whole frame's, not a --region's): read from
// DIR/<shot>.meter when its key matches, else metered on `threads` threads
// (progress on stderr) and written there durably.  Throws what the script
// or a scene throws (naming the frame), or std::runtime_error naming the
// meter file when it cannot be written.
MeterReadings shot_readings(Shot& shot, const std::filesystem::path& dir, int frame_width, int frame_height,
                            int threads);

// Each listed frame's exposure in stops, the metered one plus the shot's
// or the frame's own (`own`: frame -> the frame's `exposure`, where it
// gives one).
std::map<int, double> auto_exposures(const ShotInfo& info, const MeterReadings& meter,
                                     const std::map<int, std::optional<double>>& own);

}  // namespace lc::farm

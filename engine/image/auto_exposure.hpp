#pragma once
// Automatic exposure: each frame's exposure from its own light, smoothed
// over its neighbours in the shot (docs/light.md, "Exposure that follows
// the light").  Pure functions of the readings, so a frame gets the same
// exposure whichever frames a run renders, on whichever rank.

#include <cmath>
#include <functional>
#include <map>
#include <span>
#include <vector>

#include "image/frame_image.hpp"

namespace lc {

// The share of pixels the meter reads below: the 99th percentile of
// luminance, so the brightest 1% (the beamed side of a disk, a lensed
// star's image) may go past the display's white and everything else is
// placed by the light the frame is about.
inline constexpr double meter_percentile = 0.99;

// The meter's reading of a frame: the luminance (Rec. 709, linear) below
// which `fraction` of its pixels lie, by the nearest-rank rule (the
// ceil(fraction n)-th smallest).  NaN and negative luminance count as 0.
// Assumes a non-empty image.
double luminance_percentile(const FrameImage& image, double fraction = meter_percentile);

// Whether a reading is of a lit frame (finite and above 0): only those
// take part in metered_exposures' fit.
inline bool lit_reading(double reading) { return std::isfinite(reading) && reading > 0.0; }

// How many frames either side of a frame metered_exposures' fit reaches at
// `smoothing` (3 of its standard deviations; 0 for none).
inline long smoothing_reach(double smoothing) {
  return smoothing > 0.0 ? static_cast<long>(std::ceil(3.0 * smoothing)) : 0;
}

// Each frame's exposure in stops from its reading, so that the reading is
// shown at `level` (the linear light before the view: 1, the display's
// white): e_i = log2(level / reading_i), then smoothed in stops by a local
// linear fit (Cleveland 1979): at each frame a straight line fitted by
// least squares to the frames within 3 `smoothing` of it, weighted by a
// Gaussian of standard deviation `smoothing` frames (0: none), read at the
// frame.  So a steady climb of the light is followed exactly, to the
// shot's last frame (a plain weighted mean would lag there, where its
// window is one-sided), while a flicker from frame to frame is evened out.
// A frame whose reading is 0 or not finite (nothing lit) takes no part: it
// gets the exposure the fit gives there from its lit neighbours, else the
// nearest placed frame's (the earlier on a tie), or 0 when nothing in the
// shot is lit.  Every exposure is clamped to [-64, 64], the shot's range.
std::vector<double> metered_exposures(std::span<const double> readings, double level, double smoothing);

// The readings the exposures of `frames` (ascending, of a shot of `count`
// frames) depend on at `smoothing`, so a render of a few frames meters only
// those: metered_exposures' fit at a frame reaches smoothing_reach frames
// either side, and a frame with no lit frame within reach takes the fit of
// the nearest placed frame on each side, whose fits reach the nearest lit
// frames.  `take(batch)` gives the readings of a batch of frames (ascending):
// first every frame within reach of one of `frames`, in one batch; then one
// at a time outwards from a dark frame's reach, to the nearest lit frame or
// the shot's end.  Returns every reading taken, by frame.
std::map<int, double> needed_readings(std::span<const int> frames, int count, double smoothing,
                                      const std::function<std::vector<double>(const std::vector<int>&)>& take);

// Each of `frames`' exposure from the readings needed_readings took for
// them: what metered_exposures over the whole shot's readings gives it,
// to the bit (the fit over the span of frames taken, the frames not taken
// in it, as unlit, lying beyond the reach of every frame of `frames`).
std::map<int, double> exposures_from(const std::map<int, double>& readings, std::span<const int> frames, double level,
                                     double smoothing);

}  // namespace lc

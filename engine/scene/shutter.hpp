#pragma once
// A camera's shutter (docs/motion_blur.md): how long it stays open, in
// units of the frame interval (0: closed, every sample at the frame's own
// moment), where that interval lies against the frame's moment, and into
// how many instants it is cut.  The shot is evaluated at each instant (a
// fractional frame number) and built into a scene of its own; each sample
// of a pixel takes one instant, stratified with its place in the pixel
// (render/sample_times.hpp).  Plain data: the shot's fields (ShotInfo), a
// frame's `shutter` and the command line's flags meet here.

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/constants.hpp"
#include "core/fields.hpp"

namespace lc {

// Where the open interval lies against the frame's moment t: centred on it
// ([t - s/2, t + s/2], the film camera's), starting at it ([t, t + s]) or
// ending at it ([t - s, t]): Cycles' motion position.
enum class ShutterPosition { centre, start, end };
constexpr std::array<std::string_view, 3> choice_names(ShutterPosition) { return {"centre", "start", "end"}; }

struct Shutter {
  double open = 0.0;  // in frame intervals, [0, 1]; 0: closed
  ShutterPosition position = ShutterPosition::centre;
  int time_samples = 8;  // instants of the open interval; a pixel sampled in full takes at least this many samples

  bool closed() const { return open == 0.0; }
  // Offset of instant k (0 .. time_samples-1) from the frame's moment, in
  // frame intervals: the centre of the k-th of time_samples equal parts
  // of the open interval (stratified in time, as in space).
  double instant(int k) const {
    const double first = position == ShutterPosition::centre ? -0.5 * open
                         : position == ShutterPosition::start ? 0.0
                                                              : -open;
    return first + open * (k + 0.5) / time_samples;
  }
  std::vector<double> instants() const {
    std::vector<double> out;
    if (!closed())
      for (int k = 0; k < time_samples; ++k) out.push_back(instant(k));
    return out;
  }
  // "shutter 0.5 (centre, 8 instants)"; "shutter closed".
  std::string describe() const;
};

// What the command line sets of the shutter, over the shot's and its
// frames' (render --shutter, --shutter-position, --time-samples); unset:
// as the shot says.
struct ShutterOverride {
  std::optional<double> open{};
  std::optional<ShutterPosition> position{};
  std::optional<int> time_samples{};
  bool any() const { return open || position || time_samples; }
  bool operator==(const ShutterOverride&) const = default;
};

// The shutter of a frame: the shot's, its frame's `shutter` (if it gave
// one), then the command line's, each over the one before.
inline Shutter frame_shutter(const Shutter& shot, std::optional<double> frame_open, const ShutterOverride& over) {
  Shutter s = shot;
  if (frame_open) s.open = *frame_open;
  if (over.open) s.open = *over.open;
  if (over.position) s.position = *over.position;
  if (over.time_samples) s.time_samples = *over.time_samples;
  return s;
}

}  // namespace lc

#pragma once
// Image sizes as the command line takes them: "WxH" for --size (render,
// trace, showcase, farm-bench, encode's title cards), and the size a render
// or trace ends up with after --size and --scale.

#include <optional>
#include <string>
#include <utility>

#include "camera/image_window.hpp"

namespace lc {

// The largest side a frame may have (the renderer's limit; encoders have
// their own, see video/encode_options.hpp).
inline constexpr int max_frame_side = 16384;

// "1280x720" (or "1280X720") -> {1280, 720}.  Strict: two runs of decimal
// digits around one 'x', nothing else — no sign, space, fraction or
// trailing text — and each number must fit an int (a wrapped-around size
// would silently render something else).  Zero is let through for the
// caller's range check.  Throws std::invalid_argument naming `flag` and the
// text.
std::pair<int, int> parse_image_size(const std::string& text, const std::string& flag);

// "I,J" -> {I, J}: a pixel's column and row, as strictly as a size.
std::pair<int, int> parse_pixel(const std::string& text, const std::string& flag);

// Image size after --size and --scale, for render and trace alike: `size`
// (if given) replaces width x height, then both are multiplied by `scale`
// and rounded.  Throws std::invalid_argument naming the flag when the text
// is not a size, the scale is not a positive number, or a side ends up
// outside 1 .. max_frame_side.
std::pair<int, int> output_size(int width, int height, const std::optional<std::string>& size, double scale);

// A window of a width x height frame (render --region).
struct Region {
  ImageWindow window;     // where it is in the frame
  int width, height;      // its size: the image rendered
};

// "X0,Y0,X1,Y1" -> the window of pixels X0 .. X1-1, Y0 .. Y1-1 of a
// frame_width x frame_height frame.  Strict as a size; throws
// std::invalid_argument naming --region when it is not four whole numbers,
// is empty (X1 <= X0 or Y1 <= Y0) or reaches outside the frame (saying
// the frame's size).
Region parse_region(const std::string& text, int frame_width, int frame_height);

}  // namespace lc

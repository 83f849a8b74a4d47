#pragma once
// The monitor's pixel inspector: what `lightcone trace` reports for one
// pixel of a rendered frame, with the ray's path, as JSON.  The trace runs
// in a child process (`tracer`, the lightcone binary itself), so a shot
// script's evaluation never runs inside the server and a slow one is cut
// off, not waited on forever; it runs at a low priority (nice 10), so a
// render on the same node keeps its CPUs.

#include <filesystem>
#include <string>
#include <vector>

#include "camera/delivery_camera.hpp"

namespace lc::monitor {

struct PixelRequest {
  std::filesystem::path script;  // the shot, as the render's event log names it
  int frame = 0, x = 0, y = 0;   // the pixel: column x, row y of the frame
  int width = 0, height = 0;     // the frame's size as rendered
  Delivery delivery{};           // as render --camera ... --sky made the frame
};

// The flags that ask `lightcone trace` for the delivery `d` ("--camera",
// "dome", "--dome-tilt", "15"; the defaults left out), as render's
// (pipeline/job/delivery_flags.hpp) read them: a frame traced as the journal
// recorded it was made.
std::vector<std::string> delivery_flag_words(const Delivery& d);

// {"report": <trace --json's object>, "chart": "<the path's chart line>",
//  "path": [[x, y, z], ...]} with the path in Cartesian coordinates (a
// Boyer–Lindquist path converted: x = r sin(theta) cos(phi), ...).  Throws
// std::runtime_error with the trace's own message when it fails, or when it
// takes longer than `seconds`.
std::string trace_pixel_json(const std::filesystem::path& tracer, const PixelRequest& request, double seconds = 60.0);

}  // namespace lc::monitor

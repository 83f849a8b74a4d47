#include "inspect_command.hpp"

#include <cstdio>

#include <fmt/format.h>

#include "frame_range.hpp"
#include "scene/scene_json.hpp"
#include "scene/shot.hpp"

namespace lc {

int run_inspect(const InspectCommand& cmd) {
  Shot shot(cmd.shot);
  const ShotInfo& info = shot.info();
  const FrameRange range = cmd.frames ? parse_frame_range(*cmd.frames, info.frames, "--frames") : all_frames(info.frames);
  // Everything is evaluated before anything is printed: an error in frame 90
  // does not leave 89 frames of half a JSON document behind.
  std::string out = fmt::format(
      "{{\"shot\": {{\"name\": \"{}\", \"frames\": {}, \"fps\": {}, \"width\": {}, \"height\": {}, \"supersample\": {}}},\n"
      " \"scenes\": [\n",
      info.name, info.frames, info.fps, info.width, info.height, info.supersample);
  bool first = true;
  for (int f : range.frames()) {
    out += (first ? "  " : ",\n  ") + to_json(shot.frame(f), f);
    first = false;
  }
  out += "\n]}\n";
  std::fwrite(out.data(), 1, out.size(), stdout);
  return 0;
}

}  // namespace lc

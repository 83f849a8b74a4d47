#include "inspect_command.hpp"

#include <cstdio>

#include <fmt/format.h>

#include "frame_range.hpp"
#include "render/evaluated_json.hpp"
#include "render/scene_builder.hpp"
#include "scene/scene_json.hpp"
#include "scene/shot.hpp"

namespace lc {

int run_inspect(const InspectCommand& cmd) {
  Shot shot(cmd.shot);
  const ShotInfo& info = shot.info();
  const FrameRange range = cmd.frames ? parse_frame_range(*cmd.frames, info.frames, "--frames") : all_frames(info.frames);
  // Everything is evaluated before anything is printed: an error in frame 90
  // does not leave 89 frames of half a JSON document behind.  Each scene is
  // built as render builds it (observer, worldlines, textures), so inspect
  // refuses what render would, short of tracing a ray.
  ShotResources resources(shot.asset_dirs());
  std::string out = fmt::format(
      "{{\"shot\": {{\"name\": \"{}\", \"frames\": {}, \"fps\": {}, \"width\": {}, \"height\": {}, \"supersample\": {}}},\n"
      " \"scenes\": [\n",
      info.name, info.frames, info.fps, info.width, info.height, info.supersample);
  bool first = true;
  for (int f : range.frames()) {
    const FrameScene fs = shot.frame(f);
    const Scene scene = build_frame_scene(fs, cmd.shot, f, info.width, info.height, resources);
    out += (first ? "  " : ",\n  ") + to_json(fs, f, evaluated_json(scene));
    first = false;
  }
  out += "\n]}\n";
  std::fwrite(out.data(), 1, out.size(), stdout);
  return 0;
}

}  // namespace lc

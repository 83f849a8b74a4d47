#include "inspect_command.hpp"

#include <cstdio>

#include <fmt/format.h>

#include "job/frame_range.hpp"
#include "render/evaluated_json.hpp"
#include "render/scene_builder.hpp"
#include "scene/scene_json.hpp"
#include "script/shot.hpp"

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
  // fields_json writes ", \"name\": ..." for each declared field.
  std::string out = fmt::format("{{\"shot\": {{{}}},\n \"scenes\": [\n", fields_json(info).substr(2));
  bool first = true;
  for (int f : range.frames()) {
    const SceneSpec fs = shot.frame(f);
    const Scene scene = build_scene(fs, cmd.shot, f, info.width, info.height, resources);
    out += (first ? "  " : ",\n  ") + to_json(fs, f, evaluated_json(scene));
    first = false;
  }
  out += "\n]}\n";
  std::fwrite(out.data(), 1, out.size(), stdout);
  return 0;
}

}  // namespace lc

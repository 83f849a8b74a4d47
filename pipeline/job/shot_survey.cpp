#include "job/shot_survey.hpp"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

#include "store/content_hash.hpp"
#include "assets/asset_path.hpp"
#include "scene/frame_specs.hpp"
#include "scene/scene_skies.hpp"

namespace lc::farm {

namespace fs = std::filesystem;

ShotSurvey survey_shot(Shot& shot, const std::vector<int>& frames, const std::function<void(std::size_t)>& each) {
  ShotSurvey out;
  const auto dirs = shot.asset_dirs();
  std::map<int, std::vector<std::string>> sky_files_of;  // frame -> the files its sky reads
  for (int f : frames) {
    const FrameSpecs specs = shot.frame_specs(f);
    const SceneSpec& fs = specs.frame;
    out.frames[f].spacetime = describe(fs.spacetime);
    out.frames[f].sky = fs.sky;
    out.frames[f].camera = fs.camera;
    out.frames[f].exposure = fs.exposure;
    for (const SceneSpec& at : specs.instants) out.frames[f].instants.push_back({at.sky, at.camera});
    if (specs.blurred()) out.frames[f].shutter = specs.shutter.describe();
    // Every sky's files, a further end's too (a wormhole's other side).
    for_each_sky(fs, [&](std::string_view, const SkySpec& sky) {
      for (const std::string& asset : sky_assets(sky)) {
        // The file the render will load (the same rules): checked before
        // anything reads it, for the hash below.
        try {
          sky_files_of[f].push_back(resolve_sky_image(asset, dirs).string());
        } catch (const std::invalid_argument& e) {
          throw std::invalid_argument(fmt::format("{}: frame {}: {}", shot.file().string(), f, e.what()));
        }
      }
      // (A catalogue's own checks are the sky's, made when the scene was read.)
      for (const std::string& file : sky_system_files(sky)) sky_files_of[f].push_back(file);
    });
    if (each) each(out.frames.size());
  }
  // Script and modules: after evaluating, so modules required inside
  // frame() are included.
  std::vector<std::uint64_t> script_hashes;
  for (const auto& p : shot.loaded_files()) {
    const std::uint64_t h = hash_file(p);
    out.files[p.string()] = to_hex(h);
    script_hashes.push_back(h);
  }
  std::sort(script_hashes.begin(), script_hashes.end());
  ContentHash base;
  for (auto h : script_hashes) base.add(h);
  for (auto& [f, facts] : out.frames) {
    ContentHash h = base;
    facts.parts.script = base.hex();
    if (auto it = sky_files_of.find(f); it != sky_files_of.end()) {
      for (const std::string& file : it->second) {
        auto known = out.files.find(file);
        if (known == out.files.end()) known = out.files.emplace(file, to_hex(hash_file(file))).first;
        h.add("sky image ").add(known->second);
        facts.parts.sky += (facts.parts.sky.empty() ? "" : "+") + known->second;
      }
    }
    facts.inputs = h.hex();
  }
  return out;
}

std::uint64_t job_digest(const Shot& shot, const RenderSettings& rs, int stripes, int preview_every) {
  const ShotInfo& i = shot.info();
  ContentHash h;
  h.add(i.name).add(std::uint64_t(i.frames)).add(fmt::format("{}", i.fps));
  h.add(std::uint64_t(rs.width)).add(std::uint64_t(rs.height)).add(std::uint64_t(rs.supersample));
  h.add(std::uint64_t(rs.layers)).add(std::uint64_t(stripes)).add(std::uint64_t(preview_every));
  h.add(std::uint64_t(rs.adaptive && rs.supersample > 1)).add(std::uint64_t(shot.delivery().camera));
  if (const Delivery& d = shot.delivery(); d.beyond_camera())  // (as for the window, below)
    h.add(delivery_fields(d));
  if (rs.window.windowed())  // (frames without a window hash as they always did)
    h.add(std::uint64_t(rs.window.x0)).add(std::uint64_t(rs.window.y0)).add(std::uint64_t(rs.window.frame_width))
        .add(std::uint64_t(rs.window.frame_height));
  if (const ShutterOverride& s = shot.shutter_override(); s.any())  // (as for the window)
    h.add(fmt::format("shutter {} {} {}", s.open ? fmt::format("{:a}", *s.open) : "-",
                      s.position ? std::string(choice_name(*s.position)) : "-",
                      s.time_samples ? std::to_string(*s.time_samples) : "-"));
  for (const auto& p : shot.loaded_files()) h.add(hash_file(p));
  return h.value();
}

}  // namespace lc::farm

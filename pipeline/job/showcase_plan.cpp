#include "showcase_plan.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "image_size.hpp"
#include "script/shot.hpp"
#include "video/contact_sheet.hpp"
#include "video/encode_options.hpp"

namespace lc {

namespace fs = std::filesystem;

ShowcaseQuality parse_showcase_quality(const std::string& name) {
  if (name == "preview") return ShowcaseQuality::preview;
  if (name == "production") return ShowcaseQuality::production;
  throw std::invalid_argument(fmt::format("--quality '{}': choose preview or production", name));
}

namespace {

// The paper's sequences in the order the film shows them, with their cards
// (the pixel font has capitals, digits and common punctuation only).
struct Sequence {
  const char* name;
  std::vector<std::string> title;
};
const std::vector<Sequence>& paper_sequences() {
  static const std::vector<Sequence> list = {
      {"kerr_accrDisk", {"A SPINNING BLACK HOLE", "ITS DISK SEEN FROM ABOVE TO THE EDGE;", "THEN SPIN, THEN MASS TO ZERO"}},
      {"kerr_passing", {"FALLING PAST IT", "A FREE-FALL ORBIT THROUGH THE DISK PLANE", "INSIDE THE INNER RIM, AND AWAY"}},
      {"dihole", {"TWO CHARGED BLACK HOLES", "A SPHERE OSCILLATING BETWEEN", "EXTREME REISSNER-NORDSTROM HOLES"}},
  };
  return list;
}
// The fourth, beside the paper's: its first storyboard in light as physics
// says (docs/light.md).
const Sequence& thermal_sequence() {
  static const Sequence s = {"kerr_accrDisk_thermal",
                             {"THE SAME HOLE IN ITS OWN LIGHT", "A DISK GLOWING AT ITS TEMPERATURES,", "SHIFTED AND BEAMED BY ITS MOTION"}};
  return s;
}

}  // namespace

ShowcasePlan plan_showcase(const ShowcaseSettings& settings, const fs::path& shots_dir) {
  // Inputs: the user's choices and where the shots are; output: every
  // clip's settings.  Assumes the shots play at one rate and size (checked).
  const bool preview = settings.quality == ShowcaseQuality::preview;
  if (settings.rate && !preview)
    throw std::invalid_argument("--rate: production renders every frame; --rate goes with --quality preview");
  const double rate = settings.rate.value_or(preview_fps);
  if (!(rate >= 0.01 && rate <= 240))
    throw std::invalid_argument(fmt::format("--rate {}: must be between 0.01 and 240 frames per second of story", rate));
  std::optional<std::pair<int, int>> size;
  if (settings.size) {
    size = output_size(1, 1, settings.size, 1.0);
    // The showcase always makes a video: a size H.264 cannot take would
    // only be refused after hours of rendering.
    if (const auto why = size_refusal(Codec::h264, size->first, size->second))
      throw std::invalid_argument(fmt::format("--size {}: {}", *settings.size, *why));
  } else if (settings.camera == DeliveryCamera::dome) {
    const int side = preview ? dome_preview_side : dome_production_side;
    size = {side, side};
  } else if (settings.camera == DeliveryCamera::sphere) {
    const int h = preview ? sphere_preview_height : sphere_production_height;
    size = {2 * h, h};
  } else if (preview) {
    size = {preview_width, preview_height};
  }
  ShowcasePlan plan;
  plan.camera = settings.camera;
  plan.opening = {"LIGHTCONE", "GENERAL-RELATIVISTIC BLACK HOLE VISUALIZATION",
                  "AFTER MULLER, BOBLEST AND WEISKOPF"};
  std::vector<Sequence> sequences = paper_sequences();
  if (settings.thermal) sequences.push_back(thermal_sequence());
  for (const Sequence& s : sequences) {
    const fs::path file = shots_dir / (std::string(s.name) + ".lua");
    std::error_code ec;
    if (!fs::is_regular_file(file, ec))
      throw std::runtime_error(fmt::format("showcase: {} not found (the paper's sequences live in shots/; see --shots)",
                                           file.string()));
    const Shot shot(file);
    const ShotInfo& info = shot.info();
    SequencePlan p;
    p.name = info.name;
    p.shot = file;
    p.title = s.title;
    p.shot_frames = info.frames;
    const int width = size ? size->first : info.width, height = size ? size->second : info.height;
    if (size) p.size = fmt::format("{}x{}", width, height);
    if (preview) {
      // At least 4 frames (the first, the last and two between), as a clip
      // must have to be joined (see encode_all).
      const double seconds = info.frames / info.fps;
      const auto count = static_cast<std::size_t>(std::max(4L, std::lround(seconds * rate)));
      for (std::size_t k : pick_evenly(static_cast<std::size_t>(info.frames), count)) p.frames.push_back(static_cast<int>(k));
      p.supersample = 1;
      p.layers = true;  // small frames: the layers cost little and let a test read what each pixel saw
      p.fps = rate;
    } else {
      for (int i = 0; i < info.frames; ++i) p.frames.push_back(i);
      p.fps = info.fps;
    }
    if (!plan.sequences.empty() && (p.fps != plan.fps || width != plan.width || height != plan.height))
      throw std::runtime_error(fmt::format(
          "showcase: {} is {}x{} at {:g} fps but {} is {}x{} at {:g} fps; the clips could not be joined", file.string(),
          width, height, p.fps, plan.sequences.front().shot.string(), plan.width, plan.height, plan.fps));
    plan.fps = p.fps;
    plan.width = width;
    plan.height = height;
    plan.sequences.push_back(std::move(p));
  }
  return plan;
}

}  // namespace lc

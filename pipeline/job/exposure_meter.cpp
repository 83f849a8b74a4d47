#include "job/exposure_meter.hpp"

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <istream>
#include <numeric>
#include <set>
#include <sstream>

#include <ext/stdio_filebuf.h>
#include <fcntl.h>
#include <fmt/format.h>

#include "assets/shot_resources.hpp"
#include "store/journal.hpp"
#include "store/durable_file.hpp"
#include "store/content_hash.hpp"
#include "job/shot_survey.hpp"
#include "image/auto_exposure.hpp"
#include "render/renderer.hpp"
#include "render/scene_builder.hpp"

namespace lc::farm {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view meter_header = "lightcone-meter 2";
// Frames keyed at once (each key evaluates its frame: ~3 ms).
constexpr std::size_t meter_key_chunk = 64;

// One frame's line of the meter file: its reading and what it was made
// from (reading_keys).
struct MeterLine {
  std::string key;
  double reading = 0.0;
};

// What each frame's reading depends on: its frame's inputs (the script,
// the modules and its sky's files, by content: job/shot_survey.hpp), the
// meter's size and the camera the shot is delivered through.  Evaluates
// the frames (script only).
std::map<int, std::string> reading_keys(Shot& shot, const std::vector<int>& frames, int width, int height) {
  const ShotSurvey survey = survey_shot(shot, frames);
  std::map<int, std::string> out;
  for (const auto& [frame, facts] : survey.frames) {
    ContentHash h;
    h.add(meter_header).add(std::uint64_t(width)).add(std::uint64_t(height)).add(std::uint64_t(shot.delivery().camera));
    if (const Delivery& d = shot.delivery(); d.beyond_camera()) h.add(delivery_fields(d));  // (older keys stand)
    out[frame] = h.add(facts.inputs).hex();
  }
  return out;
}

// The file's text: a header line, a line a frame metered ("<frame> <key>
// <reading as a hex float>"), and a last line with the check of all
// before it.
std::string meter_text(int width, int height, const std::map<int, MeterLine>& lines) {
  std::string text = fmt::format("{} size={}x{}\n", meter_header, width, height);
  for (const auto& [frame, line] : lines) text += fmt::format("{} {} {:a}\n", frame, line.key, line.reading);
  return text + fmt::format("end #{}\n", to_hex(hash_bytes(text)));
}

// The lines of `file` if it is whole and made at this size; else none
// (what it held is metered again and replaced).
std::map<int, MeterLine> read_meter(const fs::path& file, int width, int height) {
  // Read as lightcone's own file: one that is no regular file (a FIFO
  // would block the render for good, a link lead anywhere) is metered
  // again, and the rename of the new one replaces it.
  OwnFile own;
  try {
    own = open_own_file(file, O_RDONLY, "read");
  } catch (const std::runtime_error&) {
    return {};
  }
  if (own.fd < 0) return {};
  __gnu_cxx::stdio_filebuf<char> buffer(own.fd, std::ios::in | std::ios::binary);  // closes the descriptor
  std::istream in(&buffer);
  std::ostringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  const auto end = text.rfind("end #");
  if (end == std::string::npos || text.substr(end) != fmt::format("end #{}\n", to_hex(hash_bytes(text.substr(0, end)))))
    return {};
  std::istringstream lines(text.substr(0, end));
  std::string line;
  if (!std::getline(lines, line) || line != fmt::format("{} size={}x{}", meter_header, width, height)) return {};
  std::map<int, MeterLine> out;
  while (std::getline(lines, line)) {
    std::istringstream fields(line);
    int frame = -1;
    std::string key, value;
    if (!(fields >> frame >> key >> value) || frame < 0) return {};
    char* stop = nullptr;
    const double v = std::strtod(value.c_str(), &stop);
    if (stop != value.c_str() + value.size()) return {};
    out[frame] = {key, v};
  }
  return out;
}

// "0-36, 84-156": the frames of a set, as runs.
std::string runs_of(const std::set<int>& frames) {
  std::string out;
  for (auto it = frames.begin(); it != frames.end();) {
    const int first = *it;
    int last = first;
    while (++it != frames.end() && *it == last + 1) last = *it;
    out += (out.empty() ? "" : ", ") + (first == last ? std::to_string(first) : fmt::format("{}-{}", first, last));
  }
  return out;
}

}  // namespace

MeterReadings shot_readings(Shot& shot, const fs::path& dir, int frame_width, int frame_height, int threads,
                            const std::vector<int>& frames, const MeterProgress& each) {
  const int count = shot.info().frames;
  const int width = meter_width;
  const int height = std::max(1, static_cast<int>(std::lround(meter_width * double(frame_height) / frame_width)));
  const fs::path file = dir / (shot.info().name + ".meter");
  std::map<int, MeterLine> lines = read_meter(file, width, height);
  MeterReadings m{width, height, {}};
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  ShotResources resources(shot.asset_dirs());
  // One sample a pixel at the frame's moment: the light, not its blur.
  const RenderSettings rs{width, height, 1, false, false};
  std::size_t done = 0, total = 0, kept = 0, metered = 0;
  // Each frame of `batch` read back where its line matches its inputs,
  // else metered (its line replaced).
  auto take = [&](const std::vector<int>& batch) {
    if (total == 0)
      fmt::print(stderr, "render: auto exposure: the readings of frames {} of the shot's {} (what the exposures of "
                         "the frames asked for reach) at {}x{}, from and to {}\n",
                 runs_of(std::set<int>(batch.begin(), batch.end())), count, width, height, file.string());
    total += batch.size();
    std::vector<double> out;
    std::map<int, std::string> keys;
    for (std::size_t k = 0; k < batch.size(); ++k) {
      // Keyed a chunk at a time, so a long batch is said and stoppable
      // (`each`) as it goes, not evaluated whole first.
      if (k % meter_key_chunk == 0)
        keys = reading_keys(shot, std::vector<int>(batch.begin() + static_cast<long>(k),
                                                   batch.begin() + static_cast<long>(std::min(batch.size(), k + meter_key_chunk))),
                            width, height);
      const int f = batch[k];
      const std::string& key = keys.at(f);
      if (const auto it = lines.find(f); it != lines.end() && it->second.key == key) {
        out.push_back(it->second.reading);
        ++kept;
      } else {
        const Scene scene = build_scene(shot.frame_specs(f).frame, shot.file(), f, width, height, resources);
        out.push_back(luminance_percentile(render_frame(scene, rs, threads)));
        lines[f] = {key, out.back()};
        ++metered;
      }
      if (each) each(++done, total);
    }
    return out;
  };
  // What was metered is kept for the next run, also when the pass stops
  // (an interrupt, a later frame's error).
  auto keep = [&] {
    if (metered == 0) return;
    DurableFile out(file, StaleTemporaries::remove, FinalName::own);
    out.write(meter_text(width, height, lines));
    out.commit();
  };
  try {
    m.readings = needed_readings(frames, count, shot.info().auto_exposure_smoothing, take);
  } catch (...) {
    // The readings so far are kept if they can be; a failure to keep them
    // (a full disk) must not hide why the pass stopped (an interrupt).
    try {
      keep();
    } catch (const std::exception& e) {
      fmt::print(stderr, "render: auto exposure: the readings so far could not be kept: {}\n", e.what());
    }
    throw;
  }
  keep();
  fmt::print(stderr, "render: auto exposure: {} readings kept from {}, {} metered in {:.1f} s\n", kept, file.string(),
             metered, std::chrono::duration<double>(Clock::now() - start).count());
  return m;
}

std::map<int, double> auto_exposures(const ShotInfo& info, const MeterReadings& meter,
                                     const std::map<int, std::optional<double>>& own) {
  std::vector<int> frames;
  for (const auto& [frame, exposure] : own) frames.push_back(frame);
  const std::map<int, double> metered =
      exposures_from(meter.readings, frames, info.auto_exposure_level, info.auto_exposure_smoothing);
  std::map<int, double> out;
  for (const auto& [frame, exposure] : own)
    out[frame] = std::clamp(metered.at(frame) + exposure.value_or(info.exposure), -64.0, 64.0);
  return out;
}

}  // namespace lc::farm

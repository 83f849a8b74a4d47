#include "farm/exposure_meter.hpp"

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <istream>
#include <numeric>
#include <sstream>

#include <ext/stdio_filebuf.h>
#include <fcntl.h>
#include <fmt/format.h>

#include "assets/shot_resources.hpp"
#include "farm/journal.hpp"
#include "durable_file.hpp"
#include "farm/content_hash.hpp"
#include "farm/shot_inputs.hpp"
#include "image/auto_exposure.hpp"
#include "render/renderer.hpp"
#include "render/scene_builder.hpp"

namespace lc::farm {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view meter_header = "lightcone-meter 1";

// What the readings depend on: every file the shot's frames read (by
// content), the meter's size and the camera the shot is delivered through.
std::string meter_key(Shot& shot, int width, int height) {
  std::vector<int> all(static_cast<std::size_t>(shot.info().frames));
  std::iota(all.begin(), all.end(), 0);
  const ShotSurvey survey = survey_shot(shot, all);
  ContentHash h;
  h.add(meter_header).add(std::uint64_t(width)).add(std::uint64_t(height)).add(std::uint64_t(shot.delivery().camera));
  if (const Delivery& d = shot.delivery(); d.beyond_camera()) h.add(delivery_fields(d));  // (older keys stand)
  for (const auto& [path, hash] : survey.files) h.add(hash);
  return h.hex();
}

// The file's text: a header line, a line a frame ("<frame> <reading as a
// hex float>"), and a last line with the check of all before it.
std::string meter_text(const MeterReadings& m) {
  std::string text = fmt::format("{} key={} size={}x{} frames={}\n", meter_header, m.key, m.width, m.height,
                                 m.readings.size());
  for (std::size_t f = 0; f < m.readings.size(); ++f) text += fmt::format("{} {:a}\n", f, m.readings[f]);
  return text + fmt::format("end #{}\n", to_hex(hash_bytes(text)));
}

// The readings in `file` if it is whole and made for `key` at this size
// with `frames` frames; else none (it is metered again and replaced).
std::optional<MeterReadings> read_meter(const fs::path& file, const std::string& key, int width, int height,
                                        int frames) {
  // Read as lightcone's own file: one that is no regular file (a FIFO
  // would block the render for good, a link lead anywhere) is metered
  // again, and the rename of the new one replaces it.
  OwnFile own;
  try {
    own = open_own_file(file, O_RDONLY, "read");
  } catch (const std::runtime_error&) {
    return std::nullopt;
  }
  if (own.fd < 0) return std::nullopt;
  __gnu_cxx::stdio_filebuf<char> buffer(own.fd, std::ios::in | std::ios::binary);  // closes the descriptor
  std::istream in(&buffer);
  std::ostringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  const auto end = text.rfind("end #");
  if (end == std::string::npos || text.substr(end) != fmt::format("end #{}\n", to_hex(hash_bytes(text.substr(0, end)))))
    return std::nullopt;
  MeterReadings m{key, width, height, {}};
  std::istringstream lines(text.substr(0, end));
  std::string line;
  if (!std::getline(lines, line) ||
      line != fmt::format("{} key={} size={}x{} frames={}", meter_header, key, width, height, frames))
    return std::nullopt;
  while (std::getline(lines, line)) {
    const auto space = line.find(' ');
    if (space == std::string::npos || line.substr(0, space) != std::to_string(m.readings.size())) return std::nullopt;
    char* stop = nullptr;
    const double v = std::strtod(line.c_str() + space + 1, &stop);
    if (stop != line.c_str() + line.size()) return std::nullopt;
    m.readings.push_back(v);
  }
  if (m.readings.size() != static_cast<std::size_t>(frames)) return std::nullopt;
  return m;
}

}  // namespace

MeterReadings shot_readings(Shot& shot, const fs::path& dir, int frame_width, int frame_height, int threads) {
  const int frames = shot.info().frames;
  const int width = meter_width;
  const int height = std::max(1, static_cast<int>(std::lround(meter_width * double(frame_height) / frame_width)));
  const std::string key = meter_key(shot, width, height);
  const fs::path file = dir / (shot.info().name + ".meter");
  if (auto kept = read_meter(file, key, width, height, frames)) {
    fmt::print(stderr, "render: auto exposure: the readings of {} frames from {}\n", frames, file.string());
    return *kept;
  }
  fmt::print(stderr, "render: auto exposure: metering every frame of the shot ({}) at {}x{} -> {}\n", frames, width,
             height, file.string());
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  Clock::time_point last = start;
  MeterReadings m{key, width, height, {}};
  ShotResources resources(shot.asset_dirs());
  // One sample a pixel at the frame's moment: the light, not its blur.
  const RenderSettings rs{width, height, 1, false, false};
  for (int f = 0; f < frames; ++f) {
    const Scene scene = build_scene(shot.frame_specs(f).frame, shot.file(), f, width, height, resources);
    m.readings.push_back(luminance_percentile(render_frame(scene, rs, threads)));
    if (Clock::now() - last > std::chrono::seconds(5)) {
      last = Clock::now();
      fmt::print(stderr, "render: auto exposure: metered {}/{} frames\n", f + 1, frames);
    }
  }
  DurableFile out(file, StaleTemporaries::remove, FinalName::own);
  out.write(meter_text(m));
  out.commit();
  fmt::print(stderr, "render: auto exposure: metered in {:.1f} s\n",
             std::chrono::duration<double>(Clock::now() - start).count());
  return m;
}

std::map<int, double> auto_exposures(const ShotInfo& info, const MeterReadings& meter,
                                     const std::map<int, std::optional<double>>& own) {
  const std::vector<double> metered =
      metered_exposures(meter.readings, info.auto_exposure_level, info.auto_exposure_smoothing);
  std::map<int, double> out;
  for (const auto& [frame, exposure] : own)
    out[frame] = std::clamp(metered.at(static_cast<std::size_t>(frame)) + exposure.value_or(info.exposure), -64.0, 64.0);
  return out;
}

}  // namespace lc::farm

#include "encode_command.hpp"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>

#include <fmt/format.h>

#include "store/frame_files.hpp"
#include "image/image_io.hpp"
#include "job/image_size.hpp"
#include "interrupt.hpp"
#include "video/concat_videos.hpp"
#include "video/encode_sequence.hpp"
#include "store/frame_sequence.hpp"
#include "cli/progress_printer.hpp"
#include "video/title_card.hpp"

namespace lc {

namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;

// "1.2 MB" etc. for the summary.
std::string size_text(const fs::path& p) {
  std::error_code ec;
  const double b = static_cast<double>(fs::file_size(p, ec));
  if (ec) return "?";
  if (b < 1e3) return fmt::format("{:.0f} B", b);
  if (b < 1e6) return fmt::format("{:.1f} kB", b / 1e3);
  return fmt::format("{:.1f} MB", b / 1e6);
}

// The first frame's EXR (<shot>.<NNNN>.exr beside its PNG) and the
// attributes the renderer recorded in its header; none when it is missing
// or unreadable (the PNGs are the encoder's input, not the EXRs).
std::pair<fs::path, ImageMetadata> first_frame_header(const FrameSequence& seq) {
  const fs::path exr = seq.files.front().parent_path() / (seq.files.front().stem().string() + ".exr");
  std::error_code ec;
  if (!fs::exists(exr, ec)) return {exr, {}};
  try {
    return {exr, read_exr_metadata(exr)};
  } catch (const std::exception&) {
    return {exr, {}};
  }
}

// The frame rate: --fps, else the "lightcone/fps" attribute of the first
// frame's EXR (if the renderer recorded it), else 30 — divided by the
// sequence's step, so a preview of every k-th frame keeps the shot's pace
// instead of playing k times too fast.  Returns the value and where it came
// from, for the summary.  Throws std::invalid_argument naming --fps, or the
// EXR when the shot's own rate cannot be a video's.
std::pair<FrameRate, std::string> frame_rate(const EncodeCommand& cmd, const FrameSequence& seq, int step) {
  if (cmd.fps) return {parse_frame_rate(*cmd.fps, "--fps"), "--fps"};
  const auto [exr, header] = first_frame_header(seq);
  std::optional<std::string> recorded;
  for (const auto& [key, value] : header)
    if (key == "lightcone/fps") recorded = value;
  const FrameRate shot =
      recorded ? parse_frame_rate(*recorded, fmt::format("the shot's rate (lightcone/fps of {}; --fps overrides it)",
                                                         exr.string()))
               : FrameRate{30, 1};
  if (step == 1)
    return {shot, recorded ? fmt::format("the shot, from {}", exr.filename().string()) : "default; --fps to change"};
  return {frame_rate_divided(shot, step),
          recorded ? fmt::format("the shot's {}, from {}, divided by the step {} to keep its pace", describe(shot),
                                 exr.filename().string(), step)
                   : fmt::format("the default 30 divided by the step {} to keep the pace; --fps to change", step)};
}

// How players must show the frames, as the first frame's EXR records it
// (the camera's: a 360-degree video's sphere, a stereo layout); flat and
// mono where it records nothing.  A layout this lightcone does not know is
// left out with a warning rather than guessed.
VideoLayout frame_layout(const FrameSequence& seq) {
  const auto [exr, header] = first_frame_header(seq);
  if (const auto layout = layout_from(header)) return *layout;
  fmt::print(stderr, "encode: warning: {} records a projection or stereo layout this lightcone does not know; the video "
                     "is written without one\n",
             exr.string());
  return {};
}

// "equirectangular 360-degree video, top-bottom stereo" for the summary.
std::string layout_text(const VideoLayout& layout) {
  std::string text;
  if (layout.projection == VideoProjection::equirectangular) text = "equirectangular 360-degree video";
  if (layout.stereo != StereoLayout::mono)
    text += fmt::format("{}{} stereo", text.empty() ? "" : ", ", name_of(layout.stereo));
  return text;
}

// The codec settings shared by every mode that encodes.
EncodeOptions encode_options(const EncodeCommand& cmd, FrameRate fps) {
  EncodeOptions o;
  o.fps = fps;
  if (cmd.codec) o.codec = parse_codec(*cmd.codec);
  o.crf = cmd.crf;
  if (cmd.preset) o.preset = *cmd.preset;
  validate(o);
  return o;
}

// "crf 18, preset medium" (or the ProRes profile).
std::string settings_text(const EncodeOptions& o) {
  const std::string preset = o.preset.empty() ? default_preset(o.codec) : o.preset;
  if (o.codec == Codec::prores) return fmt::format("prores profile {}", preset);
  return fmt::format("{} crf {}, preset {}", codec_name(o.codec), o.crf.value_or(default_crf(o.codec)), preset);
}

// Mode DIR: the PNG frames of one shot to a video.
int encode_dir(const EncodeCommand& cmd, const InterruptGuard& guard) {
  if (cmd.inputs.size() != 1)
    throw std::invalid_argument(fmt::format("encode takes one frame directory, got {} arguments (joining videos needs --concat)",
                                            cmd.inputs.size()));
  if (!cmd.title.empty() || cmd.size || cmd.seconds)
    throw std::invalid_argument("--size and --seconds go with --title (a title card), not with a frame directory");
  const fs::path& dir = cmd.inputs.front();
  // A bad flag is reported before the directory is scanned.
  if (cmd.codec) parse_codec(*cmd.codec);
  if (cmd.fps) parse_frame_rate(*cmd.fps, "--fps");
  const FrameSequence seq = select_frame_sequence(dir, cmd.shot);
  require_complete(seq, dir, farm::check_frames_current(dir, seq.shot, seq.frames, cmd.allow_stale, "encode"));
  const FrameSpacing spacing = frame_spacing(seq.frames);
  const auto [fps, fps_source] = frame_rate(cmd, seq, spacing.step);
  EncodeOptions o = encode_options(cmd, fps);
  o.layout = frame_layout(seq);
  container_for(cmd.output, o.codec);  // a wrong extension is reported before anything starts
  const std::string layout = layout_text(o.layout);
  fmt::print(stderr, "encode: shot {}, {} frames ({}), {} fps ({}), {}{} -> {}\n", seq.shot, seq.frames.size(),
             describe_range(seq.frames, spacing), describe(fps), fps_source, settings_text(o),
             layout.empty() ? "" : ", " + layout + " (marked for players)", cmd.output.string());
  // A size the codec refuses outright is encode_sequence's to refuse (before
  // it decodes a frame); one that encodes but will not play everywhere is
  // said here.
  const auto [width, height] = image_size(seq.files.front());
  if (const auto warning = size_warning(o.codec, width, height)) fmt::print(stderr, "encode: warning: {}\n", *warning);
  const Clock::time_point start = Clock::now();
  const EncodeResult r = encode_sequence(seq.files, o, cmd.output, progress_printer(guard, "encode", "frames"));
  const double s = std::chrono::duration<double>(Clock::now() - start).count();
  if (r.encoded_width != r.width || r.encoded_height != r.height)
    fmt::print(stderr, "encode: frames are {}x{}; padded to {}x{} by repeating the last {} ({} needs even sides)\n",
               r.width, r.height, r.encoded_width, r.encoded_height,
               r.width % 2 && r.height % 2 ? "column and row" : r.width % 2 ? "column" : "row",
               o.codec == Codec::prores ? "yuv422p10" : "yuv420p");
  fmt::print(stderr, "encode: done: {} frames {}x{}, {:.3f} s at {} fps -> {} ({}) in {:.1f} s, {:.1f} frames/s\n",
             r.frames, r.encoded_width, r.encoded_height, r.seconds, describe(fps), cmd.output.string(), size_text(cmd.output), s,
             r.frames / std::max(s, 1e-9));
  return 0;
}

// Mode --concat: videos joined without re-encoding.
int encode_concat(const EncodeCommand& cmd, const InterruptGuard& guard) {
  if (cmd.fps || cmd.crf || cmd.codec || cmd.preset || cmd.shot || !cmd.title.empty() || cmd.size || cmd.seconds ||
      cmd.allow_stale)
    throw std::invalid_argument(
        "--concat copies the videos without re-encoding: --fps, --crf, --codec, --preset, --shot, --title, --size, "
        "--seconds and --allow-stale do not apply");
  if (cmd.inputs.empty()) throw std::invalid_argument("--concat: name the videos to join (in order)");
  std::error_code ec;
  for (const fs::path& p : cmd.inputs)
    if (fs::equivalent(p, cmd.output, ec))
      throw std::invalid_argument(fmt::format("-o {}: is also one of the videos to join", cmd.output.string()));
  const Clock::time_point start = Clock::now();
  const ConcatResult r = concat_videos(cmd.inputs, cmd.output, progress_printer(guard, "encode", "videos"));
  const double s = std::chrono::duration<double>(Clock::now() - start).count();
  fmt::print(stderr, "encode: joined {} videos: {} frames {}x{}, {:.3f} s -> {} ({}) in {:.1f} s\n", cmd.inputs.size(),
             r.frames, r.width, r.height, r.seconds, cmd.output.string(), size_text(cmd.output), s);
  return 0;
}

// Mode --title: a title card clip.
int encode_title(const EncodeCommand& cmd, const InterruptGuard& guard) {
  if (!cmd.inputs.empty())
    throw std::invalid_argument("--title makes a title card: give no frame directory or videos");
  if (cmd.shot || cmd.allow_stale)
    throw std::invalid_argument(fmt::format("{} selects frames; a title card has none", cmd.shot ? "--shot" : "--allow-stale"));
  if (!cmd.size) throw std::invalid_argument("--title needs --size WxH (the size of the film it goes with)");
  const auto [w, h] = parse_image_size(*cmd.size, "--size");
  if (w < 2 || h < 2 || w > max_frame_side || h > max_frame_side)
    throw std::invalid_argument(fmt::format("--size {}: each side must be 2 to {}", *cmd.size, max_frame_side));
  const FrameRate fps = cmd.fps ? parse_frame_rate(*cmd.fps, "--fps") : FrameRate{30, 1};
  const EncodeOptions o = encode_options(cmd, fps);
  const double seconds = cmd.seconds.value_or(3.0);
  if (!(seconds > 0) || seconds > 600)
    throw std::invalid_argument(fmt::format("--seconds {}: must be above 0 and at most 600", seconds));
  const int frames = std::max(1, static_cast<int>(std::lround(seconds * fps.value())));
  const EncodeResult r = encode_title_card(cmd.title, w, h, frames, o, cmd.output, progress_printer(guard, "encode", "frames"));
  fmt::print(stderr, "encode: title card: {} frames {}x{}, {:.3f} s at {} fps, {} -> {} ({})\n", r.frames,
             r.encoded_width, r.encoded_height, r.seconds, describe(fps), settings_text(o), cmd.output.string(),
             size_text(cmd.output));
  return 0;
}

}  // namespace

int run_encode(const EncodeCommand& cmd) {
  // Picks the mode; a Ctrl-C or kill ends it between frames with the
  // temporary output removed (exit 128 + the signal, as a shell reports it).
  if (cmd.concat && !cmd.title.empty()) throw std::invalid_argument("--concat and --title: choose one");
  InterruptGuard guard;
  try {
    if (cmd.concat) return encode_concat(cmd, guard);
    if (!cmd.title.empty()) return encode_title(cmd, guard);
    return encode_dir(cmd, guard);
  } catch (const Interrupted& e) {
    fmt::print(stderr, "encode: {}; nothing written to {}\n", e.what(), cmd.output.string());
    return 128 + e.signal;
  }
}

}  // namespace lc

#include "video/encode_options.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace lc {

namespace {

constexpr std::array<std::string_view, 5> codec_names = {"h264", "hevc", "vp9", "av1", "prores"};
constexpr std::array<std::string_view, 10> x264_presets = {"ultrafast", "superfast", "veryfast", "faster", "fast",
                                                           "medium",    "slow",      "slower",   "veryslow", "placebo"};
constexpr std::array<std::string_view, 6> prores_profiles = {"proxy", "lt", "standard", "hq", "4444", "4444xq"};

// True when `s` is a whole decimal number in [lo, hi].
bool integer_in(const std::string& s, int lo, int hi) {
  if (s.empty() || s.size() > 3 || !std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c); }))
    return false;
  const int v = std::stoi(s);
  return v >= lo && v <= hi;
}

}  // namespace

Codec parse_codec(const std::string& name) {
  // Input: the --codec text; output: the enum, or a message listing choices.
  for (std::size_t i = 0; i < codec_names.size(); ++i)
    if (name == codec_names[i]) return static_cast<Codec>(i);
  throw std::invalid_argument(fmt::format("--codec {}: unknown codec (choose h264, hevc, vp9, av1 or prores)", name));
}

std::string_view codec_name(Codec codec) { return codec_names[static_cast<std::size_t>(codec)]; }

int default_crf(Codec codec) {
  // Roughly equal visual quality across codecs: x264 18 is near transparent;
  // the others' scales differ (x265 ~ x264 + 4; libvpx and SVT-AV1 use 0-63).
  switch (codec) {
    case Codec::h264: return 18;
    case Codec::hevc: return 22;
    case Codec::vp9: return 24;
    case Codec::av1: return 30;
    case Codec::prores: return 0;  // not used: ProRes has profiles, not a CRF
  }
  return 18;
}

std::string default_preset(Codec codec) {
  // The encoders' own balanced defaults (medium is x264's; STACK.md measured
  // ~15 frames/s at 720p on these cores), ProRes HQ for editing.
  switch (codec) {
    case Codec::h264:
    case Codec::hevc: return "medium";
    case Codec::vp9: return "4";
    case Codec::av1: return "8";
    case Codec::prores: return "hq";
  }
  return "medium";
}

Container container_for(const std::filesystem::path& out, Codec codec) {
  // Input: the output path and codec; output: the container, or why not.
  std::string ext = out.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  Container c;
  if (ext == ".mp4") c = Container::mp4;
  else if (ext == ".mov") c = Container::mov;
  else if (ext == ".mkv") c = Container::mkv;
  else if (ext == ".webm") c = Container::webm;
  else
    throw std::invalid_argument(
        fmt::format("{}: unknown video extension '{}' (use .mp4, .mov, .mkv or .webm)", out.string(), ext));
  const bool ok = c == Container::mkv || (c == Container::mp4 && codec != Codec::prores) ||
                  (c == Container::mov && (codec == Codec::h264 || codec == Codec::hevc || codec == Codec::prores)) ||
                  (c == Container::webm && (codec == Codec::vp9 || codec == Codec::av1));
  if (!ok) {
    const char* hint = codec == Codec::prores                             ? ".mov or .mkv"
                       : codec == Codec::h264 || codec == Codec::hevc ? ".mp4, .mov or .mkv"
                                                                          : ".mp4, .webm or .mkv";
    throw std::invalid_argument(fmt::format("{}: {} does not go in a {} file (use {})", out.string(),
                                            codec_name(codec), ext, hint));
  }
  return c;
}

void validate(const EncodeOptions& o) {
  // Input: options as parsed; throws naming the first bad flag.
  if (!(o.fps > 0 && o.fps <= 1000) || !std::isfinite(o.fps))
    throw std::invalid_argument(fmt::format("--fps {}: must be above 0 and at most 1000", o.fps));
  if (o.crf) {
    const int hi = o.codec == Codec::vp9 || o.codec == Codec::av1 ? 63 : 51;
    if (o.codec == Codec::prores)
      throw std::invalid_argument("--crf: ProRes has no CRF; choose its quality with --preset proxy|lt|standard|hq|4444|4444xq");
    if (*o.crf < 0 || *o.crf > hi)
      throw std::invalid_argument(fmt::format("--crf {}: {} takes 0 (best) to {}", *o.crf, codec_name(o.codec), hi));
  }
  if (o.preset.empty()) return;
  switch (o.codec) {
    case Codec::h264:
    case Codec::hevc:
      if (std::find(x264_presets.begin(), x264_presets.end(), o.preset) == x264_presets.end())
        throw std::invalid_argument(fmt::format(
            "--preset {}: {} takes ultrafast, superfast, veryfast, faster, fast, medium, slow, slower, veryslow or placebo",
            o.preset, codec_name(o.codec)));
      break;
    case Codec::vp9:
      if (!integer_in(o.preset, 0, 8))
        throw std::invalid_argument(fmt::format("--preset {}: vp9 takes its speed 0 (slowest) to 8", o.preset));
      break;
    case Codec::av1:
      if (!integer_in(o.preset, 0, 13))
        throw std::invalid_argument(fmt::format("--preset {}: av1 takes its speed 0 (slowest) to 13", o.preset));
      break;
    case Codec::prores:
      if (std::find(prores_profiles.begin(), prores_profiles.end(), o.preset) == prores_profiles.end())
        throw std::invalid_argument(
            fmt::format("--preset {}: prores takes a profile: proxy, lt, standard, hq, 4444 or 4444xq", o.preset));
      break;
  }
}

}  // namespace lc

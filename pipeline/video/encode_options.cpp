#include "video/encode_options.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <numeric>
#include <system_error>
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

// a/b in lowest terms (b > 0).
FrameRate reduced(long long a, long long b) {
  const long long g = std::gcd(a, b);
  return {static_cast<int>(a / g), static_cast<int>(b / g)};
}

// Whether lo <= a/b <= hi, exactly (terms below 2^31, so products fit).
bool rate_in(long long a, long long b, FrameRate lo, FrameRate hi) {
  return a * lo.den >= lo.num * b && a * hi.den <= hi.num * b;
}

// The message for a fraction whose terms are too large for a rate.
std::string too_large(const std::string& flag, const std::string& text) {
  return fmt::format("{} {}: too large: in lowest terms the fraction's numbers must be at most {} (as in 30000/1001)",
                     flag, text, max_rate_term);
}

// The message for a rate outside the range.
std::string out_of_range(const std::string& flag, const std::string& text) {
  return fmt::format("{} {}: must be from 1/1000 (one frame every 1000 s) to 1000 frames per second", flag, text);
}

}  // namespace

FrameRate frame_rate_near(double fps) {
  // Continued-fraction convergents p/q of fps, the last one with both terms
  // within max_rate_term, stopping as soon as one equals fps to double
  // precision (29.97 -> 2997/100, 0.3333333333333333 -> 1/3).
  if (!(fps > 0) || !std::isfinite(fps)) return {0, 1};
  long long p0 = 0, q0 = 1, p1 = 1, q1 = 0;
  double r = fps;
  for (int i = 0; i < 64; ++i) {
    const double a = std::floor(r);
    if (a > max_rate_term) break;
    const long long p2 = static_cast<long long>(a) * p1 + p0, q2 = static_cast<long long>(a) * q1 + q0;
    if (p2 > max_rate_term || q2 > max_rate_term) break;
    p0 = p1, q0 = q1, p1 = p2, q1 = q2;
    if (std::abs(static_cast<double>(p1) / static_cast<double>(q1) - fps) <= 1e-12 * fps || r == a) break;
    r = 1.0 / (r - a);
  }
  if (q1 == 0) return {0, 1};  // beyond max_rate_term: validate() refuses it
  return reduced(p1, q1);
}

FrameRate parse_frame_rate(const std::string& text, const std::string& flag) {
  // Inputs: the flag's text and name; output: the exact rate.
  const std::string expected = fmt::format(
      "{} '{}': expected frames per second as a number (30, 29.97) or a fraction of whole numbers (30000/1001)", flag,
      text);
  if (const auto slash = text.find('/'); slash != std::string::npos) {
    // Whole numbers of up to 18 digits fit a long long; a longer one is a
    // number too, only too large.
    auto whole = [&](std::string_view digits) {
      long long v = 0;
      if (digits.empty() || digits.find_first_not_of("0123456789") != std::string_view::npos)
        throw std::invalid_argument(expected);
      if (digits.size() > 18) throw std::invalid_argument(too_large(flag, text));
      std::from_chars(digits.data(), digits.data() + digits.size(), v);
      return v;
    };
    const long long num = whole(std::string_view(text).substr(0, slash));
    const long long den = whole(std::string_view(text).substr(slash + 1));
    if (den == 0) throw std::invalid_argument(fmt::format("{} {}: the denominator is 0", flag, text));
    const long long g = std::gcd(num, den);
    if (num / g > max_rate_term || den / g > max_rate_term) {
      // Which message: the value's range, roughly (exact range checks need
      // small terms), else the terms.
      const long double v = static_cast<long double>(num) / static_cast<long double>(den);
      throw std::invalid_argument(v < min_frame_rate.value() || v > max_frame_rate.value() ? out_of_range(flag, text)
                                                                                         : too_large(flag, text));
    }
    if (!rate_in(num / g, den / g, min_frame_rate, max_frame_rate)) throw std::invalid_argument(out_of_range(flag, text));
    return reduced(num, den);
  }
  // A decimal: digits first (no sign, no "inf" or "nan"), all of it a number.
  double v = 0;
  const char* end = text.data() + text.size();
  if (text.empty() || !(std::isdigit(static_cast<unsigned char>(text[0])) || text[0] == '.'))
    throw std::invalid_argument(expected);
  const auto [stop, ec] = std::from_chars(text.data(), end, v);
  if (stop != end || (ec != std::errc() && ec != std::errc::result_out_of_range)) throw std::invalid_argument(expected);
  const FrameRate r = frame_rate_near(v);
  if (ec == std::errc::result_out_of_range || r.num == 0 || !rate_in(r.num, r.den, min_frame_rate, max_frame_rate))
    throw std::invalid_argument(out_of_range(flag, text));
  return r;
}

FrameRate frame_rate_divided(FrameRate rate, int k) {
  return reduced(rate.num, static_cast<long long>(rate.den) * std::max(1, k));
}

std::string describe(FrameRate rate) {
  if (rate.den == 1) return fmt::format("{}", rate.num);
  // A short decimal that is exactly the rate ("29.97", "2.5") says it all.
  const std::string decimal = fmt::format("{:.6g}", rate.value());
  if (frame_rate_near(std::stod(decimal)) == rate) return decimal;
  return fmt::format("{}/{} ({:.4g})", rate.num, rate.den, rate.value());
}

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

std::optional<std::string> size_refusal(Codec codec, int width, int height) {
  // Inputs: the frames' size as rendered; output: the reason, naming the size.
  if (width < 1 || height < 1) return fmt::format("{}x{} is not a frame size", width, height);
  const long long w = width + width % 2, h = height + height % 2;
  if (codec == Codec::av1 && (w < 64 || h < 64 || w > 16384 || h > 8704))
    return fmt::format("av1 (SVT-AV1) takes frames from 64x64 to 16384x8704; these are {}x{}", width, height);
  if (codec == Codec::h264 && (w > 16384 || h > 16384))
    return fmt::format("libx264 takes at most 16384 pixels a side; these frames are {}x{}", width, height);
  // FFmpeg's av_image_check_size, which every encoder applies on opening.
  constexpr long long ffmpeg_area_limit = 2147483647 / 8;
  if ((w + 128) * (h + 128) >= ffmpeg_area_limit)
    return fmt::format(
        "{}x{} frames are too large for FFmpeg's encoders, which need (W+128)x(H+128) below {} (16384x16128 or "
        "16254x16254 at most)",
        width, height, ffmpeg_area_limit);
  return std::nullopt;
}

std::optional<std::string> size_warning(Codec codec, int width, int height) {
  if (codec != Codec::h264) return std::nullopt;
  constexpr long long level_62_macroblocks = 139264;
  const long long macroblocks = ((width + 15) / 16) * static_cast<long long>((height + 15) / 16);
  if (macroblocks <= level_62_macroblocks) return std::nullopt;
  return fmt::format(
      "{}x{} is {} macroblocks, beyond H.264's largest level (6.2: {}, e.g. 8192x4320): the video is written, but "
      "browsers and hardware decoders refuse to play it (ffplay and other players decoding with FFmpeg do)",
      width, height, macroblocks, level_62_macroblocks);
}

void validate(const EncodeOptions& o) {
  // Input: options as parsed; throws naming the first bad flag.
  if (o.fps.num <= 0 || o.fps.den <= 0 || !rate_in(o.fps.num, o.fps.den, min_frame_rate, max_frame_rate))
    throw std::invalid_argument(out_of_range("--fps", fmt::format("{}/{}", o.fps.num, o.fps.den)));
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

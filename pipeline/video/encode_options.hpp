#pragma once
// How a video is encoded: codec, quality, speed and frame rate, plus the
// container chosen by the output file's extension.  Plain data shared by the
// encode, concat and title-card functions and the `lightcone encode` flags.

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "store/durable_file.hpp"
#include "image/video_layout.hpp"

namespace lc {

// The codecs `lightcone encode --codec` offers (FFmpeg encoder in brackets):
// h264 (libx264; the default, plays everywhere), hevc (libx265), vp9
// (libvpx-vp9), av1 (libsvtav1), prores (prores_ks; 10-bit 4:2:2, for editing).
enum class Codec { h264, hevc, vp9, av1, prores };

// Containers, from the output's extension: .mp4, .mov, .mkv, .webm.
enum class Container { mp4, mov, mkv, webm };

// Frames per second as an exact fraction num/den: the video's time base is
// its inverse, so 30000/1001 stays 30000/1001 (a double would not).  Kept
// in lowest terms.
struct FrameRate {
  int num = 30, den = 1;
  double value() const { return static_cast<double>(num) / den; }
  bool operator==(const FrameRate&) const = default;
};

// The rates a video may have: the containers' clocks hold a frame of 1000 s
// (and the MP4 muxer's durations overflow well below 1e-9 fps) and frames
// 1 ms apart (Matroska's clock); the numbers of a fraction stay below this
// too, as they become the stream's clock.
inline constexpr FrameRate min_frame_rate{1, 1000};
inline constexpr FrameRate max_frame_rate{1000, 1};
inline constexpr int max_rate_term = 1001000;

// "30", "29.97", "2.5e1" or "30000/1001" -> the rate.  A fraction is kept
// exactly (reduced); a decimal becomes the nearest fraction whose terms are
// at most max_rate_term (exact when it has one: 29.97 is 2997/100; NTSC's
// 30000/1001 must be written as that fraction).  Throws
// std::invalid_argument naming `flag` for junk, a zero denominator, or a
// rate outside min_frame_rate .. max_frame_rate.
FrameRate parse_frame_rate(const std::string& text, const std::string& flag);

// The nearest fraction to `fps` with terms at most max_rate_term, for rates
// that arrive as numbers (a shot's fps, the showcase's); 0 or less, or not
// finite, gives {0, 1}, which validate() refuses.
FrameRate frame_rate_near(double fps);

// `rate` / k: the pace of a sequence that keeps every k-th frame (k >= 1).
FrameRate frame_rate_divided(FrameRate rate, int k);

// "24", "29.97", "30000/1001 (29.97)": for messages.
std::string describe(FrameRate rate);

struct EncodeOptions {
  FrameRate fps;                 // frames per second; the video lasts frames / fps
  Codec codec = Codec::h264;
  std::optional<int> crf;        // constant-quality level; unset: default_crf(codec)
  std::string preset;            // speed/quality knob; empty: default_preset(codec)
  VideoLayout layout;            // a 360-degree or stereo video's, written into the container for players
  // Whose name the output is: the user's (-o), or one lightcone gives it in
  // a folder it keeps (the showcase's videos), never written through a link.
  FinalName output_name = FinalName::users;
};

// Called after each frame is encoded with (frames done, frames in all).  May
// throw to abandon the encoding (the output is then removed): that is how a
// Ctrl-C reaches the encoder.
using ProgressFn = std::function<void(int done, int total)>;

// "h264" -> Codec::h264 etc.; throws std::invalid_argument naming --codec
// and listing the choices.
Codec parse_codec(const std::string& name);
std::string_view codec_name(Codec codec);

// Defaults chosen for these films (docs/encoding.md): sharp checker edges and
// star points need more bits than typical footage.
int default_crf(Codec codec);               // h264 18, hevc 22, vp9 24, av1 30; prores has none
std::string default_preset(Codec codec);    // medium (x264/x265), 4 (vp9 cpu-used), 8 (SVT-AV1), hq (ProRes profile)

// The container for `out` from its extension; throws std::invalid_argument
// naming the file when the extension is not one of the four or the codec
// cannot go in it (e.g. ProRes in .mp4, H.264 in .webm).
Container container_for(const std::filesystem::path& out, Codec codec);

// Why frames of width x height (padded to even sides, as they are encoded)
// cannot be encoded with `codec`, or nullopt when they can.  The limits:
// FFmpeg refuses frames whose (W+128)(H+128) reaches INT_MAX/8 (its
// av_image_check_size: 16384x16128 is the largest at 16384 wide), libx264
// sides above 16384, SVT-AV1 frames outside 64x64 .. 16384x8704.  Checked
// before any frame is read: an encoder refusing the size only once it
// opens (after the first frame is decoded) cost seconds and gigabytes and
// said "(0x0): Invalid argument".
std::optional<std::string> size_refusal(Codec codec, int width, int height);

// Why a video of width x height, though it can be written, will not play
// everywhere, or nullopt: H.264 beyond its largest level (6.2, 139264
// macroblocks of 16x16, 8192x4320 for instance) is written by libx264 with
// a level it exceeds; browsers and hardware decoders refuse it.
std::optional<std::string> size_warning(Codec codec, int width, int height);

// Checks fps (min_frame_rate .. max_frame_rate), crf and preset against the
// codec; throws std::invalid_argument naming the flag (--fps, --crf,
// --preset) and the allowed values.
void validate(const EncodeOptions& options);

}  // namespace lc

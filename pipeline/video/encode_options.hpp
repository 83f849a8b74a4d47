#pragma once
// How a video is encoded: codec, quality, speed and frame rate, plus the
// container chosen by the output file's extension.  Plain data shared by the
// encode, concat and title-card functions and the `lightcone encode` flags.

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace lc {

// The codecs `lightcone encode --codec` offers (FFmpeg encoder in brackets):
// h264 (libx264; the default, plays everywhere), hevc (libx265), vp9
// (libvpx-vp9), av1 (libsvtav1), prores (prores_ks; 10-bit 4:2:2, for editing).
enum class Codec { h264, hevc, vp9, av1, prores };

// Containers, from the output's extension: .mp4, .mov, .mkv, .webm.
enum class Container { mp4, mov, mkv, webm };

struct EncodeOptions {
  double fps = 30;               // frames per second; the video lasts frames / fps
  Codec codec = Codec::h264;
  std::optional<int> crf;        // constant-quality level; unset: default_crf(codec)
  std::string preset;            // speed/quality knob; empty: default_preset(codec)
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

// Checks fps, crf and preset against the codec; throws std::invalid_argument
// naming the flag (--fps, --crf, --preset) and the allowed values.
void validate(const EncodeOptions& options);

}  // namespace lc

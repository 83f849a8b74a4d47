#pragma once
// Internal to pipeline/video/*.cpp: the FFmpeg headers (C, hence extern "C")
// and small helpers turning FFmpeg's error codes into exceptions.  No header
// outside this folder's .cpp files includes it, so FFmpeg stays out of the
// rest of lightcone.

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/avutil.h>
#include <libavutil/error.h>
#include <libavutil/opt.h>
#include <libavutil/pixdesc.h>
#include <libavutil/spherical.h>
#include <libavutil/stereo3d.h>
#include <libswscale/swscale.h>
}

#include <cstdint>
#include <string>

#include "video/encode_options.hpp"

namespace lc::libav {

// FFmpeg's text for an error code (av_err2str is a C compound literal,
// not usable from C++).
std::string error_text(int code);

// Throws std::runtime_error "<what>: <FFmpeg's reason>" when code < 0;
// returns code otherwise.
int check(int code, const std::string& what);

// Lowers FFmpeg's process-wide log level to errors, once: the encoders'
// banners and statistics (x264 prints several lines per file) would bury
// lightcone's own progress.  FFmpeg keeps the level in one global; nothing
// else in lightcone uses FFmpeg's log.
void quiet_logs();

// The clock MP4's movie header should use for a video stream with
// `time_base` so its duration is exact (write_header explains).
std::int64_t movie_timescale(AVRational time_base);

// FFmpeg's muxer for a container ("mp4", "matroska", ...).
const char* muxer_name(Container container);

// Attaches `layout` to `stream` of `ctx` (before the header is written) as
// the side data players read: AVSphericalMapping for an equirectangular
// whole sphere, AVStereo3D for a stereo layout.  The MP4/MOV muxer writes
// them as Google's spherical video V2 boxes (sv3d, st3d) only when told
// unofficial extensions are welcome (it drops them silently otherwise), so
// `ctx` is set to that; Matroska writes its own Projection and StereoMode.
// Nothing for a flat mono layout.  Throws naming `where`.
void add_layout(AVFormatContext* ctx, AVStream* stream, const VideoLayout& layout, const std::string& where);

// Writes the header of `ctx` (opened for `container`, its one stream of
// `time_base` added): for MP4/MOV with the index in front, so a browser
// plays before the whole file has arrived, and the movie clock of
// movie_timescale.  Throws naming `where`.
void write_header(AVFormatContext* ctx, Container container, AVRational time_base, const std::string& where);

}  // namespace lc::libav

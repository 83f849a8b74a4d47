#include "video/libav.hpp"

#include <mutex>
#include <stdexcept>

#include <fmt/format.h>

namespace lc::libav {

std::string error_text(int code) {
  // Input: a negative AVERROR; output: its message.
  char buf[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, buf, sizeof buf);
  return buf;
}

int check(int code, const std::string& what) {
  if (code < 0) throw std::runtime_error(what + ": " + error_text(code));
  return code;
}

void quiet_logs() {
  static std::once_flag once;
  std::call_once(once, [] { av_log_set_level(AV_LOG_ERROR); });
}

std::int64_t movie_timescale(AVRational time_base) {
  // Input: the stream's time base; output: the MP4 track timescale the
  // mov muxer derives from it.
  std::int64_t t = time_base.den;
  while (t < 10000) t *= 2;
  return t;
}

const char* muxer_name(Container c) {
  switch (c) {
    case Container::mp4: return "mp4";
    case Container::mov: return "mov";
    case Container::mkv: return "matroska";
    case Container::webm: return "webm";
  }
  return "mp4";
}

namespace {

// Hands `data` (allocated by av_malloc, `size` bytes) to the stream as side
// data of `type`, or frees it and throws.  FFmpeg 6.1 moved stream side
// data into the codec parameters.
void attach(AVStream* stream, AVPacketSideDataType type, std::uint8_t* data, std::size_t size, const std::string& where) {
#if LIBAVFORMAT_VERSION_INT >= AV_VERSION_INT(60, 15, 100)
  if (!av_packet_side_data_add(&stream->codecpar->coded_side_data, &stream->codecpar->nb_coded_side_data, type, data,
                               size, 0)) {
    av_free(data);
    throw std::runtime_error(fmt::format("cannot write {}: out of memory for its side data", where));
  }
#else
  const int rc = av_stream_add_side_data(stream, type, data, size);
  if (rc < 0) av_free(data);
  check(rc, fmt::format("cannot write {}", where));
#endif
}

}  // namespace

void add_layout(AVFormatContext* ctx, AVStream* stream, const VideoLayout& layout, const std::string& where) {
  if (layout == VideoLayout{}) return;
  ctx->strict_std_compliance = FF_COMPLIANCE_UNOFFICIAL;
  if (layout.projection == VideoProjection::equirectangular) {
    std::size_t size = 0;
    AVSphericalMapping* map = av_spherical_alloc(&size);
    if (!map) throw std::bad_alloc();
    map->projection = AV_SPHERICAL_EQUIRECTANGULAR;  // yaw, pitch, roll and bounds zero: the whole sphere, as rendered
    attach(stream, AV_PKT_DATA_SPHERICAL, reinterpret_cast<std::uint8_t*>(map), size, where);
  }
  if (layout.stereo != StereoLayout::mono) {
    AVStereo3D* stereo = av_stereo3d_alloc();
    if (!stereo) throw std::bad_alloc();
    stereo->type = layout.stereo == StereoLayout::top_bottom ? AV_STEREO3D_TOPBOTTOM : AV_STEREO3D_SIDEBYSIDE;
    attach(stream, AV_PKT_DATA_STEREO3D, reinterpret_cast<std::uint8_t*>(stereo), sizeof(AVStereo3D), where);
  }
}

void write_header(AVFormatContext* ctx, Container container, AVRational time_base, const std::string& where) {
  AVDictionary* mux = nullptr;
  if (container == Container::mp4 || container == Container::mov) {
    av_dict_set(&mux, "movflags", "+faststart", 0);
    // The movie header's clock, 1/1000 s by default, would round the
    // file's duration to milliseconds (4 frames at 30 fps: 0.134 s); the
    // track's own clock (the muxer's rule: the time base's denominator,
    // doubled up to 10000 or more) holds frames / fps exactly.
    av_dict_set_int(&mux, "movie_timescale", movie_timescale(time_base), 0);
  }
  const int rc = avformat_write_header(ctx, &mux);
  av_dict_free(&mux);
  check(rc, fmt::format("cannot write {}", where));
}

}  // namespace lc::libav

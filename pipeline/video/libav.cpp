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

#include "video/libav.hpp"

#include <mutex>
#include <stdexcept>

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

}  // namespace lc::libav

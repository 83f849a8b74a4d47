#include "video/concat_videos.hpp"

#include <algorithm>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "store/durable_file.hpp"
#include "video/libav.hpp"

namespace lc {

namespace fs = std::filesystem;

namespace {

// One opened input file and its single video stream.
struct Input {
  fs::path path;
  AVFormatContext* ctx = nullptr;
  AVStream* stream = nullptr;

  explicit Input(fs::path p) : path(std::move(p)) {
    // Opens and probes; throws naming the file.
    const std::string name = path.string();
    libav::check(avformat_open_input(&ctx, name.c_str(), nullptr, nullptr), fmt::format("cannot read {}", name));
    libav::check(avformat_find_stream_info(ctx, nullptr), fmt::format("cannot read {}", name));
    if (ctx->nb_streams != 1 || ctx->streams[0]->codecpar->codec_type != AVMEDIA_TYPE_VIDEO)
      throw std::runtime_error(fmt::format("{}: {} streams; concat joins files holding one video stream "
                                           "(as lightcone encode writes)",
                                           name, ctx->nb_streams));
    stream = ctx->streams[0];
  }
  ~Input() { avformat_close_input(&ctx); }
  Input(const Input&) = delete;
  Input& operator=(const Input&) = delete;
};

// The lightcone codec of a stream; throws naming the file for others.
Codec codec_of(const Input& in) {
  switch (in.stream->codecpar->codec_id) {
    case AV_CODEC_ID_H264: return Codec::h264;
    case AV_CODEC_ID_HEVC: return Codec::hevc;
    case AV_CODEC_ID_VP9: return Codec::vp9;
    case AV_CODEC_ID_AV1: return Codec::av1;
    case AV_CODEC_ID_PRORES: return Codec::prores;
    default:
      throw std::runtime_error(fmt::format("{}: codec {} is not one lightcone encodes (h264, hevc, vp9, av1, prores)",
                                           in.path.string(), avcodec_get_name(in.stream->codecpar->codec_id)));
  }
}

// Throws unless `in` can follow `first` in one stream: same codec, size,
// pixel format, frame rate and codec headers (extradata: the SPS/PPS of
// H.264, the decoder's set-up; a player reads them once per file).
void require_compatible(const Input& first, const Input& in) {
  const AVCodecParameters& a = *first.stream->codecpar;
  const AVCodecParameters& b = *in.stream->codecpar;
  const std::string f = first.path.string(), n = in.path.string();
  if (a.codec_id != b.codec_id)
    throw std::runtime_error(fmt::format("{}: codec {}, but {} is {}: join only videos of one codec", n,
                                         avcodec_get_name(b.codec_id), f, avcodec_get_name(a.codec_id)));
  if (a.width != b.width || a.height != b.height)
    throw std::runtime_error(fmt::format("{}: {}x{}, but {} is {}x{}: join only videos of one size", n, b.width,
                                         b.height, f, a.width, a.height));
  if (a.format != b.format)
    throw std::runtime_error(fmt::format("{}: pixel format {}, but {} has {}", n,
                                         av_get_pix_fmt_name(static_cast<AVPixelFormat>(b.format)), f,
                                         av_get_pix_fmt_name(static_cast<AVPixelFormat>(a.format))));
  const AVRational ra = first.stream->avg_frame_rate, rb = in.stream->avg_frame_rate;
  if (av_cmp_q(ra, rb) != 0)
    throw std::runtime_error(fmt::format("{}: {:.6g} frames/s, but {} has {:.6g}: join only videos of one frame rate",
                                         n, av_q2d(rb), f, av_q2d(ra)));
  if (a.extradata_size != b.extradata_size ||
      (a.extradata_size > 0 && std::memcmp(a.extradata, b.extradata, static_cast<std::size_t>(a.extradata_size)) != 0))
    throw std::runtime_error(fmt::format(
        "{}: its {} headers differ from {}'s (encoded with another --preset or encoder): encode both with the same "
        "settings to join them",
        n, avcodec_get_name(b.codec_id), f));
}

// The container's sample tag for the copied stream: the input's when the
// output container knows it for this codec (ProRes tags carry the profile),
// 'hvc1' for HEVC in MP4/MOV (what Safari plays), else 0 (the muxer picks).
unsigned int output_tag(const AVOutputFormat* ofmt, const AVCodecParameters& par, Container c) {
  if (par.codec_id == AV_CODEC_ID_HEVC && (c == Container::mp4 || c == Container::mov)) return MKTAG('h', 'v', 'c', '1');
  if (ofmt->codec_tag && av_codec_get_id(ofmt->codec_tag, par.codec_tag) == par.codec_id) return par.codec_tag;
  return 0;
}

// The output side: muxer, stream, temporary file.
struct Output {
  DurableFile file;
  AVFormatContext* ctx = nullptr;
  Output(const fs::path& p, FinalName name) : file(p, StaleTemporaries::remove, name) {}
  ~Output() {
    if (ctx) {
      if (ctx->pb) avio_closep(&ctx->pb);
      avformat_free_context(ctx);
    }
  }
};

}  // namespace

ConcatResult concat_videos(const std::vector<fs::path>& inputs, const fs::path& out, const ProgressFn& progress,
                           const VideoLayout& layout, FinalName name) {
  // Inputs: video files in order; output: one file at `out`.  Every input is
  // opened and compared before anything is written.
  if (inputs.empty()) throw std::runtime_error(fmt::format("cannot write {}: no videos to join", out.string()));
  libav::quiet_logs();
  std::vector<std::unique_ptr<Input>> in;
  for (const fs::path& p : inputs) in.push_back(std::make_unique<Input>(p));
  const Codec codec = codec_of(*in.front());
  for (std::size_t i = 1; i < in.size(); ++i) require_compatible(*in.front(), *in[i]);
  const Container container = container_for(out, codec);

  const std::string where = out.string();
  Output o(out, name);
  // By the temporary's descriptor path, never its name, as VideoWriter does.
  const std::string file = o.file.library_path().string();
  libav::check(avformat_alloc_output_context2(&o.ctx, nullptr, libav::muxer_name(container), file.c_str()),
               fmt::format("cannot write {}", where));
  AVStream* st = avformat_new_stream(o.ctx, nullptr);
  if (!st) throw std::bad_alloc();
  const AVStream& first = *in.front()->stream;
  libav::check(avcodec_parameters_copy(st->codecpar, first.codecpar), fmt::format("cannot write {}", where));
  st->codecpar->codec_tag = output_tag(o.ctx->oformat, *first.codecpar, container);
  st->time_base = first.time_base;
  st->avg_frame_rate = first.avg_frame_rate;
  st->r_frame_rate = first.avg_frame_rate;
  libav::add_layout(o.ctx, st, layout, where);
  libav::check(avio_open(&o.ctx->pb, file.c_str(), AVIO_FLAG_WRITE), fmt::format("cannot write {}", where));
  libav::write_header(o.ctx, container, st->time_base, where);

  // Each input is shifted by `offset` (output time base) so it starts where
  // the previous one ended; its end is its latest pts + duration.
  std::unique_ptr<AVPacket, void (*)(AVPacket*)> pkt(av_packet_alloc(), [](AVPacket* p) { av_packet_free(&p); });
  if (!pkt) throw std::bad_alloc();
  std::int64_t offset = 0, last_dts = INT64_MIN;
  int frames = 0;
  for (std::size_t i = 0; i < in.size(); ++i) {
    const Input& src = *in[i];
    const AVRational tb = src.stream->time_base;
    const std::int64_t start = src.stream->start_time == AV_NOPTS_VALUE ? 0 : src.stream->start_time;
    const std::int64_t one_frame = av_rescale_q(1, av_inv_q(src.stream->avg_frame_rate), tb);
    std::int64_t end = offset;
    for (;;) {
      const int rc = av_read_frame(src.ctx, pkt.get());
      if (rc == AVERROR_EOF) break;
      libav::check(rc, fmt::format("cannot read {}", src.path.string()));
      if (pkt->pts == AV_NOPTS_VALUE || pkt->dts == AV_NOPTS_VALUE)
        throw std::runtime_error(fmt::format("{}: a packet without timestamps; cannot join it", src.path.string()));
      if (pkt->duration <= 0) pkt->duration = one_frame;
      pkt->pts -= start;
      pkt->dts -= start;
      av_packet_rescale_ts(pkt.get(), tb, st->time_base);
      pkt->pts += offset;
      pkt->dts += offset;
      if (pkt->dts <= last_dts)
        throw std::runtime_error(fmt::format("{}: its timestamps run back into the previous video's; cannot join it",
                                             src.path.string()));
      last_dts = pkt->dts;
      end = std::max(end, pkt->pts + pkt->duration);
      pkt->stream_index = st->index;
      pkt->pos = -1;
      libav::check(av_interleaved_write_frame(o.ctx, pkt.get()), fmt::format("cannot write {}", where));
      ++frames;
    }
    offset = end;
    if (progress) progress(static_cast<int>(i + 1), static_cast<int>(in.size()));
  }
  libav::check(av_write_trailer(o.ctx), fmt::format("cannot write {}", where));
  libav::check(avio_closep(&o.ctx->pb), fmt::format("cannot write {}", where));
  o.file.commit();
  return {frames, first.codecpar->width, first.codecpar->height, av_q2d(st->time_base) * static_cast<double>(offset)};
}

}  // namespace lc

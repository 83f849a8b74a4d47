#include "video/video_writer.hpp"

#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "store/durable_file.hpp"
#include "video/libav.hpp"

namespace lc {

namespace {

// The FFmpeg encoder behind each codec (docs/encoding.md says why these).
const char* encoder_name(Codec c) {
  switch (c) {
    case Codec::h264: return "libx264";
    case Codec::hevc: return "libx265";
    case Codec::vp9: return "libvpx-vp9";
    case Codec::av1: return "libsvtav1";
    case Codec::prores: return "prores_ks";
  }
  return "libx264";
}

// The encoder's private options for `o` (crf, preset and friends).
AVDictionary* encoder_options(const EncodeOptions& o) {
  AVDictionary* d = nullptr;
  const std::string preset = o.preset.empty() ? default_preset(o.codec) : o.preset;
  const std::string crf = std::to_string(o.crf.value_or(default_crf(o.codec)));
  switch (o.codec) {
    case Codec::h264:
      av_dict_set(&d, "preset", preset.c_str(), 0);
      av_dict_set(&d, "crf", crf.c_str(), 0);
      // Headers that do not depend on the rate control, so clips encoded
      // with the same size, fps and preset share them and concat_videos can
      // join them without re-encoding (x264's "stitchable").
      av_dict_set(&d, "x264-params", "stitchable=1", 0);
      break;
    case Codec::hevc:
      av_dict_set(&d, "preset", preset.c_str(), 0);
      av_dict_set(&d, "crf", crf.c_str(), 0);
      av_dict_set(&d, "x265-params", "log-level=error", 0);
      break;
    case Codec::vp9:
      // Constant quality needs the bit rate unset (b = 0, set on the context).
      av_dict_set(&d, "crf", crf.c_str(), 0);
      av_dict_set(&d, "deadline", "good", 0);
      av_dict_set(&d, "cpu-used", preset.c_str(), 0);
      av_dict_set(&d, "row-mt", "1", 0);
      break;
    case Codec::av1:
      av_dict_set(&d, "crf", crf.c_str(), 0);
      av_dict_set(&d, "preset", preset.c_str(), 0);
      break;
    case Codec::prores:
      av_dict_set(&d, "profile", preset.c_str(), 0);
      break;
  }
  return d;
}

}  // namespace

struct VideoWriter::Impl {
  DurableFile output;
  int width, height;  // as given (frames must have this size)
  AVFormatContext* fmt = nullptr;
  AVCodecContext* enc = nullptr;
  AVStream* stream = nullptr;
  SwsContext* sws = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  int frames = 0;
  bool finished = false;

  Impl(const std::filesystem::path& out, int w, int h, FinalName name)
      : output(out, StaleTemporaries::remove, name), width(w), height(h) {}

  ~Impl() {
    // Frees in reverse order of creation; the temporary file goes with
    // `output` when finish() did not commit it.
    av_packet_free(&packet);
    av_frame_free(&frame);
    sws_freeContext(sws);
    avcodec_free_context(&enc);
    if (fmt) {
      if (fmt->pb) avio_closep(&fmt->pb);
      avformat_free_context(fmt);
    }
  }

  std::string where() const { return output.final_path().string(); }

  // Sends `f` (nullptr: end of stream) and writes every packet the encoder
  // has ready, each lasting one frame (STACK.md: the MP4 is otherwise a frame short).
  void send(const AVFrame* f) {
    libav::check(avcodec_send_frame(enc, f), fmt::format("cannot encode {}", where()));
    for (;;) {
      const int rc = avcodec_receive_packet(enc, packet);
      if (rc == AVERROR(EAGAIN) || rc == AVERROR_EOF) return;
      libav::check(rc, fmt::format("cannot encode {}", where()));
      packet->duration = 1;  // one frame, in the codec's time base 1/fps
      av_packet_rescale_ts(packet, enc->time_base, stream->time_base);
      packet->stream_index = stream->index;
      libav::check(av_interleaved_write_frame(fmt, packet), fmt::format("cannot write {}", where()));
    }
  }
};

VideoWriter::VideoWriter(const std::filesystem::path& out, int width, int height, const EncodeOptions& options) {
  // Inputs: output path, frame size, options; opens everything up to the
  // container header, so an unwritable path fails before any encoding.
  validate(options);
  const Container container = container_for(out, options.codec);
  if (const auto why = size_refusal(options.codec, width, height))
    throw std::invalid_argument(fmt::format("cannot write {}: {}", out.string(), *why));
  libav::quiet_logs();
  impl_ = std::make_unique<Impl>(out, width, height, options.output_name);
  Impl& m = *impl_;
  const std::string where = m.where();

  const AVCodec* codec = avcodec_find_encoder_by_name(encoder_name(options.codec));
  if (!codec)
    throw std::runtime_error(fmt::format("cannot write {}: this FFmpeg has no {} encoder for {}", where,
                                         encoder_name(options.codec), codec_name(options.codec)));
  // FFmpeg opens its file by path, and reopens it (faststart reads it
  // back): the temporary's descriptor path, never its name (durable_file.hpp).
  const std::string file = m.output.library_path().string();
  libav::check(avformat_alloc_output_context2(&m.fmt, nullptr, libav::muxer_name(container), file.c_str()),
               fmt::format("cannot write {}", where));
  m.stream = avformat_new_stream(m.fmt, nullptr);
  m.enc = avcodec_alloc_context3(codec);
  m.frame = av_frame_alloc();
  m.packet = av_packet_alloc();
  if (!m.stream || !m.enc || !m.frame || !m.packet) throw std::bad_alloc();

  // The rate as the fraction it is: 30000/1001 frames per second, a time
  // base of 1001/30000 s.
  const AVRational rate{options.fps.num, options.fps.den};
  m.enc->width = width + width % 2;
  m.enc->height = height + height % 2;
  m.enc->pix_fmt = options.codec == Codec::prores ? AV_PIX_FMT_YUV422P10LE : AV_PIX_FMT_YUV420P;
  m.enc->time_base = av_inv_q(rate);
  m.enc->framerate = rate;
  m.enc->sample_aspect_ratio = AVRational{1, 1};
  m.enc->bit_rate = 0;  // constant quality, not a bit-rate target
  // Rendered frames are sRGB, whose primaries are BT.709's; the matrix and
  // limited range are what every browser and player assumes for yuv420p.
  // The transfer is tagged BT.709 like nearly all web video, so players
  // show the PNG's values as they are (docs/encoding.md).
  m.enc->color_range = AVCOL_RANGE_MPEG;
  m.enc->colorspace = AVCOL_SPC_BT709;
  m.enc->color_primaries = AVCOL_PRI_BT709;
  m.enc->color_trc = AVCOL_TRC_BT709;
  if (m.fmt->oformat->flags & AVFMT_GLOBALHEADER) m.enc->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;

  AVDictionary* opts = encoder_options(options);
  const int rc = avcodec_open2(m.enc, codec, &opts);
  av_dict_free(&opts);
  libav::check(rc, fmt::format("cannot open the {} encoder for {} ({}x{})", encoder_name(options.codec), where,
                               m.enc->width, m.enc->height));

  libav::check(avcodec_parameters_from_context(m.stream->codecpar, m.enc), fmt::format("cannot write {}", where));
  m.stream->time_base = m.enc->time_base;  // a hint; the muxer may refine it in write_header
  m.stream->avg_frame_rate = rate;
  m.stream->r_frame_rate = rate;
  // Safari plays HEVC in MP4 only under the 'hvc1' sample entry.
  if (options.codec == Codec::hevc && (container == Container::mp4 || container == Container::mov))
    m.stream->codecpar->codec_tag = MKTAG('h', 'v', 'c', '1');

  libav::add_layout(m.fmt, m.stream, options.layout, where);

  libav::check(avio_open(&m.fmt->pb, file.c_str(), AVIO_FLAG_WRITE),
               fmt::format("cannot write {}", where));
  libav::write_header(m.fmt, container, m.enc->time_base, where);

  m.sws = sws_getContext(m.enc->width, m.enc->height, AV_PIX_FMT_RGB24, m.enc->width, m.enc->height, m.enc->pix_fmt,
                         SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INP, nullptr, nullptr, nullptr);
  if (!m.sws) throw std::runtime_error(fmt::format("cannot write {}: no RGB to {} conversion", where,
                                                   av_get_pix_fmt_name(m.enc->pix_fmt)));
  // swscale defaults to the BT.601 matrix; the stream says BT.709, so
  // convert with BT.709 (full-range RGB in, limited-range YUV out).
  const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
  sws_setColorspaceDetails(m.sws, bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);

  m.frame->format = m.enc->pix_fmt;
  m.frame->width = m.enc->width;
  m.frame->height = m.enc->height;
  m.frame->color_range = m.enc->color_range;
  m.frame->colorspace = m.enc->colorspace;
  m.frame->color_primaries = m.enc->color_primaries;
  m.frame->color_trc = m.enc->color_trc;
  libav::check(av_frame_get_buffer(m.frame, 0), fmt::format("cannot write {}", where));
}

VideoWriter::~VideoWriter() = default;

void VideoWriter::add(const Rgb8Image& image) {
  // Input: the next frame (the opened size); converts, encodes, writes.
  Impl& m = *impl_;
  if (m.finished) throw std::logic_error("VideoWriter::add after finish");
  if (image.width != m.width || image.height != m.height ||
      image.pixels.size() != 3 * static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height))
    throw std::invalid_argument(fmt::format("{}: frame {} is {}x{}, the video is {}x{}", m.where(), m.frames,
                                            image.width, image.height, m.width, m.height));
  // Padding copies the frame: only for odd sizes.
  const bool odd = image.width % 2 != 0 || image.height % 2 != 0;
  const Rgb8Image padded = odd ? pad_to_even(image) : Rgb8Image{};
  const Rgb8Image& even = odd ? padded : image;
  // The encoder may still hold the previous frame's buffers.
  libav::check(av_frame_make_writable(m.frame), fmt::format("cannot encode {}", m.where()));
  const std::uint8_t* src[1] = {even.pixels.data()};
  const int stride[1] = {3 * even.width};
  sws_scale(m.sws, src, stride, 0, even.height, m.frame->data, m.frame->linesize);
  m.frame->pts = m.frames;  // codec time base is 1/fps: pts counts frames
  m.send(m.frame);
  ++m.frames;
}

void VideoWriter::finish() {
  // Drains, writes the trailer (MP4: rewrites the file with moov first),
  // closes, syncs and renames.
  Impl& m = *impl_;
  if (m.finished) return;
  if (m.frames == 0) throw std::runtime_error(fmt::format("cannot write {}: no frames", m.where()));
  m.send(nullptr);
  libav::check(av_write_trailer(m.fmt), fmt::format("cannot write {}", m.where()));
  libav::check(avio_closep(&m.fmt->pb), fmt::format("cannot write {}", m.where()));
  m.output.commit();
  m.finished = true;
}

int VideoWriter::frames() const { return impl_->frames; }
int VideoWriter::encoded_width() const { return impl_->enc->width; }
int VideoWriter::encoded_height() const { return impl_->enc->height; }

}  // namespace lc

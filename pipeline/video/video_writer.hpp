#pragma once
// Writes a video frame by frame through the FFmpeg libraries: 8-bit sRGB
// frames in, an encoded file out (H.264/yuv420p/MP4 with the moov atom first
// by default).  The file appears under its final name only after finish();
// a writer destroyed before that (an error, a Ctrl-C) leaves nothing there.
//
// Timing is exact: frame k is shown at k/fps for 1/fps, so N frames last
// exactly N/fps (each packet carries its duration and the stream its
// average frame rate; without them MP4 comes out one frame short).

#include <filesystem>
#include <memory>

#include "video/encode_options.hpp"
#include "video/rgb8_image.hpp"

namespace lc {

class VideoWriter {
 public:
  // Opens `out` (through a temporary beside it) for width x height frames.
  // Odd sides are padded to even by repeating the last column/row (4:2:0 and
  // 4:2:2 store colour per pair of pixels): see encoded_width().  Throws
  // std::invalid_argument for bad options or extension, std::runtime_error
  // naming `out` when it cannot be written or the encoder refuses.
  VideoWriter(const std::filesystem::path& out, int width, int height, const EncodeOptions& options);
  ~VideoWriter();
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;

  // Encodes the next frame; it must be width x height as opened (throws
  // std::invalid_argument otherwise).
  void add(const Rgb8Image& frame);

  // Drains the encoder, writes the index (moved to the front for MP4/MOV),
  // syncs and renames onto the final name.  Throws if no frame was added.
  void finish();

  int frames() const;
  int encoded_width() const;
  int encoded_height() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace lc

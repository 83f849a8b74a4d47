#include "video/encode_sequence.hpp"

#include <stdexcept>

#include <fmt/format.h>

#include "image/image_io.hpp"
#include "video/video_writer.hpp"

namespace lc {

namespace {
// The summary of a finished writer.
EncodeResult result_of(const VideoWriter& w, int width, int height, FrameRate fps) {
  return {w.frames(), width, height, w.encoded_width(), w.encoded_height(), static_cast<double>(w.frames()) * fps.den / fps.num};
}
}  // namespace

EncodeResult encode_sequence(const std::vector<std::filesystem::path>& images, const EncodeOptions& options,
                             const std::filesystem::path& out, const ProgressFn& progress) {
  // Inputs: image paths in display order; output: the video at `out`.
  // Options are checked before any image is read, so a bad flag costs nothing.
  validate(options);
  container_for(out, options.codec);
  if (images.empty()) throw std::runtime_error(fmt::format("cannot write {}: no frames to encode", out.string()));
  const int total = static_cast<int>(images.size());
  // The size from the first frame's header: one the encoder cannot take is
  // refused before a frame's pixels are decoded (at 16384x16384, gigabytes).
  const auto [width, height] = image_size(images.front());
  if (const auto why = size_refusal(options.codec, width, height))
    throw std::invalid_argument(fmt::format("{}: {}", images.front().string(), *why));
  VideoWriter writer(out, width, height, options);
  for (int i = 0; i < total; ++i) {
    const std::filesystem::path& p = images[static_cast<std::size_t>(i)];
    const Rgb8Image image = read_rgb8(p);
    if (image.width != width || image.height != height)
      throw std::runtime_error(fmt::format("{}: {}x{}, but the sequence's first frame {} is {}x{}", p.string(),
                                           image.width, image.height, images.front().filename().string(), width,
                                           height));
    writer.add(image);
    if (progress) progress(i + 1, total);
  }
  writer.finish();
  return result_of(writer, width, height, options.fps);
}

EncodeResult encode_still(const Rgb8Image& image, int frames, const EncodeOptions& options,
                          const std::filesystem::path& out, const ProgressFn& progress) {
  // Inputs: one picture and how many frames to hold it; output: the video.
  if (frames < 1) throw std::invalid_argument(fmt::format("cannot write {}: {} frames", out.string(), frames));
  VideoWriter writer(out, image.width, image.height, options);
  for (int i = 0; i < frames; ++i) {
    writer.add(image);
    if (progress) progress(i + 1, frames);
  }
  writer.finish();
  return result_of(writer, image.width, image.height, options.fps);
}

}  // namespace lc

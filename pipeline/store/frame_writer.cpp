#include "store/frame_writer.hpp"

#include <stdexcept>

#include <fmt/format.h>

#include "durable_file.hpp"
#include "image/png_check.hpp"

namespace lc::farm {

namespace {

enum class FrameFormat { exr, png };

// Writes `image` in `format` to `file`'s temporary and checks what lies on
// disk: an EXR is read back whole and its size checked; a PNG's chunks are
// checked whole with their CRCs and its size (image/png_check.hpp), which
// finds what a read-back would (a file cut short or changed) without
// decoding it.  Both go through the temporary's descriptor (library_path),
// never its name, so a link planted under the name is neither written
// through nor read.  Throws naming the final name.  The caller commits.
void write_verified(DurableFile& file, FrameFormat format, const FrameImage& image,
                    const ImageMetadata& metadata = {}, PngDepth depth = PngDepth::eight) {
  const std::filesystem::path temp = file.library_path();
  if (format == FrameFormat::exr)
    write_exr(temp, image, metadata, file.final_path());
  else
    write_png(temp, image, file.final_path(), depth);
  try {
    if (format == FrameFormat::png) return check_png_file(temp, image.width, image.height);
    const FrameImage back = read_exr(temp);
    if (back.width != image.width || back.height != image.height)
      throw std::runtime_error(fmt::format("it reads back as {}x{}", back.width, back.height));
  } catch (const std::exception& e) {
    throw std::runtime_error(fmt::format("cannot write {}: the file written does not read back ({})",
                                         file.final_path().string(), e.what()));
  }
}

}  // namespace

void write_frame_files(const std::filesystem::path& exr, const std::filesystem::path& png, const FrameImage& image,
                       const ImageMetadata& metadata, const Look& look, PngDepth png_depth) {
  // The frame store clears its folders of temporaries when a render starts;
  // the names are its own (a link there is replaced, not written through).
  DurableFile exr_file(exr, StaleTemporaries::cleaned_by_caller, FinalName::own),
      png_file(png, StaleTemporaries::cleaned_by_caller, FinalName::own);
  write_verified(exr_file, FrameFormat::exr, image, metadata);
  write_verified(png_file, FrameFormat::png, look.identity() ? image : look.applied(image), {}, png_depth);
  commit_together({&exr_file, &png_file});
}

void write_png_file(const std::filesystem::path& png, const FrameImage& image, const Look& look, PngDepth png_depth) {
  DurableFile file(png, StaleTemporaries::cleaned_by_caller, FinalName::own);
  write_verified(file, FrameFormat::png, look.identity() ? image : look.applied(image), {}, png_depth);
  file.commit();
}

}  // namespace lc::farm

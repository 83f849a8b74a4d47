#pragma once
// Frames out and images in: OpenEXR reference frames, 8-bit sRGB PNG
// previews, and reading both back.  OpenImageIO does the file formats but
// stays inside image_io.cpp: nothing that includes this header sees OIIO.
//
// Every function takes the file format from its own name (EXR or PNG), not
// from the path's extension, because the frame store writes to temporary
// names ("x.0001.exr.tmp-123") and renames.  Readers detect the format from
// the file's content.  Every failure is a std::runtime_error whose message
// names the file and the reason.  A writer given `named` (a DurableFile's
// final path while `path` leads to its temporary) names that file instead.
// A writer opens `path` as it is, following links (O_CREAT | O_TRUNC): a
// file in a folder lightcone keeps is never handed over by name but as the
// path of a descriptor lightcone created it under (/proc/self/fd/N,
// DurableFile::library_path in pipeline/store/durable_file.hpp).

#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "image/frame_image.hpp"

namespace lc {

using ImageMetadata = std::vector<std::pair<std::string, std::string>>;

// Bits per channel of a frame's PNG: 8 for video and the web, 16 for dome
// masters (a dome's dark skies band in 8 bits; docs/cameras.md).
enum class PngDepth { eight = 8, sixteen = 16 };

// Writes `image` as OpenEXR to `path`: channels R, G, B, then A where some
// pixel is not opaque (has_transparency: associated alpha, the colour
// already weighted by it), then one channel per layer named after it, all
// 32-bit FLOAT (reference images are never lossy and never half), zip
// compression, scanlines top to bottom, plus
// `metadata` as string attributes (e.g. "lightcone/shot" = "kerr_disk").
// Refuses an inconsistent image (sizes, empty or duplicate layer names, a
// layer called R, G, B or A) and metadata keys that would steer the writer
// instead of annotating the file (containing ':', or EXR's own header
// names such as "compression").  No timestamp is added, so equal frames and
// metadata give byte-identical files.  On a failure after the file was
// created the partial file is removed.
void write_exr(const std::filesystem::path& path, const FrameImage& image, const ImageMetadata& metadata = {},
               const std::filesystem::path& named = {});

// Writes the RGB of `image` as an sRGB PNG of `depth` bits per channel
// (linear -> sRGB curve, clamp, round to nearest; NaN -> 0), tagged as
// sRGB.  Alpha and layers are ignored: outside a dome's disc is black.
void write_png(const std::filesystem::path& path, const FrameImage& image, const std::filesystem::path& named = {},
               PngDepth depth = PngDepth::eight);

// Reads an EXR written by write_exr: R, G, B into rgb, A (if present) into
// alpha and every other channel, by name, into layers in the order the file
// lists them (OpenEXR sorts channel names, so that may differ from the order written).  Values
// are returned as stored, no colour conversion.  Throws when the file is not
// an EXR or has no R, G, B channels.
FrameImage read_exr(const std::filesystem::path& path);

// The string attributes of an EXR's header (those passed to write_exr, plus
// any OpenImageIO or OpenEXR add themselves), in file order.
ImageMetadata read_exr_metadata(const std::filesystem::path& path);

// The width and height of any image OpenImageIO understands, from its
// header alone (no pixel is decoded: a check of a 16384x16384 frame costs
// what one of 16x16 does).  Throws like read_image_linear for a missing or
// unreadable file, zero size, or a side above max_image_side.
std::pair<int, int> image_size(const std::filesystem::path& path);

// Reads any image OpenImageIO understands into linear RGB (layers empty).
// Colour: the file's colour-space tag decides (sRGB, linear, gamma n); with
// no usable tag integer data is taken as sRGB and floating point as linear.
// Grey images are copied to R, G and B.  Unassociated alpha is applied in
// linear light (composited over black, what an opaque sky needs); other
// channels beyond the fourth are ignored.  Throws for a missing file, a
// file no reader accepts, zero size, or a side above max_image_side.
FrameImage read_image_linear(const std::filesystem::path& path);

// A band of rows of an image, in linear RGB (3 * width floats a row).
struct ImageBand {
  int width = 0, height = 0;  // the whole image's
  int y0 = 0, rows = 0;       // the band: rows y0 .. y0 + rows - 1
  std::span<const float> rgb;
};

// Reads an image as read_image_linear does, `band_rows` rows at a time, top
// to bottom, handing each band to `use` (valid during the call): for
// callers that reduce the image as it comes (a contact sheet's
// thumbnails), so that memory is one band, not the image.  A tiled file is
// one band (its reader gives no scanlines), and so is an interlaced PNG in
// OpenImageIO's reader.  Throws as read_image_linear, but takes any size
// up to max_image_side a side.
void read_image_bands(const std::filesystem::path& path, int band_rows, const std::function<void(const ImageBand&)>& use);

}  // namespace lc

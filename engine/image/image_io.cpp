// The OpenImageIO side of the image layer: EXR and PNG writers and the
// readers.  OIIO is included here only (it bundles its own fmt, see
// STACK.md), so error messages are built with plain std::string.
#include "image/image_io.hpp"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <span>
#include <stdexcept>
#include <string_view>
#include <system_error>

#include "image/read_linear.hpp"
#include "image/srgb.hpp"
#include "image/srgb8_encoder.hpp"

// The build option LIGHTCONE_OWN_IMAGE_CODECS (CMakeLists.txt) sets this to
// 1 or 0 for this file alone: whether 8-bit PNGs and lightcone's own EXRs go
// through lightcone's codecs or, as before them, through OpenImageIO.
#if !defined(LIGHTCONE_OWN_IMAGE_CODECS)
#error "image_io.cpp is built with LIGHTCONE_OWN_IMAGE_CODECS set to 1 or 0 (engine/CMakeLists.txt)"
#elif LIGHTCONE_OWN_IMAGE_CODECS
#include "image/exr_rgb_reader.hpp"
#include "image/png_encoder.hpp"
#endif

namespace lc {
namespace {

namespace fs = std::filesystem;

// Throws "<what> '<path>': <reason>".
[[noreturn]] void fail(std::string_view what, const fs::path& path, const std::string& reason) {
  throw std::runtime_error(std::string(what) + " '" + path.string() + "': " + reason);
}

// OIIO's error text on one line (it stacks messages line by line), never empty.
std::string oiio_reason(std::string msg) {
  while (!msg.empty() && std::isspace(static_cast<unsigned char>(msg.back()))) msg.pop_back();
  for (std::size_t at = msg.find('\n'); at != std::string::npos; at = msg.find('\n', at)) msg.replace(at, 1, "; ");
  return msg.empty() ? std::string("unknown OpenImageIO error") : msg;
}

// The first of OIIO's stacked messages, one a line (a writer that fails on
// every block says so thousands of times).
std::string first_line(std::string msg) {
  while (!msg.empty() && std::isspace(static_cast<unsigned char>(msg.back()))) msg.pop_back();
  const std::size_t at = msg.find('\n');
  return at == std::string::npos ? msg : msg.substr(0, at) + " (and more)";
}

std::string lowercase(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string size_text(long w, long h) { return std::to_string(w) + " x " + std::to_string(h); }

// Checks width/height are positive and at most max_image_side.
void check_size(long w, long h, std::string_view what, const fs::path& path) {
  if (w <= 0 || h <= 0) fail(what, path, "zero-size image (" + size_text(w, h) + ")");
  if (w > max_image_side || h > max_image_side)
    fail(what, path,
         "image too large (" + size_text(w, h) + "; at most " + std::to_string(max_image_side) + " a side)");
}

// Checks a frame is self-consistent before anything is written: buffer
// sizes, and (for EXR) layer names that will survive as distinct channels.
void check_frame(const FrameImage& im, bool with_layers, std::string_view what, const fs::path& path) {
  check_size(im.width, im.height, what, path);
  const std::size_t n = static_cast<std::size_t>(im.width) * static_cast<std::size_t>(im.height);
  if (im.rgb.size() != 3 * n)
    fail(what, path,
         "rgb holds " + std::to_string(im.rgb.size()) + " floats, expected 3 * " + size_text(im.width, im.height));
  if (!with_layers) return;
  if (!im.alpha.empty() && im.alpha.size() != n)
    fail(what, path,
         "alpha holds " + std::to_string(im.alpha.size()) + " floats, expected " + size_text(im.width, im.height));
  std::set<std::string> names{"R", "G", "B", "A"};
  for (const FrameImage::Layer& l : im.layers) {
    if (l.name.empty()) fail(what, path, "a data layer has an empty name");
    if (!names.insert(l.name).second)
      fail(what, path, "data layer name '" + l.name + "' is used twice or clashes with R, G, B, A");
    if (l.values.size() != n)
      fail(what, path,
           "data layer '" + l.name + "' holds " + std::to_string(l.values.size()) + " floats, expected " +
               size_text(im.width, im.height));
  }
}

// Metadata keys must annotate the file, never reconfigure the writer:
// OIIO reads "format:name" keys as instructions to a writer, and EXR's own
// header attributes describe the pixel layout.
void check_metadata(const ImageMetadata& metadata, std::string_view what, const fs::path& path) {
  static constexpr std::array<std::string_view, 14> reserved = {
      "channels", "chunkcount",       "compression",        "datawindow",        "displaywindow", "lineorder", "name",
      "tiles",    "pixelaspectratio", "screenwindowcenter", "screenwindowwidth", "type",          "version",   "view"};
  for (const auto& [key, value] : metadata) {
    if (key.empty()) fail(what, path, "metadata key is empty");
    if (key.find(':') != std::string::npos ||
        std::find(reserved.begin(), reserved.end(), lowercase(key)) != reserved.end())
      fail(what, path, "metadata key '" + key + "' is reserved for the file format");
  }
}

// OIIO's writers go through this proxy, not OIIO's own file: its file
// proxy notes a short write (a full disk) in the writer's error text but
// write_image() and close() still report success, so a truncated PNG was
// taken as written (issue #25).  Here every write is checked, the first
// OS error is kept with its errno, and close() is checked too (NFS reports
// write errors there).
class CheckedFileOutput final : public OIIO::Filesystem::IOProxy {
 public:
  explicit CheckedFileOutput(const fs::path& path) : IOProxy(path.string(), Write) {
    fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd_ < 0) {
      errno_ = errno;
      m_mode = Closed;
    }
  }
  ~CheckedFileOutput() override { close(); }
  const char* proxytype() const override { return "lightcone-checked-file"; }
  void close() override {
    if (fd_ < 0) return;
    if (::close(fd_) != 0 && errno_ == 0) errno_ = errno;
    fd_ = -1;
    m_mode = Closed;
  }
  bool seek(int64_t offset) override {
    m_pos = offset;
    return true;
  }
  size_t write(const void* buf, size_t size) override {
    const size_t n = pwrite(buf, size, m_pos);
    m_pos += static_cast<int64_t>(n);
    return n;
  }
  size_t pwrite(const void* buf, size_t size, int64_t offset) override {
    // Loops because write() may take fewer bytes than asked.
    const char* p = static_cast<const char*>(buf);
    size_t done = 0;
    while (fd_ >= 0 && done < size) {
      const ssize_t n = ::pwrite(fd_, p + done, size - done, static_cast<off_t>(offset) + static_cast<off_t>(done));
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        if (errno_ == 0) errno_ = n < 0 ? errno : EIO;
        break;
      }
      done += static_cast<size_t>(n);
    }
    end_ = std::max(end_, offset + static_cast<int64_t>(done));
    return done;
  }
  size_t size() const override { return static_cast<size_t>(end_); }
  // The first OS error (0: none).
  int os_error() const { return errno_; }

 private:
  int fd_ = -1;
  int errno_ = 0;
  int64_t end_ = 0;
};

// Writes interleaved `pixels` of type `type` laid out as `spec` to `path`
// with OIIO's writer for `format` (a format name, so the extension of
// `path` does not matter), through CheckedFileOutput.  Messages name
// `named` when given (the final name of a temporary `path`), else `path`.
// Removes the half-written file if writing or closing fails after it was
// opened (a descriptor's path, /proc/self/fd/N, cannot be removed: the
// file's owner, a DurableFile, removes it); the reason is the OS's when it
// had one ("No space left on device").
void write_with(const char* format, const OIIO::ImageSpec& spec, OIIO::TypeDesc type, const void* pixels,
                std::string_view what, const fs::path& path, const fs::path& named) {
  const fs::path& blame = named.empty() ? path : named;
  std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(format);
  if (!out) fail(what, blame, std::string("no OpenImageIO writer for ") + format + ": " + oiio_reason(OIIO::geterror()));
  if (!out->supports("ioproxy")) fail(what, blame, std::string("the OpenImageIO writer for ") + format + " takes no I/O proxy");
  CheckedFileOutput file(path);
  if (file.os_error() != 0) fail(what, blame, std::strerror(file.os_error()));
  std::string error;
  if (!out->set_ioproxy(&file) || !out->open(path.string(), spec)) error = out->geterror();
  if (error.empty() && !out->write_image(type, pixels)) error = out->geterror();
  if (!out->close() && error.empty()) error = out->geterror();
  if (error.empty() && out->has_error()) error = out->geterror();
  file.close();
  if (file.os_error() != 0) error = std::strerror(file.os_error());  // the cause, rather than OIIO's account of it
  if (error.empty()) return;
  out.reset();
  std::error_code ignored;
  fs::remove(path, ignored);
  fail(what, blame, oiio_reason(first_line(error)));
}

#if LIGHTCONE_OWN_IMAGE_CODECS
// Writes `bytes` (a whole file made here) to `path` through
// CheckedFileOutput, with write_with's messages, and removes what was
// written if it fails.
void write_bytes(std::span<const unsigned char> bytes, std::string_view what, const fs::path& path,
                 const fs::path& named) {
  const fs::path& blame = named.empty() ? path : named;
  CheckedFileOutput file(path);
  if (file.os_error() != 0) fail(what, blame, std::strerror(file.os_error()));
  file.write(bytes.data(), bytes.size());
  file.close();
  const int error = file.os_error();
  if (error == 0) return;
  std::error_code ignored;
  fs::remove(path, ignored);
  fail(what, blame, std::strerror(error));
}
#endif

// Fails with a clear reason when `path` is not an existing regular file
// (OIIO's own message for a missing file is "could not open").
void check_readable(const fs::path& path, std::string_view what) {
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (!fs::exists(st)) fail(what, path, "no such file");
  if (fs::is_directory(st)) fail(what, path, "is a directory, not an image");
}

// Opens `path` with OIIO's OpenEXR reader (by format name: the extension
// does not matter, a non-EXR file is refused).
std::unique_ptr<OIIO::ImageInput> open_exr(const fs::path& path, std::string_view what) {
  check_readable(path, what);
  std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::create("openexr");
  if (!in) fail(what, path, "no OpenImageIO reader for OpenEXR: " + oiio_reason(OIIO::geterror()));
  OIIO::ImageSpec spec;
  if (!in->open(path.string(), spec)) fail(what, path, "not a readable OpenEXR file: " + oiio_reason(in->geterror()));
  return in;
}

// How stored values map to linear light.
struct Transfer {
  enum Kind { linear, srgb, gamma } kind = linear;
  double exponent = 1.0;  // for gamma: linear = stored^exponent
};

// The file's colour-space tag decides; without a tag this reader knows,
// integer data is taken as sRGB (what 8/16-bit images on disk almost
// always are) and floating point as linear.  Primaries are never
// converted: a linear ACEScg texture is read as if it were linear Rec.709.
Transfer transfer_of(const OIIO::ImageSpec& spec) {
  const std::string cs = lowercase(spec.get_string_attribute("oiio:ColorSpace"));
  if (cs.find("lin") != std::string::npos || cs == "acescg") return {Transfer::linear};
  if (cs.find("srgb") != std::string::npos) return {Transfer::srgb};
  if (cs.rfind("gammacorrected", 0) == 0 || cs.rfind("gamma", 0) == 0) {
    // "GammaCorrected2.2": the exponent follows the name unless oiio:Gamma says it.
    const std::size_t digits = std::min(cs.find_first_of("0123456789."), cs.size());
    double g = std::strtod(cs.c_str() + digits, nullptr);
    g = spec.get_float_attribute("oiio:Gamma", static_cast<float>(g));
    if (g > 0.1 && g < 10.0) return {Transfer::gamma, g};
    return {Transfer::srgb};  // unreadable exponent: sRGB is the closest common guess
  }
  return spec.format.is_floating_point() ? Transfer{Transfer::linear} : Transfer{Transfer::srgb};
}

// Stored value (normalised to [0, 1] for integer formats) -> linear.
double decode(const Transfer& t, double v) {
  switch (t.kind) {
    case Transfer::linear:
      return v;
    case Transfer::srgb:
      return srgb_to_linear(v);
    case Transfer::gamma:
      return v > 0.0 ? std::pow(v, t.exponent) : 0.0;
  }
  return v;
}

}  // namespace

// Validates, names the channels, interleaves RGB (A) and layers, writes FLOAT zip.
void write_exr(const std::filesystem::path& path, const FrameImage& image, const ImageMetadata& metadata,
               const std::filesystem::path& named) {
  constexpr std::string_view what = "cannot write EXR";
  const fs::path& blame = named.empty() ? path : named;
  check_frame(image, true, what, blame);
  check_metadata(metadata, what, blame);
  const bool with_alpha = has_transparency(image);
  const int first_layer = with_alpha ? 4 : 3;
  const int nch = first_layer + static_cast<int>(image.layers.size());
  OIIO::ImageSpec spec(image.width, image.height, nch, OIIO::TypeDesc::FLOAT);
  spec.channelnames = {"R", "G", "B"};
  if (with_alpha) spec.channelnames.push_back("A");
  for (const FrameImage::Layer& l : image.layers) spec.channelnames.push_back(l.name);
  // The ImageSpec constructor guessed a 4th channel to be alpha; data
  // layers are plain values, never composited.  A is EXR's associated
  // alpha: the colour is already the mean over all samples, black ones
  // where the camera had no ray included.
  spec.alpha_channel = with_alpha ? 3 : -1;
  spec.z_channel = -1;
  spec.attribute("compression", "zip");
  // OIIO stamps the current time into the header unless told otherwise (an
  // empty DateTime writes none): the same frame then gives the same bytes,
  // whichever run or node wrote it.  A caller may still pass a DateTime.
  spec.attribute("DateTime", "");
  for (const auto& [key, value] : metadata) spec.attribute(key, value);

  // OIIO writes interleaved pixels; alpha and layers are planar in FrameImage.
  const std::size_t n = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height);
  std::vector<float> pixels(n * static_cast<std::size_t>(nch));
  for (std::size_t p = 0; p < n; ++p) {
    float* px = &pixels[p * static_cast<std::size_t>(nch)];
    px[0] = image.rgb[3 * p];
    px[1] = image.rgb[3 * p + 1];
    px[2] = image.rgb[3 * p + 2];
    if (with_alpha) px[3] = image.alpha[p];
    for (std::size_t l = 0; l < image.layers.size(); ++l) px[first_layer + l] = image.layers[l].values[p];
  }
  write_with("openexr", spec, OIIO::TypeDesc::FLOAT, pixels.data(), what, path, named);
}

// Encodes to sRGB codes here (srgb.hpp); 8-bit PNGs are made by
// png_encoder.hpp (faster) when built with lightcone's own codecs, every
// other PNG stored by OIIO.
void write_png(const std::filesystem::path& path, const FrameImage& image, const std::filesystem::path& named,
               PngDepth depth) {
  constexpr std::string_view what = "cannot write PNG";
  check_frame(image, false, what, named.empty() ? path : named);
  // `codes` through OIIO's PNG writer, tagged sRGB.
  const auto store = [&](OIIO::TypeDesc type, const void* codes) {
    OIIO::ImageSpec spec(image.width, image.height, 3, type);
    spec.attribute("oiio:ColorSpace", "sRGB");  // the writer then stores an sRGB chunk
    write_with("png", spec, type, codes, what, path, named);
  };
  if (depth == PngDepth::sixteen) {
    std::vector<std::uint16_t> codes(image.rgb.size());
    std::transform(image.rgb.begin(), image.rgb.end(), codes.begin(), linear_to_srgb16);
    store(OIIO::TypeDesc::UINT16, codes.data());
    return;
  }
  std::vector<std::uint8_t> codes(image.rgb.size());
  std::transform(image.rgb.begin(), image.rgb.end(), codes.begin(), std::cref(Srgb8Encoder::shared()));
#if LIGHTCONE_OWN_IMAGE_CODECS
  write_bytes(encode_png8(codes, image.width, image.height), what, path, named);
#else
  store(OIIO::TypeDesc::UINT8, codes.data());
#endif
}

// Lightcone's own layout directly (exr_rgb_reader.hpp) when built with
// lightcone's own codecs; any other file through OIIO: every channel as
// float, then R, G, B split from the layers by name.
FrameImage read_exr(const std::filesystem::path& path) {
#if LIGHTCONE_OWN_IMAGE_CODECS
  if (std::optional<FrameImage> own = read_rgb_exr(path)) return std::move(*own);
#endif
  constexpr std::string_view what = "cannot read EXR";
  std::unique_ptr<OIIO::ImageInput> in = open_exr(path, what);
  const OIIO::ImageSpec spec = in->spec();
  check_size(spec.width, spec.height, what, path);
  if (spec.depth != 1) fail(what, path, "a volume image, not a frame");
  const int nch = spec.nchannels;
  static constexpr std::array<std::string_view, 3> rgb_names = {"R", "G", "B"};
  int rgb_index[3] = {-1, -1, -1};
  for (int c = 0; c < nch; ++c)
    for (int k = 0; k < 3; ++k)
      if (spec.channelnames[static_cast<std::size_t>(c)] == rgb_names[static_cast<std::size_t>(k)]) rgb_index[k] = c;
  if (rgb_index[0] < 0 || rgb_index[1] < 0 || rgb_index[2] < 0)
    fail(what, path, "no R, G, B channels (not a frame written by lightcone)");

  const std::size_t n = static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.height);
  std::vector<float> pixels(n * static_cast<std::size_t>(nch));
  if (!in->read_image(0, 0, 0, nch, OIIO::TypeDesc::FLOAT, pixels.data()))
    fail(what, path, oiio_reason(in->geterror()));

  FrameImage image;
  image.width = spec.width;
  image.height = spec.height;
  image.rgb.resize(3 * n);
  int alpha_index = -1;
  for (int c = 0; c < nch; ++c)
    if (spec.channelnames[static_cast<std::size_t>(c)] == "A") alpha_index = c;
  if (alpha_index >= 0) image.alpha.resize(n);
  for (int c = 0; c < nch; ++c) {
    if (c == rgb_index[0] || c == rgb_index[1] || c == rgb_index[2] || c == alpha_index) continue;
    image.layers.push_back({spec.channelnames[static_cast<std::size_t>(c)], std::vector<float>(n)});
  }
  for (std::size_t p = 0; p < n; ++p) {
    const float* px = &pixels[p * static_cast<std::size_t>(nch)];
    for (int k = 0; k < 3; ++k) image.rgb[3 * p + static_cast<std::size_t>(k)] = px[rgb_index[k]];
    std::size_t l = 0;
    if (alpha_index >= 0) image.alpha[p] = px[alpha_index];
    for (int c = 0; c < nch; ++c)
      if (c != rgb_index[0] && c != rgb_index[1] && c != rgb_index[2] && c != alpha_index)
        image.layers[l++].values[p] = px[c];
  }
  return image;
}

// Only the header is read, no pixels.
ImageMetadata read_exr_metadata(const std::filesystem::path& path) {
  std::unique_ptr<OIIO::ImageInput> in = open_exr(path, "cannot read EXR");
  ImageMetadata metadata;
  for (const OIIO::ParamValue& p : in->spec().extra_attribs)
    if (p.type() == OIIO::TypeString) metadata.emplace_back(p.name().string(), p.get_string());
  return metadata;
}

// Opens by content like the reader, but stops at the header.
std::pair<int, int> image_size(const std::filesystem::path& path) {
  constexpr std::string_view what = "cannot read image";
  check_readable(path, what);
  std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path.string());
  if (!in) fail(what, path, "not an image OpenImageIO can read (" + oiio_reason(OIIO::geterror()) + ")");
  const OIIO::ImageSpec& spec = in->spec();
  check_size(spec.width, spec.height, what, path);
  return {spec.width, spec.height};
}

// The shared reader, with messages that say "image".
FrameImage read_image_linear(const std::filesystem::path& path) {
  return detail::read_linear_rgb(path, "cannot read image");
}

namespace {

// How a file's stored channels become linear RGB (the rules at
// read_image_linear), found once from its header.
struct LinearDecoder {
  int width = 0, height = 0;
  int nread = 0;  // channels read: at most four
  int alpha = -1;
  std::array<int, 3> colour{};
  bool apply_alpha = false;
  Transfer transfer;
  bool eight_bit = false;
  std::array<float, 256> table{};  // 8-bit code -> linear

  // Reads rows [y0, y1) of `in` and writes their linear RGB to `rgb`
  // (3 * width * (y1 - y0) floats).  The whole image is read with one
  // read_image (any file, tiled ones too), a band of it with read_scanlines.
  void read_rows(OIIO::ImageInput& in, int y0, int y1, float* rgb, const char* what, const fs::path& path) const;
};

// Opens by content (any extension), checks the size, and works out the
// channels and their decoding.
std::pair<std::unique_ptr<OIIO::ImageInput>, LinearDecoder> open_linear(const fs::path& path, const char* what) {
  check_readable(path, what);
  // Ask for alpha as stored so it can be applied in linear light below
  // (OIIO would otherwise premultiply the sRGB-encoded values).
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path.string(), &config);
  if (!in) fail(what, path, "not an image OpenImageIO can read (" + oiio_reason(OIIO::geterror()) + ")");
  const OIIO::ImageSpec& spec = in->spec();
  check_size(spec.width, spec.height, what, path);
  if (spec.depth != 1) fail(what, path, "a volume image, not a 2D image");
  if (spec.nchannels < 1) fail(what, path, "image has no channels");

  LinearDecoder d;
  d.width = spec.width;
  d.height = spec.height;
  // Colour channels: the first three that are not alpha (one means grey).
  d.nread = std::min(spec.nchannels, 4);
  d.alpha = spec.alpha_channel >= 0 && spec.alpha_channel < d.nread ? spec.alpha_channel : -1;
  int ncolour = 0;
  for (int c = 0; c < d.nread && ncolour < 3; ++c)
    if (c != d.alpha) d.colour[static_cast<std::size_t>(ncolour++)] = c;
  if (ncolour == 0) fail(what, path, "image has only an alpha channel");
  if (ncolour < 3) d.colour = {d.colour[0], d.colour[0], d.colour[0]};
  d.apply_alpha = d.alpha >= 0 && spec.get_int_attribute("oiio:UnassociatedAlpha", 0) != 0;
  d.transfer = transfer_of(spec);
  // 8-bit data goes through a 256-entry table: a large sky texture would
  // otherwise cost one pow() per value at load.
  d.eight_bit = spec.format == OIIO::TypeDesc::UINT8 && spec.channelformats.empty();
  for (int k = 0; k < 256; ++k) d.table[static_cast<std::size_t>(k)] = static_cast<float>(decode(d.transfer, k / 255.0));
  return {std::move(in), d};
}

void LinearDecoder::read_rows(OIIO::ImageInput& in, int y0, int y1, float* rgb, const char* what,
                              const fs::path& path) const {
  const bool whole = y0 == 0 && y1 == height;
  auto read = [&](OIIO::TypeDesc type, void* data) {
    const bool ok = whole ? in.read_image(0, 0, 0, nread, type, data)
                          : in.read_scanlines(0, 0, y0, y1, 0, 0, nread, type, data);
    if (!ok) fail(what, path, oiio_reason(in.geterror()));
  };
  const std::size_t n = static_cast<std::size_t>(width) * static_cast<std::size_t>(y1 - y0);
  std::vector<float> values(n * static_cast<std::size_t>(nread));
  if (eight_bit) {
    std::vector<std::uint8_t> bytes(values.size());
    read(OIIO::TypeDesc::UINT8, bytes.data());
    for (std::size_t i = 0; i < bytes.size(); ++i) values[i] = table[bytes[i]];
    if (alpha >= 0)  // alpha is coverage, never colour-decoded
      for (std::size_t p = 0; p < n; ++p)
        values[p * static_cast<std::size_t>(nread) + static_cast<std::size_t>(alpha)] =
            bytes[p * static_cast<std::size_t>(nread) + static_cast<std::size_t>(alpha)] / 255.0f;
  } else {
    read(OIIO::TypeDesc::FLOAT, values.data());
    if (transfer.kind != Transfer::linear)
      for (std::size_t i = 0; i < values.size(); ++i)
        if (static_cast<int>(i % static_cast<std::size_t>(nread)) != alpha)
          values[i] = static_cast<float>(decode(transfer, values[i]));
  }
  for (std::size_t p = 0; p < n; ++p) {
    const float* px = &values[p * static_cast<std::size_t>(nread)];
    const float a = apply_alpha ? px[alpha] : 1.0f;
    for (std::size_t k = 0; k < 3; ++k) rgb[3 * p + k] = px[colour[k]] * a;
  }
}

}  // namespace

// Checks the size before allocating, then reads the whole image at once.
FrameImage detail::read_linear_rgb(const std::filesystem::path& path, const char* what, long max_pixels) {
  auto [in, d] = open_linear(path, what);
  if (long{d.width} * d.height > max_pixels)
    fail(what, path,
         "image too large (" + size_text(d.width, d.height) + "; at most " + std::to_string(max_pixels) +
             " pixels, e.g. " + size_text(static_cast<long>(std::sqrt(2.0 * max_pixels)),
                                          static_cast<long>(std::sqrt(0.5 * max_pixels))) +
             ": it is held as float RGB, 12 bytes a pixel)");
  FrameImage image;
  image.width = d.width;
  image.height = d.height;
  image.rgb.resize(3 * static_cast<std::size_t>(d.width) * static_cast<std::size_t>(d.height));
  d.read_rows(*in, 0, d.height, image.rgb.data(), what, path);
  return image;
}

void read_image_bands(const std::filesystem::path& path, int band_rows, const std::function<void(const ImageBand&)>& use) {
  constexpr const char* what = "cannot read image";
  auto [in, d] = open_linear(path, what);
  // A tiled file is read whole: its reader gives no scanlines.
  const int rows = in->spec().tile_width > 0 ? d.height : std::clamp(band_rows, 1, d.height);
  std::vector<float> rgb(3 * static_cast<std::size_t>(d.width) * static_cast<std::size_t>(rows));
  for (int y0 = 0; y0 < d.height; y0 += rows) {
    const int y1 = std::min(d.height, y0 + rows);
    d.read_rows(*in, y0, y1, rgb.data(), what, path);
    use(ImageBand{d.width, d.height, y0, y1 - y0,
                  std::span<const float>(rgb.data(), 3 * static_cast<std::size_t>(d.width) * static_cast<std::size_t>(y1 - y0))});
  }
}

}  // namespace lc

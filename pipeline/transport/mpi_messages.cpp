#include "transport/mpi_messages.hpp"

#include <cstring>
#include <stdexcept>

#include <fmt/format.h>

#include "core/constants.hpp"

namespace lc::farm {

namespace {

template <class T>
void put(Bytes& b, const T& v) {
  // resize + memcpy rather than insert: GCC 12 warns falsely about the
  // latter (-Wstringop-overflow on a range of sizeof(T) bytes).
  const std::size_t at = b.size();
  b.resize(at + sizeof(T));
  std::memcpy(b.data() + at, &v, sizeof(T));
}

template <class T>
T get(std::span<const char> b, std::size_t& at) {
  if (at + sizeof(T) > b.size()) throw std::runtime_error("farm message: truncated");
  T v;
  std::memcpy(&v, b.data() + at, sizeof(T));
  at += sizeof(T);
  return v;
}

struct ResultHeader {
  std::int32_t frame, stripe, pass;
  std::int32_t sky;    // planes of sky points that follow the rows' pixels (FrameImage::sky_planes): 0, 1 or a
                       // blurred frame's instants
  std::int32_t alpha;  // 1 when the rows' alpha follows their RGB (some pixel is not opaque)
  std::int32_t unused = 0;
  std::int64_t rays, steps, gave_up, reused;
  double seconds;
};

}  // namespace

Bytes pack_hello(const Hello& h) {
  Bytes b;
  put(b, h.digest);
  put(b, static_cast<std::int64_t>(h.threads));
  const std::string host = h.host.substr(0, 255);
  put(b, static_cast<std::uint8_t>(host.size()));
  b.insert(b.end(), host.begin(), host.end());
  return b;
}

Hello unpack_hello(std::span<const char> b) {
  std::size_t at = 0;
  Hello h;
  h.digest = get<std::uint64_t>(b, at);
  h.threads = static_cast<int>(get<std::int64_t>(b, at));
  const auto n = get<std::uint8_t>(b, at);
  if (at + n > b.size()) throw std::runtime_error("farm message: truncated");
  h.host.assign(b.data() + at, n);
  return h;
}

Bytes pack_count(int n) {
  Bytes b;
  put(b, static_cast<std::int32_t>(n));
  return b;
}

int unpack_count(std::span<const char> b) {
  std::size_t at = 0;
  return get<std::int32_t>(b, at);
}

Bytes pack_items(const std::vector<WorkItem>& items) {
  Bytes b;
  put(b, static_cast<std::int32_t>(items.size()));
  for (const auto& i : items) {
    put(b, static_cast<std::int32_t>(i.frame));
    put(b, static_cast<std::int32_t>(i.stripe));
    put(b, static_cast<std::int32_t>(i.pass));
  }
  return b;
}

std::vector<WorkItem> unpack_items(std::span<const char> b) {
  std::size_t at = 0;
  const auto n = get<std::int32_t>(b, at);
  if (n < 0 || static_cast<std::size_t>(n) * 12 + 4 != b.size()) throw std::runtime_error("farm message: bad work list");
  std::vector<WorkItem> out(static_cast<std::size_t>(n));
  for (auto& i : out) {
    i.frame = get<std::int32_t>(b, at);
    i.stripe = get<std::int32_t>(b, at);
    i.pass = get<std::int32_t>(b, at) == 0 ? Pass::preview : Pass::full;
  }
  return out;
}

namespace {

// Bytes of the rows that follow a result's header.
std::size_t row_bytes(std::size_t rows, std::size_t w, std::size_t layers, bool alpha, std::size_t sky_planes) {
  return rows * w * ((3 + (alpha ? 1 : 0) + layers) * sizeof(float) + sky_planes * sizeof(SkyPoint));
}

// Whether a pixel of these rows is not opaque: only then is alpha sent (a
// receiving canvas starts opaque, make_frame), so a pinhole's results are
// no larger for it.
bool rows_have_transparency(const FrameImage& canvas, const std::vector<int>& rows) {
  if (canvas.alpha.empty()) return false;
  const std::size_t w = static_cast<std::size_t>(canvas.width);
  for (int j : rows)
    for (std::size_t i = 0; i < w; ++i)
      if (canvas.alpha[w * static_cast<std::size_t>(j) + i] != 1.0f) return true;
  return false;
}

}  // namespace

Bytes pack_result(const WorkItem& item, const RenderStats& stats, const FrameImage& canvas,
                  const std::vector<int>& rows) {
  const std::size_t w = static_cast<std::size_t>(canvas.width);
  const std::size_t sky = canvas.sky_planes(), plane = w * static_cast<std::size_t>(canvas.height);
  const bool alpha = rows_have_transparency(canvas, rows);
  const std::size_t bytes = row_bytes(rows.size(), w, canvas.layers.size(), alpha, sky);
  Bytes b;
  b.reserve(sizeof(ResultHeader) + bytes);
  put(b, ResultHeader{item.frame, item.stripe, static_cast<std::int32_t>(item.pass),
                      static_cast<std::int32_t>(sky), alpha ? 1 : 0, 0,
                      stats.rays, stats.steps, stats.gave_up, stats.reused, stats.seconds});
  auto append = [&](const auto* p, std::size_t n) {
    const char* c = reinterpret_cast<const char*>(p);
    b.insert(b.end(), c, c + n * sizeof(*p));
  };
  for (int j : rows) {
    append(canvas.rgb.data() + 3 * w * j, 3 * w);
    if (alpha) append(canvas.alpha.data() + w * j, w);
    for (const auto& layer : canvas.layers) append(layer.values.data() + w * j, w);
    for (std::size_t k = 0; k < sky; ++k) append(canvas.sky.data() + k * plane + w * j, w);
  }
  return b;
}

WorkItem result_item(std::span<const char> b) {
  std::size_t at = 0;
  const auto h = get<ResultHeader>(b, at);
  return {h.frame, h.stripe, h.pass == 0 ? Pass::preview : Pass::full};
}

RenderStats unpack_result(std::span<const char> b, FrameImage& canvas, const std::vector<int>& rows) {
  std::size_t at = 0;
  const auto h = get<ResultHeader>(b, at);
  const std::size_t w = static_cast<std::size_t>(canvas.width);
  if (h.alpha && canvas.alpha.size() != w * static_cast<std::size_t>(canvas.height))
    throw std::runtime_error(fmt::format("farm message: stripe {} of frame {} has alpha its canvas has no room for",
                                         h.stripe, h.frame));
  if (h.sky < 0 || h.sky > max_time_samples)
    throw std::runtime_error(fmt::format("farm message: stripe {} of frame {} has {} planes of sky points", h.stripe,
                                         h.frame, h.sky));
  const std::size_t sky = static_cast<std::size_t>(h.sky), plane = w * static_cast<std::size_t>(canvas.height);
  const std::size_t bytes = row_bytes(rows.size(), w, canvas.layers.size(), h.alpha != 0, sky);
  if (b.size() != sizeof(ResultHeader) + bytes)
    throw std::runtime_error(fmt::format("farm message: stripe {} of frame {} has {} bytes, expected {}", h.stripe,
                                         h.frame, b.size(), sizeof(ResultHeader) + bytes));
  // The first stripe with sky points makes room for the frame's.
  if (sky) canvas.sky.resize(sky * plane);
  auto take = [&](auto* p, std::size_t n) {
    std::memcpy(p, b.data() + at, n * sizeof(*p));
    at += n * sizeof(*p);
  };
  for (int j : rows) {
    take(canvas.rgb.data() + 3 * w * j, 3 * w);
    if (h.alpha) take(canvas.alpha.data() + w * j, w);
    for (auto& layer : canvas.layers) take(layer.values.data() + w * j, w);
    for (std::size_t k = 0; k < sky; ++k) take(canvas.sky.data() + k * plane + w * j, w);
  }
  return {h.rays, h.steps, h.gave_up, h.reused, h.seconds};
}

}  // namespace lc::farm

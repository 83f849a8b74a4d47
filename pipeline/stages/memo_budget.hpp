#pragma once
// How much memory a process may give its sample memo (render/sample_memo.hpp):
// a whole frame's samples at 1280x720 2x2 are ~170 MB, at 3840x2160 4x4 ~5 GB;
// and whether a render's frames fit this machine's memory at all.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "render/render_settings.hpp"

namespace lc::farm {

// Why a process, one of `sharers` rendering on this node, should not keep a
// memo for frames of `rs` (it would take more than a quarter of the node's
// physical memory divided among them), or nullopt when it may.
std::optional<std::string> memo_refusal(const RenderSettings& rs, int sharers);

// The memory a render's master holds for one frame at its peak, per
// pixel of the frame: its canvas (colour, alpha, each pixel's ray for the
// point stars), the copy the stars are drawn on and the EXR's interleaved
// buffer and read-back (docs/performance.md, change 43).
inline constexpr double frame_peak_bytes_per_pixel = 108.0;

// The memory this process may use, in bytes: the least of the machine's
// physical memory, what the kernel says is available now (MemAvailable)
// and the memory limit of its cgroup (v2 memory.max or v1
// memory.limit_in_bytes, its own and its parents'), each where it can be
// read; `from` says which gave it ("MemAvailable").  nullopt when none
// can be read.
struct MemoryBound {
  std::uint64_t bytes = 0;
  std::string from;
};
std::optional<MemoryBound> memory_available();

// Why frames of `rs` cannot be rendered with `available` bytes (one
// frame's peak, frame_peak_bytes_per_pixel a pixel of the rendered image,
// is more), naming the figures and what to change; nullopt when they fit.
std::optional<std::string> frame_memory_refusal(const RenderSettings& rs, const MemoryBound& available);

}  // namespace lc::farm

#pragma once
// How much memory a process may give its sample memo (render/sample_memo.hpp):
// a whole frame's samples at 1280x720 2x2 are ~170 MB, at 3840x2160 4x4 ~5 GB.

#include <cstddef>
#include <optional>
#include <string>

#include "render/render_settings.hpp"

namespace lc::farm {

// Why a process, one of `sharers` rendering on this node, should not keep a
// memo for frames of `rs` (it would take more than a quarter of the node's
// physical memory divided among them), or nullopt when it may.
std::optional<std::string> memo_refusal(const RenderSettings& rs, int sharers);

}  // namespace lc::farm

#pragma once
// The star pass's constants (stars/star_pass.hpp; docs/stars.md, "How a
// frame draws them"), in one place: how its work is cut into tiles, when a
// tile or a patch is searched which way, and what is too faint to draw.

#include <cstddef>

#include "core/constants.hpp"

namespace lc {

// Tiles of tile x tile quads are searched together (one lookup in the star
// bins per tile, stars/star_search.hpp); rows of tiles are the pass's units
// of parallel work, and bands of this many pixel rows those of adding the
// light to the image (stars/pixel_light.hpp).
constexpr int star_tile = 16;

// A block of a tile's quads whose cap holds more stars than this is
// searched as four.
constexpr std::size_t star_block_split_above = 16;

// A tile whose nodes lie within this of their centre (rad) is searched in
// its tangent plane (a gnomonic projection stretches 1 / cos^2: 1.3 here).
constexpr double plane_tile_radius = 30.0 * degree;

// A patch wider than this (centre to corner, rad) is searched alone: about
// a bin of the star field (stars/star_field.cpp).
constexpr double wide_patch_radius = 1.0 * degree;

// Images fainter than this share of the faintest star's light are not
// drawn, and a glare's halo stops under this share of it on one pixel:
// 7.5 magnitudes under the faintest star the sky holds.
constexpr double invisible_share = 1e-3;

}  // namespace lc

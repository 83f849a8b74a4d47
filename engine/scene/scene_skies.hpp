#pragma once
// Every sky of a scene, each with the name of the end it is at: the one
// place what keys, writes, checks or reads a scene's skies lists them
// (the still key, the frame JSON, the shutter's check, the input hash's
// sky files), so a sky at a further end — a wormhole's other side — is
// never left out of one of them.

#include <string_view>

#include "scene/scene_spec.hpp"

namespace lc {

// f(end, sky) for the scene's `sky` (end: empty, the spacetime's first end
// and every end without a sky of its own), then for each of its `skies`
// (end: that end's name), in order.
template <class F>
void for_each_sky(const SceneSpec& fs, F&& f) {
  f(std::string_view{}, fs.sky);
  for (const EndSky& e : fs.end_skies) f(std::string_view(e.name), e.sky);
}

}  // namespace lc

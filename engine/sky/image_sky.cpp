#include "sky/image_sky.hpp"

#include "render/shot_resources.hpp"

namespace lc {

// The image is loaded once per shot (ShotResources).
ImageSky::ImageSky(const Params& p, ShotResources& res) : rotate_(p.rotate), texture_(res.texture(p.file)) {}

}  // namespace lc

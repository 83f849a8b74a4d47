#include "sky/image_sky.hpp"

#include "assets/shot_resources.hpp"

namespace lc {

// The image is loaded once per shot (ShotResources).
ImageSky::ImageSky(const Params& p, ShotResources& res) : TextureSky(p.rotate, p.brightness, res.texture(p.file)) {}

}  // namespace lc

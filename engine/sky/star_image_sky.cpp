#include "sky/star_image_sky.hpp"

#include "assets/shot_resources.hpp"

namespace lc {

// The field is made once per shot, seed and size (ShotResources).
StarImageSky::StarImageSky(const Params& p, ShotResources& res)
    : TextureSky(p.rotate, p.brightness, res.starfield(p.seed, p.resolution)) {}

}  // namespace lc

#include "render/point_star_stage.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "stars/star_pass.hpp"
#include "stars/star_streaks.hpp"

namespace lc {

namespace {

// Black where the camera has no ray through any part of a pixel (its
// centre and its four corners: a fisheye's pixels wholly outside its
// disc): the star stage's glare may spill there, but a dome shows nothing
// outside its disc.  The traced colour there is black already (no sample
// had a ray), so only star light is removed.
void black_outside_rays(const Camera& camera, FrameImage& image) {
  for (int j = 0; j < image.height; ++j)
    for (int i = 0; i < image.width; ++i) {
      if (camera.ray({i + 0.5, j + 0.5, 0.0})) continue;
      bool any = false;
      for (int c = 0; c < 4 && !any; ++c) any = camera.ray({i + (c & 1) * 1.0, j + (c >> 1) * 1.0, 0.0}).has_value();
      if (any) continue;
      const std::size_t p = 3 * (static_cast<std::size_t>(j) * image.width + i);
      image.rgb[p] = image.rgb[p + 1] = image.rgb[p + 2] = 0.0f;
    }
}

}  // namespace

long draw_point_stars(const PointStars& stars, const Camera& camera, std::span<const SkyPoint> rays,
                      FrameImage& image, int threads, double* cpu_seconds) {
  StarPassOptions options;
  options.threads = threads;
  options.wrap = camera.wrap();
  options.glare = stars.glare;
  const auto directions = [&](double x, double y) { return unit3(camera.direction(x, y)); };
  const std::vector<EyePicture> pictures = camera.pictures();
  long drawn = 0;
  if (pictures.size() == 1) {
    options.glare_radius = stars.glare_size * camera.frame_height();
    drawn = add_point_stars(rays, image.width, image.height, *stars.field, directions, options, image.rgb, cpu_seconds);
  } else {
    // A stereo frame: each eye's picture is a frame of its own to the
    // pass (its edges, its wrap), drawn on a copy of its pixels.
    for (const EyePicture& p : pictures) {
      const std::size_t w = static_cast<std::size_t>(p.width), n = w * static_cast<std::size_t>(p.height);
      std::vector<SkyPoint> sky(n);
      std::vector<float> rgb(3 * n);
      auto pixel = [&](std::size_t i, std::size_t j) {
        return (static_cast<std::size_t>(p.y0) + j) * static_cast<std::size_t>(image.width) + p.x0 + i;
      };
      for (std::size_t j = 0; j < static_cast<std::size_t>(p.height); ++j)
        for (std::size_t i = 0; i < w; ++i) {
          sky[j * w + i] = rays[pixel(i, j)];
          for (int c = 0; c < 3; ++c) rgb[3 * (j * w + i) + c] = image.rgb[3 * pixel(i, j) + c];
        }
      options.glare_radius = stars.glare_size * p.height;
      drawn += add_point_stars(sky, p.width, p.height, *stars.field, directions, options, rgb, cpu_seconds);
      for (std::size_t j = 0; j < static_cast<std::size_t>(p.height); ++j)
        for (std::size_t i = 0; i < w; ++i)
          for (int c = 0; c < 3; ++c) image.rgb[3 * pixel(i, j) + c] = rgb[3 * (j * w + i) + c];
    }
  }
  if (!camera.rays_everywhere()) black_outside_rays(camera, image);
  return drawn;
}

namespace {

// One instant's stars in one picture of the frame (the frame, or a stereo
// eye's half), ready for the star pass: its rays copied out of the instant's
// plane, the pass's options and the camera's directions.
struct InstantPicture {
  std::vector<SkyPoint> sky;
  StarPassOptions options;
  CameraDirections directions;
};

// Instant `at`'s rays of picture `p` of a frame `frame_width` wide (`plane`:
// the instant's sky points, one per pixel), with the options its camera and
// sky give the pass.
InstantPicture instant_picture(const InstantStars& at, const EyePicture& p, std::span<const SkyPoint> plane,
                               int frame_width, bool whole_frame, int threads) {
  InstantPicture picture;
  picture.options.threads = threads;
  picture.options.wrap = at.camera->wrap();
  picture.options.glare = at.stars->glare;
  picture.options.glare_radius = at.stars->glare_size * (whole_frame ? at.camera->frame_height() : p.height);
  const Camera* camera = at.camera;
  picture.directions = [camera](double x, double y) { return unit3(camera->direction(x, y)); };
  picture.sky.resize(static_cast<std::size_t>(p.width) * static_cast<std::size_t>(p.height));
  for (int j = 0; j < p.height; ++j)
    for (int i = 0; i < p.width; ++i)
      picture.sky[static_cast<std::size_t>(j) * p.width + i] =
          plane[static_cast<std::size_t>(p.y0 + j) * static_cast<std::size_t>(frame_width) + p.x0 + i];
  return picture;
}

}  // namespace

long draw_point_stars(std::span<const InstantStars> instants, std::span<const SkyPoint> rays, FrameImage& image,
                      int threads, double* cpu_seconds) {
  // Inputs: the instants' stars and cameras (one picture layout: a change of
  // camera kind or stereo layout within a shutter is refused before here),
  // a plane of sky points per instant; output: the stars' light, each
  // instant's 1/K of it, drawn along the streaks the images of consecutive
  // instants make (stars/star_streaks.hpp).
  const std::size_t n = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height);
  if (instants.empty() || rays.size() != n * instants.size())
    throw std::logic_error(fmt::format("the star stage got {} sky points for {} instants of {} pixels", rays.size(),
                                       instants.size(), n));
  const std::vector<EyePicture> pictures = instants.front().camera->pictures();
  const bool whole_frame = pictures.size() == 1;
  const std::vector<EyePicture> parts =
      whole_frame ? std::vector<EyePicture>{{0, 0, 0, image.width, image.height}} : pictures;
  // Streaks join the images of one star field's stars: with each instant's
  // own field (none today: a sky may not change within a shutter) they are
  // dots, as before.
  bool one_field = true;
  for (const InstantStars& at : instants) {
    const std::vector<EyePicture> own = at.camera->pictures();
    const auto same = [](const EyePicture& a, const EyePicture& b) {
      return a.eye == b.eye && a.x0 == b.x0 && a.y0 == b.y0 && a.width == b.width && a.height == b.height;
    };
    if (!std::equal(own.begin(), own.end(), pictures.begin(), pictures.end(), same))
      throw std::logic_error("the star stage got instants whose cameras split the frame differently");
    one_field = one_field && at.stars->field == instants.front().stars->field;
  }
  // Each picture's images at every instant, then their paths.
  std::vector<std::vector<InstantPicture>> at(parts.size());
  std::vector<std::vector<std::vector<FoundStarImage>>> found(parts.size());
  std::vector<std::vector<std::vector<StreakPath>>> paths(parts.size());
  long drawn = 0;
  for (std::size_t q = 0; q < parts.size(); ++q) {
    for (std::size_t k = 0; k < instants.size(); ++k) {
      at[q].push_back(instant_picture(instants[k], parts[q], rays.subspan(k * n, n), image.width, whole_frame, threads));
      found[q].push_back(find_star_images(at[q][k].sky, parts[q].width, parts[q].height, *instants[k].stars->field,
                                          at[q][k].directions, at[q][k].options, cpu_seconds));
      drawn += static_cast<long>(found[q][k].size());
    }
    paths[q] = one_field ? star_streaks(found[q], parts[q].width, parts[q].height, at[q].front().options.wrap)
                         : std::vector<std::vector<StreakPath>>(instants.size());
  }
  // Each instant's light on a frame of its own, outside its camera's rays
  // removed, then added with weight 1/K.
  const float weight = 1.0f / static_cast<float>(instants.size());
  FrameImage stars_only{image.width, image.height, {}, {}, {}, {}};
  for (std::size_t k = 0; k < instants.size(); ++k) {
    stars_only.rgb.assign(3 * n, 0.0f);
    for (std::size_t q = 0; q < parts.size(); ++q) {
      const EyePicture& p = parts[q];
      std::vector<float> rgb(3 * static_cast<std::size_t>(p.width) * static_cast<std::size_t>(p.height), 0.0f);
      draw_star_images(found[q][k], paths[q][k], p.width, p.height, *instants[k].stars->field, at[q][k].directions,
                       at[q][k].options, rgb, cpu_seconds);
      for (int j = 0; j < p.height; ++j)
        std::copy_n(&rgb[3 * static_cast<std::size_t>(j) * p.width], 3 * p.width,
                    &stars_only.rgb[3 * ((static_cast<std::size_t>(p.y0 + j)) * image.width + p.x0)]);
    }
    if (!instants[k].camera->rays_everywhere()) black_outside_rays(*instants[k].camera, stars_only);
    for (std::size_t v = 0; v < 3 * n; ++v) image.rgb[v] += weight * stars_only.rgb[v];
  }
  return drawn;
}

}  // namespace lc

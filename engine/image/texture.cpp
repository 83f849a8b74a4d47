#include "image/texture.hpp"

#include <stdexcept>
#include <string>
#include <utility>

#include "image/frame_image.hpp"
#include "image/read_linear.hpp"

namespace lc {

// Everything format- and colour-related is the shared reader's job.
Texture Texture::load(const std::filesystem::path& path, long max_pixels) {
  FrameImage image = detail::read_linear_rgb(path, "cannot load texture", max_pixels);
  return Texture(image.width, image.height, std::move(image.rgb));
}

// Checks what sample() relies on: a non-empty image and a full buffer.
Texture Texture::from_pixels(int width, int height, std::vector<float> rgb) {
  if (width <= 0 || height <= 0 || width > max_image_side || height > max_image_side)
    throw std::invalid_argument("Texture::from_pixels: bad size " + std::to_string(width) + " x " +
                                std::to_string(height));
  if (rgb.size() != 3 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height))
    throw std::invalid_argument("Texture::from_pixels: " + std::to_string(rgb.size()) + " floats for a " +
                                std::to_string(width) + " x " + std::to_string(height) + " RGB image");
  return Texture(width, height, std::move(rgb));
}

}  // namespace lc

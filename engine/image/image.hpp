#pragma once
// The image layer in one include: frames (FrameImage) and their files
// (EXR, PNG), sky textures, and the procedural star field.  OpenImageIO
// stays behind these headers; none of them includes it.

#include "image/frame_image.hpp"
#include "image/image_io.hpp"
#include "image/srgb.hpp"
#include "image/generated_stars.hpp"
#include "image/texture.hpp"

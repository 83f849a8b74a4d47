#pragma once
// What a video player must be told to show a camera's frames as they were
// made: as a flat picture or as the inside of a sphere (a whole sphere's
// equirectangular frame: a 360-degree video), and where each eye's picture
// is in a stereo frame.  The camera knows it (camera/camera.hpp); the frame
// store records it in each EXR's header; `lightcone encode` reads it back
// and writes it into the video's container (Google's spherical video V2
// boxes in MP4, Matroska's projection and stereo elements: docs/cameras.md).

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "image/image_io.hpp"

namespace lc {

enum class VideoProjection { flat, equirectangular };
enum class StereoLayout { mono, top_bottom, side_by_side };  // the left eye on top, or on the left
// Its names in a shot (a camera's `stereo` field) and in an EXR header.
constexpr std::array<std::string_view, 3> choice_names(StereoLayout) { return {"mono", "top-bottom", "side-by-side"}; }

struct VideoLayout {
  VideoProjection projection = VideoProjection::flat;
  StereoLayout stereo = StereoLayout::mono;
  bool operator==(const VideoLayout&) const = default;
};

// The EXR header attributes that carry a layout, each written only when it
// is not the default (a flat mono frame's header has neither).
inline constexpr std::string_view projection_attribute = "lightcone/projection";
inline constexpr std::string_view stereo_attribute = "lightcone/stereo";

inline std::string_view name_of(VideoProjection p) { return p == VideoProjection::equirectangular ? "equirectangular" : "flat"; }
inline std::string_view name_of(StereoLayout s) { return choice_names(s)[static_cast<std::size_t>(s)]; }

// The header attributes of `layout`.
inline ImageMetadata layout_metadata(const VideoLayout& layout) {
  ImageMetadata m;
  if (layout.projection != VideoProjection::flat)
    m.emplace_back(std::string(projection_attribute), std::string(name_of(layout.projection)));
  if (layout.stereo != StereoLayout::mono) m.emplace_back(std::string(stereo_attribute), std::string(name_of(layout.stereo)));
  return m;
}

// The layout a header records (the defaults where it says nothing);
// nullopt when it names a projection or stereo layout this lightcone does
// not know (a newer one wrote it).
inline std::optional<VideoLayout> layout_from(const ImageMetadata& metadata) {
  VideoLayout layout;
  for (const auto& [key, value] : metadata) {
    if (key == projection_attribute) {
      if (value == name_of(VideoProjection::equirectangular))
        layout.projection = VideoProjection::equirectangular;
      else if (value != name_of(VideoProjection::flat))
        return std::nullopt;
    } else if (key == stereo_attribute) {
      if (value == name_of(StereoLayout::top_bottom))
        layout.stereo = StereoLayout::top_bottom;
      else if (value == name_of(StereoLayout::side_by_side))
        layout.stereo = StereoLayout::side_by_side;
      else if (value != name_of(StereoLayout::mono))
        return std::nullopt;
    }
  }
  return layout;
}

}  // namespace lc

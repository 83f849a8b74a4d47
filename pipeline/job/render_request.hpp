#pragma once
// What a render is asked for: the flags of `lightcone render` (docs/cli.md)
// as they arrive, before the shot is read.  The job (job/render_job.hpp)
// derives everything else from it and the shot; the showcase builds one per
// shot.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "image/image_io.hpp"
#include "job/delivery_flags.hpp"

namespace lc {

struct RenderRequest {
  std::filesystem::path shot;
  std::filesystem::path out;
  std::optional<std::string> frames;  // "A", "A:B" or "A:B:STEP"
  std::vector<int> frame_list;        // the frames themselves, ascending (the showcase's picks); overrides `frames`
  std::optional<std::string> size;    // "WxH"
  std::optional<std::string> region;  // "X0,Y0,X1,Y1": a window of the frame (of --size's, or the shot's)
  DeliveryFlags delivery;             // --camera, --dome-tilt, --dome-elevation, --separation, --sky
  double scale = 1.0;
  std::optional<int> supersample;
  bool layers = false;
  bool full_supersample = false;      // every sample of the N x N grid, not adaptively
  bool no_reuse = false;              // trace every sample, none kept from earlier frames of a still scene
  int threads = 0;                    // 0: every core (under MPI: the node's share)
  std::optional<int> stripes;         // working sets per frame (default: farm::default_stripes)
  int preview = 0;                    // k >= 2: every k-th stripe of every frame first
  bool force = false;                 // re-render frames made from other settings or inputs
  int png_bits = 8;                   // --png-depth: 8 or 16 (CLI11 zeroes an enum option not given)
  PngDepth png_depth() const { return png_bits == 16 ? PngDepth::sixteen : PngDepth::eight; }
  double progress = 5.0;              // seconds between plain progress lines (0: none)
  // The shutter over the shot's (docs/motion_blur.md): --shutter,
  // --shutter-position, --time-samples.
  std::optional<double> shutter;
  std::optional<std::string> shutter_position;
  std::optional<int> time_samples;
};

}  // namespace lc

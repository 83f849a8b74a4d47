#pragma once
// `lightcone showcase [--quality preview|production] [--out DIR]`: the
// paper's film in one command — renders the three sequences with the farm
// (threads, or master and workers under mpirun), encodes each to MP4 with a
// contact sheet, and joins them behind title cards into DIR/showcase.mp4.
// Run again, it resumes: finished frames are kept, videos newer than their
// frames are kept (docs/showcase.md).

#include <filesystem>
#include <optional>
#include <string>

namespace lc {

struct ShowcaseCommand {
  std::string quality = "preview";
  std::optional<std::string> size;             // WxH instead of the quality's
  std::optional<double> rate;                  // preview: frames per second of story
  std::optional<std::filesystem::path> out;    // default out/showcase/<quality>
  std::optional<std::filesystem::path> shots;  // default: the project's shots/
  int threads = 0;                             // as render --threads
  bool force = false;                          // as render --force
  bool thermal = false;                        // the fourth sequence too
  std::string camera = "shot";                 // --camera: shot, dome or 360
  int png_bits = 8;                            // as render --png-depth
  bool motion_blur = false;                    // --motion-blur: every shot's shutter at 0.5 (docs/motion_blur.md)
  double progress = 5.0;                       // as render --progress
};

int run_showcase(const ShowcaseCommand& cmd);

}  // namespace lc

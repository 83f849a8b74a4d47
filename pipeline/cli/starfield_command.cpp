#include "starfield_command.hpp"

#include <stdexcept>

#include <fmt/format.h>

#include "command_output.hpp"
#include "store/durable_file.hpp"
#include "image/image.hpp"

namespace lc {

int run_starfield(const StarfieldCommand& cmd) {
  // PNG only: the sky texture's exact 8-bit codes (a JPEG would change them;
  // writing PNG bytes under another format's name misled every viewer).
  require_extension(cmd.output, ".png", "the star field is written as an 8-bit sRGB PNG");
  if (cmd.width < 64 || cmd.width > 16384 || cmd.width % 2 != 0)
    throw std::invalid_argument(fmt::format("--width {}: must be even, between 64 and 16384", cmd.width));
  DurableFile out(cmd.output);
  // Written by the image layer, whose errors then name the final file.
  write_png(out.library_path(), render_starfield(cmd.width, cmd.width / 2, cmd.seed), out.final_path());
  out.commit();
  fmt::print(stderr, "starfield: {}x{} (seed {}) -> {}\n", cmd.width, cmd.width / 2, cmd.seed, cmd.output.string());
  return 0;
}

}  // namespace lc

#pragma once
// `lightcone develop DIR [--shot NAME] [--frames A:B:S] [--exposure S]
// [--exposure-shift S] [--view V] [--white-balance K] [--saturation S]
// [--bloom B] [--bloom-radius R] [--reset] [--out DIR2] [--threads N]`: a rendered shot's PNGs
// made again from its EXRs through another look, without tracing a ray
// (docs/light.md, "Develop without re-tracing").  Each frame starts from
// the look its journal line records (the one its PNG was made with); the
// flags replace parts of it, and --exposure-shift sets its exposure to the
// render's own plus the shift (never the last develop's plus the shift: a
// develop run again, after a stop part way or not, gives the same frames);
// the PNG is replaced atomically and a journal line records the new look,
// so `encode` and the contact sheet take the developed frames as the
// render's own.  --reset starts each frame from the render's own look
// instead; --out writes the PNGs into another folder and changes nothing
// of DIR's, so two looks can sit side by side.

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "image/look.hpp"

namespace lc {

struct DevelopCommand {
  std::filesystem::path dir;
  std::optional<std::string> shot;            // which shot's frames when DIR holds several
  std::optional<std::string> frames;          // A, A:B or A:B:STEP; default every finished frame
  std::map<std::string, std::string> look;    // a look field of the shot's (look_flags) -> its flag's text
  std::optional<double> exposure_shift;       // stops added to the exposure each frame was rendered with
  bool reset = false;                         // start from the render's own look, not the last develop's
  std::optional<std::filesystem::path> out;   // write the PNGs here instead of into `dir`
  int threads = 0;                            // 0: every core
};

// The look's fields as develop's flags, from the shot's field declarations
// (scene/shot_info.hpp): the field's name ("white_balance"), the flag
// ("--white-balance") and its help (the field's documentation and range).
struct LookFlag {
  std::string field, flag, help;
};
std::vector<LookFlag> look_flags();

// A frame's look after a develop.  Inputs: `current`, the look its PNG
// shows now; `rendered`, the one the render made it with (the same unless
// a develop changed it); the look flags; the exposure shift.  Output:
// `current` with the flags' values in place of its own, and with an
// exposure shift its exposure set to the flag's (--exposure) or else the
// render's, plus the shift: fixed points, so that running a develop again
// changes nothing.  Throws std::invalid_argument naming the flag when a
// value is not one the shot's field takes.
Look developed_look(const Look& current, const Look& rendered, const std::map<std::string, std::string>& flags,
                    std::optional<double> exposure_shift);

int run_develop(const DevelopCommand& cmd);

}  // namespace lc

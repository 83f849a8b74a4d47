#include "contact_sheet_command.hpp"

#include <stdexcept>

#include <fmt/format.h>

#include "command_output.hpp"
#include "store/frame_files.hpp"
#include "video/contact_sheet.hpp"
#include "store/frame_sequence.hpp"

namespace lc {

int run_contact_sheet(const ContactSheetCommand& cmd) {
  // Input: the parsed flags; output: the sheet, and a summary on stderr.
  // Holes in the sequence are allowed here (a sheet is for looking at
  // whatever exists); the labels show which frames are there.  Frames of
  // another version of the shot are not (a sheet would show a film that
  // never was), unless --allow-stale.
  require_extension(cmd.output, ".png", "a contact sheet is a PNG");
  const FrameSequence seq = select_frame_sequence(cmd.dir, cmd.shot);
  farm::check_frames_current(cmd.dir, seq.shot, seq.frames, cmd.allow_stale, "contact-sheet");
  const ContactSheetOptions o{cmd.columns, cmd.width, cmd.count};
  write_contact_sheet(seq, o, cmd.output);
  const std::size_t shown = pick_evenly(seq.files.size(), static_cast<std::size_t>(cmd.count)).size();
  fmt::print(stderr, "contact-sheet: shot {}, {} of {} frames ({}-{}) -> {}\n", seq.shot, shown, seq.files.size(),
             seq.frames.front(), seq.frames.back(), cmd.output.string());
  return 0;
}

}  // namespace lc

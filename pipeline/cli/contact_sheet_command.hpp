#pragma once
// `lightcone contact-sheet DIR -o SHEET.png [--columns N] [--width W]
// [--count N] [--shot NAME]`: a PNG grid of frames picked evenly across one
// shot's sequence, each labelled with its frame number
// (video/contact_sheet.hpp does the work).

#include <filesystem>
#include <optional>
#include <string>

namespace lc {

struct ContactSheetCommand {
  std::filesystem::path dir;
  std::filesystem::path output;
  int columns = 4;
  int width = 1280;
  int count = 16;
  std::optional<std::string> shot;
  bool allow_stale = false;  // show frames of other versions of the shot than the latest render's
};

int run_contact_sheet(const ContactSheetCommand& cmd);

}  // namespace lc

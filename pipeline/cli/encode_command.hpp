#pragma once
// `lightcone encode`: frames to video, three ways —
//   lightcone encode DIR -o FILE.mp4 [--fps F] [--crf Q] [--codec C] [--preset P] [--shot NAME]
//   lightcone encode --concat A.mp4 B.mp4 ... -o ALL.mp4
//   lightcone encode --title TEXT [--title TEXT ...] --size WxH [--seconds S] -o CARD.mp4
// The work is in pipeline/video/ (encode_sequence, concat_videos,
// encode_title_card), which the showcase calls directly.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace lc {

struct EncodeCommand {
  std::vector<std::filesystem::path> inputs;  // DIR; or the videos to join with --concat
  std::filesystem::path output;
  std::optional<std::string> fps;       // "30", "29.97", "30000/1001"; default: the frames' "lightcone/fps" EXR attribute, else 30
  std::optional<int> crf;               // default per codec
  std::optional<std::string> codec;     // default h264
  std::optional<std::string> preset;    // default per codec
  std::optional<std::string> shot;      // which shot's frames when DIR holds several
  bool allow_stale = false;             // encode frames of other versions of the shot than the latest render's
  bool concat = false;
  std::vector<std::string> title;       // --title lines: encode a title card
  std::optional<std::string> size;      // --size WxH of the title card
  std::optional<double> seconds;        // --seconds: title card length (default 3)
};

int run_encode(const EncodeCommand& cmd);

}  // namespace lc

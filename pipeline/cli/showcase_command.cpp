#include "showcase_command.hpp"

#include <chrono>
#include <cmath>
#include <exception>
#include <stdexcept>

#include <fmt/format.h>

#include "store/frame_files.hpp"
#include "transport/mpi_session.hpp"
#include "interrupt.hpp"
#include "render_command.hpp"
#include "script/script_paths.hpp"
#include "job/showcase_plan.hpp"
#include "video/concat_videos.hpp"
#include "video/contact_sheet.hpp"
#include "video/encode_sequence.hpp"
#include "store/frame_sequence.hpp"
#include "cli/progress_printer.hpp"
#include "video/title_card.hpp"

namespace lc {

namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;

// Where everything goes under the output directory.
struct ShowcaseLayout {
  fs::path root;
  fs::path frames(const std::string& shot) const { return root / "frames" / shot; }
  fs::path video(const std::string& shot) const { return root / (shot + ".mp4"); }
  fs::path sheet(const std::string& shot) const { return root / (shot + ".sheet.png"); }
  fs::path card(const std::string& name) const { return root / "cards" / (name + ".mp4"); }
  fs::path film() const { return root / "showcase.mp4"; }
};

// True when `out` exists and is at least as new as every input: a resumed
// showcase keeps what an interrupted one finished.
bool up_to_date(const fs::path& out, const std::vector<fs::path>& inputs) {
  std::error_code ec;
  const auto made = fs::last_write_time(out, ec);
  if (ec) return false;
  for (const fs::path& in : inputs) {
    const auto t = fs::last_write_time(in, ec);
    if (ec || t > made) return false;
  }
  return true;
}

// The frames of one planned sequence, as files the renderer left.
FrameSequence rendered_frames(const SequencePlan& s, const ShowcaseLayout& layout) {
  FrameSequence seq;
  seq.shot = s.name;
  seq.frames = s.frames;
  for (int i : s.frames) seq.files.push_back(farm::frame_path(layout.frames(s.name), s.name, i, "png"));
  return seq;
}

// The shutter of `showcase --motion-blur`: the film camera's 180 degrees.
constexpr double showcase_shutter = 0.5;

// Renders every sequence on every rank.  Returns 0 when all went well, else
// the exit status of an interrupted render (128 + the signal; the master
// has said what it kept), or -1 on a worker whose master failed (it has
// nothing more to do); the master throws the first failure.
int render_all(const ShowcasePlan& plan, const ShowcaseLayout& layout, const ShowcaseCommand& cmd,
               const farm::MpiSession& mpi) {
  const bool master = mpi.rank() == 0;
  for (std::size_t k = 0; k < plan.sequences.size(); ++k) {
    const SequencePlan& s = plan.sequences[k];
    RenderRequest rc;
    rc.shot = s.shot;
    rc.out = layout.frames(s.name);
    rc.frame_list = s.frames;
    rc.size = s.size;
    rc.supersample = s.supersample;
    rc.layers = s.layers;
    rc.threads = cmd.threads;
    rc.force = cmd.force;
    rc.progress = cmd.progress;
    rc.delivery.camera = std::string(name_of(plan.camera));
    rc.png_bits = cmd.png_bits;
    if (cmd.motion_blur) rc.shutter = showcase_shutter;
    if (master)
      fmt::print(stderr, "showcase: [{}/{}] rendering {}: {} of its {} frames\n", k + 1, plan.sequences.size(), s.name,
                 s.frames.size(), s.shot_frames);
    std::exception_ptr failure;
    int status = 0;
    try {
      status = render_in_session(rc, mpi);
    } catch (...) {
      failure = std::current_exception();
    }
    // Workers learn whether the master is going on to the next sequence.
    const bool go_on = mpi.broadcast_from_master(failure == nullptr && status == 0);
    if (master && failure) std::rethrow_exception(failure);
    if (status != 0) return status;
    if (!go_on) return -1;
    if (failure) std::rethrow_exception(failure);  // a worker's own failure after the master succeeded
  }
  return 0;
}

// The card's lines, or as many of the first as fit a small frame (a tiny
// test film): at worst a blank card, so the film keeps its rhythm.
std::vector<std::string> card_lines_that_fit(const std::vector<std::string>& lines, int width, int height,
                                             CardShape shape) {
  for (std::size_t n = lines.size(); n > 0; --n) {
    std::vector<std::string> first(lines.begin(), lines.begin() + static_cast<std::ptrdiff_t>(n));
    try {
      title_card(width, height, first, shape);
      return first;
    } catch (const std::invalid_argument&) {
    }
  }
  return {" "};
}

// "1.2 MB" for the summary.
std::string size_text(const fs::path& p) {
  std::error_code ec;
  const double b = static_cast<double>(fs::file_size(p, ec));
  return ec ? "?" : fmt::format("{:.1f} MB", b / 1e6);
}

// Encodes the sequences, their cards and sheets, and joins the film (the
// master only, after every frame is stored).
void encode_all(const ShowcasePlan& plan, const ShowcaseLayout& layout, const InterruptGuard& guard) {
  EncodeOptions o;
  o.fps = frame_rate_near(plan.fps);
  // The videos, sheets and cards are the showcase folder's own files: a link
  // planted under one of their names is replaced, never written through.
  o.output_name = FinalName::own;
  // At least 4 frames: H.264's B-frames make a clip's decode times start up
  // to 2 frames before 0, and they must not reach back into the previous clip.
  const int card_frames = std::max(4, static_cast<int>(std::lround(title_seconds * plan.fps)));
  fs::create_directories(layout.card("x").parent_path());
  std::vector<fs::path> film;
  // A dome's cards are drawn where a dome shows them, inside the disc.
  const CardShape shape = plan.camera == DeliveryCamera::dome ? CardShape::dome : CardShape::flat;
  auto card = [&](const std::string& name, const std::vector<std::string>& lines) {
    const fs::path out = layout.card(name);
    const std::vector<std::string> shown = card_lines_that_fit(lines, plan.width, plan.height, shape);
    if (shown.size() < lines.size() || shown == std::vector<std::string>{" "})
      fmt::print(stderr, "showcase: the {} card's text does not fit a {}x{} frame even broken between words; {} (a larger --size "
                 "shows it all)\n",
                 name, plan.width, plan.height,
                 shown == std::vector<std::string>{" "} ? "the card is blank"
                                                        : fmt::format("it shows the first {} of its {} lines",
                                                                      shown.size(), lines.size()));
    encode_title_card(shown, plan.width, plan.height, card_frames, o, out, progress_printer(guard, "showcase", "frames"),
                      shape);
    film.push_back(out);
  };
  card("opening", plan.opening);
  for (const SequencePlan& s : plan.sequences) {
    const FrameSequence seq = rendered_frames(s, layout);
    const fs::path video = layout.video(s.name);
    if (up_to_date(video, seq.files)) {
      fmt::print(stderr, "showcase: {} is newer than its frames; kept\n", video.string());
    } else {
      fmt::print(stderr, "showcase: encoding {} frames of {} at {:g} fps -> {}\n", seq.files.size(), s.name, plan.fps,
                 video.string());
      // A 360-degree sequence's video is marked as one, as the film is.
      EncodeOptions marked = o;
      if (plan.camera == DeliveryCamera::sphere) marked.layout.projection = VideoProjection::equirectangular;
      encode_sequence(seq.files, marked, video, progress_printer(guard, "showcase", "frames"));
    }
    // Thumbnails no larger than the frames.
    const ContactSheetOptions sheet{4, 4 * std::min(plan.width, 320), 16, FinalName::own};
    if (!up_to_date(layout.sheet(s.name), seq.files)) write_contact_sheet(seq, sheet, layout.sheet(s.name));
    card(s.name, s.title);
    film.push_back(video);
  }
  fmt::print(stderr, "showcase: joining {} clips -> {}\n", film.size(), layout.film().string());
  // A 360-degree film is marked for players as a whole (its cards are
  // seen on the sphere's front); a dome's is a flat square preview.
  VideoLayout film_layout;
  if (plan.camera == DeliveryCamera::sphere) film_layout.projection = VideoProjection::equirectangular;
  const ConcatResult r =
      concat_videos(film, layout.film(), progress_printer(guard, "showcase", "clips"), film_layout, FinalName::own);
  fmt::print(stderr, "showcase: {}: {} frames {}x{}, {:.1f} s at {:g} fps ({})\n", layout.film().string(), r.frames,
             r.width, r.height, r.seconds, plan.fps, size_text(layout.film()));
}

}  // namespace

int run_showcase(const ShowcaseCommand& cmd) {
  const Clock::time_point start = Clock::now();
  ShowcaseSettings settings{parse_showcase_quality(cmd.quality), cmd.size, cmd.rate, cmd.thermal};
  if (const auto camera = delivery_named(cmd.camera)) settings.camera = *camera;
  // Each camera's film in a folder of its own (a dome's frames are not
  // the flat film's: a shared folder would refuse to resume).
  // A blurred film's too.
  const std::string folder = (settings.camera == DeliveryCamera::shot ? cmd.quality : cmd.quality + "-" + cmd.camera) +
                             (cmd.motion_blur ? "-blur" : "");
  const ShowcaseLayout layout{cmd.out.value_or(fs::path("out") / "showcase" / folder)};
  const fs::path shots = cmd.shots.value_or(library_dir().parent_path() / "shots");
  farm::MpiSession mpi;
  const bool master = mpi.rank() == 0;
  // Every rank plans alike from the same scripts (each needs the frames).
  const ShowcasePlan plan = plan_showcase(settings, shots);
  if (master) {
    std::size_t frames = 0;
    for (const SequencePlan& s : plan.sequences) frames += s.frames.size();
    fmt::print(stderr, "showcase: {} quality: {} sequences, {} frames at {}, {:g} fps -> {}\n", cmd.quality,
               plan.sequences.size(), frames, fmt::format("{}x{}", plan.width, plan.height), plan.fps,
               layout.root.string());
  }
  // One guard for the whole film: a Ctrl-C while rendering stops the
  // render as `render` does (frames kept), while encoding between frames.
  InterruptGuard interrupts;
  const int rendered = render_all(plan, layout, cmd, mpi);
  if (rendered > 0) {
    if (master) fmt::print(stderr, "showcase: stopped; the same command resumes\n");
    return rendered;
  }
  if (rendered < 0 || !master) return 0;
  try {
    encode_all(plan, layout, interrupts);
  } catch (const Interrupted& e) {
    fmt::print(stderr, "showcase: {}; the frames are kept, the same command resumes\n", e.what());
    return 128 + e.signal;
  }
  const double minutes = std::chrono::duration<double>(Clock::now() - start).count() / 60;
  fmt::print(stderr, "showcase: done in {:.1f} min: {} (and per sequence: <shot>.mp4, <shot>.sheet.png) in {}\n", minutes,
             layout.film().filename().string(), layout.root.string());
  return 0;
}

}  // namespace lc

#include "develop_command.hpp"

#include <algorithm>
#include <atomic>

#include <malloc.h>
#include <charconv>
#include <memory>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <thread>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/cpu_time.hpp"
#include "core/parallel_for.hpp"
#include "store/dir_lock.hpp"
#include "store/frame_files.hpp"
#include "store/frame_store.hpp"
#include "transport/threads.hpp"
#include "job/frame_range.hpp"
#include "interrupt.hpp"
#include "scene/shot_info.hpp"
#include "cli/progress_printer.hpp"

namespace lc {

namespace fs = std::filesystem;

namespace {

// Whether a shot field is one a look is made of (ShotInfo::look).
bool is_look_field(std::string_view name) {
  return std::find(look_field_names.begin(), look_field_names.end(), name) != look_field_names.end();
}

std::string flag_of(std::string_view field) {
  std::string flag = "--" + std::string(field);
  std::replace(flag.begin(), flag.end(), '_', '-');
  return flag;
}

// A look as the shot's fields hold it, and back.
ShotInfo as_fields(const Look& look) {
  ShotInfo s;
  s.exposure = look.exposure;
  s.view = look.view;
  s.white_balance = look.white_balance;
  s.saturation = look.saturation;
  s.bloom = look.bloom;
  s.bloom_radius = look.bloom_radius;
  return s;
}

// Sets field `f` of `s` from a flag's text, checked as a shot's value is.
template <class F>
void set_from_text(ShotInfo& s, const F& f, const std::string& text) {
  using T = typename F::Value;
  const std::string flag = flag_of(f.name);
  if constexpr (Choice<T>) {
    const auto names = choice_names(T{});
    const auto it = std::find(names.begin(), names.end(), text);
    if (it == names.end())
      throw std::invalid_argument(fmt::format("{} {}: must be {}", flag, text, choices_text<T>()));
    s.*(f.member) = static_cast<T>(it - names.begin());
  } else if constexpr (std::is_floating_point_v<T>) {
    double v = 0.0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(v))
      throw std::invalid_argument(fmt::format("{} {}: not a number", flag, text));
    if (!in_range(v, f.lo, f.hi))
      throw std::invalid_argument(fmt::format("{} {}: must be {}{}{}", flag, text, range_text(f.lo, f.hi),
                                              f.unit.empty() ? "" : " ", f.unit));
    s.*(f.member) = v;
  } else {
    throw std::logic_error(fmt::format("{}: a look field develop cannot set", f.name));
  }
}

// The shots of `dir` that a render journalled ("<shot>.journal"), by name.
std::vector<std::string> journalled_shots(const fs::path& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw std::runtime_error(fmt::format("{}: {}", dir.string(), fs::exists(dir, ec) ? "not a directory" : "no such directory"));
  std::vector<std::string> shots;
  for (const auto& e : fs::directory_iterator(dir, ec))
    if (e.path().extension() == ".journal" && e.is_regular_file(ec)) shots.push_back(e.path().stem().string());
  std::sort(shots.begin(), shots.end());
  return shots;
}

std::string pick_shot(const fs::path& dir, const std::optional<std::string>& wanted) {
  const std::vector<std::string> shots = journalled_shots(dir);
  if (shots.empty())
    throw std::runtime_error(fmt::format("{}: no render here (no <shot>.journal): develop makes a rendered shot's PNGs "
                                         "again from the EXRs `lightcone render` wrote",
                                         dir.string()));
  if (wanted) {
    if (std::find(shots.begin(), shots.end(), *wanted) == shots.end())
      throw std::runtime_error(fmt::format("--shot {}: {} holds no render of it; it holds {}", *wanted, dir.string(),
                                           fmt::join(shots, ", ")));
    return *wanted;
  }
  if (shots.size() > 1)
    throw std::runtime_error(
        fmt::format("{} holds the renders of {} shots ({}): name one with --shot", dir.string(), shots.size(), fmt::join(shots, ", ")));
  return shots.front();
}

// "3, 4, 9 and 2 more".
std::string some_of(const std::vector<std::string>& items) {
  if (items.size() <= 4) return fmt::format("{}", fmt::join(items, "; "));
  return fmt::format("{}; ... and {} more", fmt::join(items.begin(), items.begin() + 3, "; "), items.size() - 3);
}

// The frames to develop: the journal's, or those of --frames (each must be
// finished); each with its EXR whole (present, of the size the journal
// records).  Throws naming every frame at fault, before anything is written.
std::vector<int> frames_to_develop(const farm::FrameStore& store, const fs::path& dir, const std::string& shot,
                                   const std::optional<std::string>& range) {
  const auto& journal = store.journal().frames;
  if (journal.empty())
    throw std::runtime_error(fmt::format("{}: the journal of '{}' records no finished frame", dir.string(), shot));
  std::vector<int> frames;
  if (range) {
    frames = parse_frame_range(*range, journal.rbegin()->first + 1, "--frames").frames();
    std::vector<std::string> unfinished;
    for (int f : frames)
      if (!journal.contains(f)) unfinished.push_back(std::to_string(f));
    if (!unfinished.empty())
      throw std::runtime_error(fmt::format("--frames {}: frame{} {} of '{}' {} not finished in {}", *range,
                                           unfinished.size() == 1 ? "" : "s", some_of(unfinished), shot,
                                           unfinished.size() == 1 ? "is" : "are", dir.string()));
  } else {
    for (const auto& [f, line] : journal) frames.push_back(f);
  }
  std::vector<std::string> bad;
  for (int f : frames) {
    const fs::path exr = farm::frame_path(dir, shot, f, "exr");
    std::error_code ec;
    const auto bytes = fs::file_size(exr, ec);
    if (ec)
      bad.push_back(fmt::format("{} is missing", exr.filename().string()));
    else if (bytes != journal.at(f).exr_bytes)
      bad.push_back(fmt::format("{} has {} bytes where the render wrote {} (cut short or replaced)",
                                exr.filename().string(), bytes, journal.at(f).exr_bytes));
  }
  if (!bad.empty())
    throw std::runtime_error(fmt::format("{}: {} of the {} frames cannot be developed: {}. Nothing was changed; render "
                                         "those frames again (the same render command resumes them)",
                                         dir.string(), bad.size(), frames.size(), some_of(bad)));
  return frames;
}

// The number of decimal places in the shortest text that reads back as
// `v` ("-34.2": 1), or -1 where that text is too long to be worth it.
int decimal_places(double v) {
  char text[64];
  const auto [end, ec] = std::to_chars(text, text + sizeof text, v, std::chars_format::fixed);
  if (ec != std::errc()) return -1;
  const std::string_view t(text, static_cast<std::size_t>(end - text));
  const auto dot = t.find('.');
  return dot == std::string_view::npos ? 0 : static_cast<int>(t.size() - dot - 1);
}

// a + b as the decimals written would add: -34.2 + 0.5 is -33.7, where the
// binary sum is -33.699999999999996, which the journal's look would then
// spell.  The exact decimal sum has no more places than the longer of the
// two, and the binary sum lies within an ulp or so of it, so rounding it to
// those places finds it; a + b itself where a text is too long.
double decimal_sum(double a, double b) {
  const int places_a = decimal_places(a), places_b = decimal_places(b), places = std::max(places_a, places_b);
  const double sum = a + b;
  if (places_a < 0 || places_b < 0 || places > 17) return sum;
  char text[64];
  const auto [end, ec] = std::to_chars(text, text + sizeof text, sum, std::chars_format::fixed, places);
  double rounded = sum;
  if (ec != std::errc() || std::from_chars(text, end, rounded).ec != std::errc()) return sum;
  return rounded;
}

// Refuses `out` (develop --out) where its PNGs would land on a render's
// frames: the render's own folder, or a folder holding a render of `shot`.
void check_out_folder(const fs::path& out, const fs::path& dir, const std::string& shot) {
  std::error_code ec;
  if (fs::exists(out, ec) && fs::equivalent(out, dir, ec))
    throw std::runtime_error(fmt::format("--out {}: the render's own folder; develop without --out makes its PNGs there",
                                         out.string()));
  const fs::path journal = out / (shot + ".journal");
  if (fs::exists(fs::symlink_status(journal, ec)))
    throw std::runtime_error(fmt::format("--out {}: it holds a render of '{}' ({}); develop --out writes developed PNGs "
                                         "into a folder of their own, never over a render's frames",
                                         out.string(), shot, journal.string()));
}

// Makes develop --out's folder ready: checked (check_out_folder), created,
// locked (a render or another develop kept out meanwhile) and checked again
// under the lock, and cleared of temporaries a killed develop left.
// Output: the lock, held until the develop ends.
std::unique_ptr<farm::DirLock> take_out_folder(const fs::path& out, const fs::path& dir, const std::string& shot) {
  check_out_folder(out, dir, shot);
  std::error_code ec;
  fs::create_directories(out, ec);
  if (ec || !fs::is_directory(out))
    throw std::runtime_error(fmt::format("--out {}: cannot create the folder: {}", out.string(),
                                         ec ? ec.message() : "a file of that name exists"));
  auto lock = std::make_unique<farm::DirLock>(out, "--out");
  check_out_folder(out, dir, shot);
  farm::remove_frame_temporaries(out, shot);
  return lock;
}

}  // namespace

std::vector<LookFlag> look_flags() {
  std::vector<LookFlag> flags;
  for_each_field<ShotInfo>([&](const auto& f) {
    if (!is_look_field(f.name)) return;
    using T = typename std::decay_t<decltype(f)>::Value;
    std::string range;
    if constexpr (std::is_floating_point_v<T>)
      range = fmt::format(" ({}{}{})", range_text(f.lo, f.hi), f.unit.empty() ? "" : " ", f.unit);
    flags.push_back({std::string(f.name), flag_of(f.name), fmt::format("The shot's `{}`: {}{}", f.name, f.doc, range)});
  });
  return flags;
}

Look developed_look(const Look& current, const Look& rendered, const std::map<std::string, std::string>& flags,
                    std::optional<double> exposure_shift) {
  ShotInfo s = as_fields(current);
  // The shift is from the render's exposure unless --exposure gives another.
  if (exposure_shift) s.exposure = rendered.exposure;
  for_each_field<ShotInfo>([&](const auto& f) {
    if (const auto it = flags.find(std::string(f.name)); it != flags.end() && is_look_field(f.name))
      set_from_text(s, f, it->second);
  });
  for (const auto& [field, text] : flags)
    if (!is_look_field(field)) throw std::logic_error(fmt::format("{}: not a field of a look", field));
  try {
    s.validate();
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(fmt::format("{}: {}", flags.contains("white_balance") ? "--white-balance" : "the look", e.what()));
  }
  Look look = s.look();
  if (exposure_shift) {
    look.exposure = decimal_sum(look.exposure, *exposure_shift);
    if (!(std::abs(look.exposure) <= 64.0))
      throw std::invalid_argument(fmt::format("--exposure-shift {}: takes an exposure to {} stops, outside -64 to 64",
                                              *exposure_shift, look.exposure));
  }
  return look;
}

int run_develop(const DevelopCommand& cmd) {
  // Input: the parsed flags; output: the frames' PNGs and journal lines,
  // and a summary on stderr.  Flags are checked before the directory is
  // touched, every frame's EXR before any PNG is written.
  developed_look(Look{}, Look{}, cmd.look, cmd.exposure_shift);
  // Each frame takes the same few large buffers (the EXR's pixels, the
  // look's copy, the bloom's light).  Above glibc's mmap threshold each
  // would be mapped, faulted in and zeroed page by page, and unmapped again
  // every frame; kept in the heap they are reused (docs/performance.md).
  // One arena for every thread: a thread's own arena is made of 64 MB heaps,
  // and one that empties (a frame's buffers freed) is unmapped whatever the
  // trim threshold, so the next frame faulted its pages in again.
  ::mallopt(M_MMAP_THRESHOLD, 32 << 20);  // glibc's largest
  ::mallopt(M_TRIM_THRESHOLD, 1 << 30);
  ::mallopt(M_ARENA_MAX, 1);
  InterruptGuard guard;
  const std::string shot = pick_shot(cmd.dir, cmd.shot);
  farm::FrameStore store(cmd.dir, shot, "DIR");  // its lock keeps a render out meanwhile
  const std::vector<int> frames = frames_to_develop(store, cmd.dir, shot, cmd.frames);

  const auto& journal = store.journal().frames;
  std::vector<Look> looks;
  for (int f : frames) {
    const farm::JournalFrame& line = journal.at(f);
    looks.push_back(
        developed_look(cmd.reset ? line.rendered_look() : line.look, line.rendered_look(), cmd.look, cmd.exposure_shift));
  }
  const std::unique_ptr<farm::DirLock> out_lock = cmd.out ? take_out_folder(*cmd.out, cmd.dir, shot) : nullptr;
  double render_seconds = 0.0;
  bool render_recorded = true;
  for (int f : frames) {
    render_seconds += journal.at(f).cost.core_seconds + journal.at(f).cost.star_seconds;
    render_recorded = render_recorded && journal.at(f).cost.recorded();
  }
  const int threads = std::clamp(cmd.threads > 0 ? cmd.threads : farm::usable_cpus(), 1, static_cast<int>(frames.size()));
  fmt::print(stderr, "develop: {} frame{} of '{}' in {}{} on {} thread{}{}\n", frames.size(), frames.size() == 1 ? "" : "s",
             shot, cmd.dir.string(), cmd.out ? " into " + cmd.out->string() : "", threads, threads == 1 ? "" : "s",
             looks.front() == looks.back() ? fmt::format(", look: {}", look_text(looks.front()).empty()
                                                                            ? "the paper's (the light as traced)"
                                                                            : look_text(looks.front()))
                                           : "");

  const auto start = std::chrono::steady_clock::now();
  const double cpu_at_start = process_cpu_seconds();
  std::atomic<std::size_t> done{0};
  std::optional<std::string> error;
  std::optional<int> interrupted;
  try {
    parallel_for(
        frames.size(), {.threads = threads},
        [&](std::size_t k) {
          store.develop_frame(frames[k], looks[k], cmd.out);
          ++done;
        },
        [&](ParallelRun& run) {
          const ProgressFn progress = progress_printer(guard, "develop", "frames");
          while (done < frames.size() && !run.stopped()) {
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
            try {
              progress(static_cast<int>(done), static_cast<int>(frames.size()));
            } catch (const Interrupted& e) {
              interrupted = e.signal;
              run.stop();
            }
          }
        });
  } catch (const std::exception& e) {
    error = e.what();
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (error) {
    fmt::print(stderr, "develop: stopped after {} of {} frames (each one developed is whole, with its journal line)\n",
               done.load(), frames.size());
    throw std::runtime_error(*error);
  }
  if (interrupted) {
    fmt::print(stderr, "develop: interrupted by {}: {} of {} frames developed, each whole; {}\n",
               signal_name(*interrupted), done.load(), frames.size(),
               cmd.out ? fmt::format("the rest are not in {} yet", cmd.out->string()) : "the rest keep their PNGs");
    return 128 + *interrupted;
  }
  // What it cost beside what rendering the frames cost: the journal's
  // core-seconds of their rays and stars (the render's writer, which made
  // the same files, is not in them, so this overstates the share).
  const double cpu = process_cpu_seconds() - cpu_at_start;
  fmt::print(stderr, "develop: done: {} frame{} in {:.2f} s, {:.2f} core-seconds ({:.1f} ms a frame){}\n", frames.size(),
             frames.size() == 1 ? "" : "s", seconds, cpu, 1e3 * cpu / static_cast<double>(frames.size()),
             render_recorded && render_seconds > 0.0
                 ? fmt::format("; {:.1f}% of the {:.1f} core-seconds the journal records for rendering them",
                               100.0 * cpu / render_seconds, render_seconds)
                 : "");
  return 0;
}

}  // namespace lc

#include "store/frame_store.hpp"

#include <chrono>
#include <algorithm>
#include <stdexcept>

#include <sys/resource.h>
#include <sys/statvfs.h>
#include <fmt/format.h>

#include "durable_file.hpp"
#include "store/frame_files.hpp"
#include "store/frame_writer.hpp"
#include "image/image_io.hpp"

namespace lc::farm {

namespace fs = std::filesystem;

namespace {

// Whether `name` is a temporary of this shot's frame files
// ("<shot>.<NNNN>.<ext>" + a DurableFile's temporary suffix).
bool is_frame_temporary(const std::string& name, const std::string& shot) {
  return name.rfind(shot + ".", 0) == 0 && is_temporary_name(name);
}

// Makes the previews' folder `dir` if missing, refusing a link under its
// name: the previews are the render's own files and go nowhere else.
void make_preview_dir(const fs::path& dir) {
  std::error_code ec;
  const fs::file_status st = fs::symlink_status(dir, ec);
  if (fs::is_symlink(st))
    throw std::runtime_error(fmt::format("cannot write previews into {}: it is a symbolic link, and lightcone never "
                                         "follows a link among its own files in a folder (move it away)",
                                         dir.string()));
  fs::create_directories(dir, ec);
  if (ec) throw std::runtime_error(fmt::format("cannot create {}: {}", dir.string(), ec.message()));
}

// Why a write into `dir` may have failed, when the image library's message
// does not say: a full file system or a file-size limit (ulimit -f).
std::string space_hint(const fs::path& dir) {
  std::string hint;
  struct statvfs vfs {};
  if (::statvfs(dir.c_str(), &vfs) == 0) {
    const auto avail = static_cast<std::uintmax_t>(vfs.f_bavail) * vfs.f_frsize;
    if (avail < (std::uintmax_t{64} << 20))
      hint += fmt::format(" (the file system holding {} has {} KiB free: is the disk full?)", dir.string(), avail / 1024);
  }
  struct rlimit lim {};
  if (::getrlimit(RLIMIT_FSIZE, &lim) == 0 && lim.rlim_cur != RLIM_INFINITY)
    hint += fmt::format(" (files are limited to {} KiB by ulimit -f)", lim.rlim_cur / 1024);
  return hint;
}

// Runs `write`; a failure's message gains the space hint.
template <class Write>
void with_space_hint(const fs::path& dir, Write&& write) {
  try {
    write();
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(e.what() + space_hint(dir));
  }
}

std::optional<std::uintmax_t> size_of(const fs::path& p) {
  std::error_code ec;
  const auto n = fs::file_size(p, ec);
  if (ec) return std::nullopt;
  return n;
}

}  // namespace

void remove_frame_temporaries(const fs::path& dir, const std::string& shot) {
  std::error_code ec;
  if (!fs::is_directory(fs::symlink_status(dir, ec))) return;  // (a link to a folder elsewhere is not looked into)
  for (const auto& e : fs::directory_iterator(dir, ec))
    if ((e.is_symlink(ec) || e.is_regular_file(ec)) && is_frame_temporary(e.path().filename().string(), shot))
      fs::remove(e.path(), ec);
}

FrameStore::FrameStore(fs::path dir, std::string shot, const char* flag) : dir_(std::move(dir)), shot_(std::move(shot)) {
  std::error_code ec;
  const bool made = !fs::exists(fs::symlink_status(dir_, ec));
  fs::create_directories(dir_, ec);
  if (ec || !fs::is_directory(dir_))
    throw std::runtime_error(fmt::format("{} {}: cannot create the output directory: {}", flag, dir_.string(),
                                         ec ? ec.message() : "a file of that name exists"));
  try {
    lock_ = std::make_unique<DirLock>(dir_, flag);
    remove_frame_temporaries(dir_, shot_);
    remove_frame_temporaries(preview_dir(), shot_);
    const fs::path file = dir_ / (shot_ + ".journal");
    journal_ = read_journal(file);
    writer_ = std::make_unique<JournalWriter>(file, journal_.valid_bytes);
  } catch (...) {
    // Refused (a full disk, another render, a journal that is not one):
    // the folder is left as it was found, so one made here goes again.
    lock_.reset();
    if (made) fs::remove(dir_, ec);  // (only if empty)
    throw;
  }
}

FrameState FrameStore::state(int frame, const FrameSettings& settings, const std::string& inputs) const {
  auto it = journal_.frames.find(frame);
  if (it == journal_.frames.end()) return FrameState::todo;
  const JournalFrame& jf = it->second;
  if (!(jf.settings == settings) || jf.inputs != inputs) return FrameState::stale;
  const auto exr = size_of(frame_path(dir_, shot_, frame, "exr"));
  const auto png = size_of(frame_path(dir_, shot_, frame, "png"));
  if (!exr || !png || *exr != jf.exr_bytes || *png != jf.png_bytes) return FrameState::damaged;
  return FrameState::done;
}

void FrameStore::note_inputs(const std::map<std::string, std::string>& files) {
  std::lock_guard lock(journal_mutex_);
  for (const auto& [path, hash] : files) {
    auto it = journal_.inputs.find(path);
    if (it != journal_.inputs.end() && it->second == hash) continue;
    pending_input_lines_.push_back(journal_input_line(hash, path));
    journal_.inputs[path] = hash;
  }
}

void FrameStore::write_frame(int frame, const FrameImage& image, const ImageMetadata& metadata,
                             const FrameSettings& settings, const std::string& inputs, const InputParts& parts,
                             FrameCost cost, const Look& look, const FrameMakers& makers,
                             std::optional<std::chrono::steady_clock::time_point> dispatched) {
  with_space_hint(dir_, [&] {
    write_frame_files(frame_path(dir_, shot_, frame, "exr"), frame_path(dir_, shot_, frame, "png"), image, metadata,
                      look, settings.png_depth);
  });
  JournalFrame jf;
  jf.frame = frame;
  jf.settings = settings;
  jf.inputs = inputs;
  jf.parts = parts;
  cost.finished = std::chrono::duration_cast<std::chrono::seconds>(std::chrono::system_clock::now().time_since_epoch()).count();
  // Its files are renamed into place and durable by now: the wall time
  // ends where the frame is safe, as a wrangler's "task done" does.
  if (dispatched) cost.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - *dispatched).count();
  jf.cost = cost;
  jf.makers = makers;
  const auto exr = size_of(frame_path(dir_, shot_, frame, "exr"));
  const auto png = size_of(frame_path(dir_, shot_, frame, "png"));
  if (!exr || !png)
    throw std::runtime_error(fmt::format("frame {} vanished from {} right after it was written", frame, dir_.string()));
  jf.exr_bytes = *exr;
  jf.png_bytes = *png;
  jf.look = look;
  append_frame_line(jf);
}

void FrameStore::append_frame_line(const JournalFrame& jf) {
  std::lock_guard lock(journal_mutex_);
  with_space_hint(dir_, [&] {
    while (!pending_input_lines_.empty()) {
      writer_->append(pending_input_lines_.front());
      pending_input_lines_.erase(pending_input_lines_.begin());
    }
    writer_->append(journal_frame_line(jf));
  });
  journal_.frames[jf.frame] = jf;
}

void FrameStore::develop_frame(int frame, const Look& look, const std::optional<fs::path>& into) {
  JournalFrame jf;
  {
    std::lock_guard lock(journal_mutex_);
    const auto it = journal_.frames.find(frame);
    if (it == journal_.frames.end())
      throw std::runtime_error(fmt::format("frame {} of '{}' has no line in {}: it is not recorded as finished", frame,
                                           shot_, (dir_ / (shot_ + ".journal")).string()));
    jf = it->second;
  }
  const fs::path exr = frame_path(dir_, shot_, frame, "exr");
  const auto exr_bytes = size_of(exr);
  if (!exr_bytes)
    throw std::runtime_error(fmt::format("{}: missing (the journal records frame {} as finished)", exr.string(), frame));
  if (*exr_bytes != jf.exr_bytes)
    throw std::runtime_error(fmt::format("{}: {} bytes, but the journal records {}: not the file the render wrote "
                                         "(cut short or replaced)",
                                         exr.string(), *exr_bytes, jf.exr_bytes));
  const FrameImage image = read_exr(exr);
  const fs::path png = frame_path(into ? *into : dir_, shot_, frame, "png");
  with_space_hint(png.parent_path(), [&] { write_png_file(png, image, look, jf.settings.png_depth); });
  if (into) return;  // another folder's frame: this folder's journal does not record it
  const auto png_bytes = size_of(png);
  if (!png_bytes) throw std::runtime_error(fmt::format("{} vanished right after it was written", png.string()));
  jf.png_bytes = *png_bytes;
  // The render's own look stays on record beside the developed one: the
  // next develop's exposure shift starts from it, whatever was applied since.
  if (!jf.render_look) jf.render_look = jf.look;
  jf.look = look;
  append_frame_line(jf);
}

void fill_missing_rows(FrameImage& image, const std::vector<int>& rendered) {
  if (rendered.empty()) return;
  const std::size_t w = static_cast<std::size_t>(image.width);
  auto copy_row = [&](int from, int to) {
    std::copy_n(image.rgb.begin() + static_cast<long>(3 * w * from), 3 * w, image.rgb.begin() + static_cast<long>(3 * w * to));
    if (!image.alpha.empty())
      std::copy_n(image.alpha.begin() + static_cast<long>(w * from), w, image.alpha.begin() + static_cast<long>(w * to));
    for (auto& layer : image.layers)
      std::copy_n(layer.values.begin() + static_cast<long>(w * from), w, layer.values.begin() + static_cast<long>(w * to));
  };
  std::size_t k = 0;  // rendered[k] is the first rendered row >= j
  for (int j = 0; j < image.height; ++j) {
    while (k < rendered.size() && rendered[k] < j) ++k;
    if (k < rendered.size() && rendered[k] == j) continue;
    const int below = k < rendered.size() ? rendered[k] : -1;
    const int above = k > 0 ? rendered[k - 1] : -1;
    int from = above;
    if (above < 0 || (below >= 0 && below - j < j - above)) from = below;
    copy_row(from, j);
  }
}

void FrameStore::write_preview(int frame, FrameImage image, const std::vector<int>& rendered,
                               const Look& look) {
  fill_missing_rows(image, rendered);
  const fs::path dir = preview_dir();
  make_preview_dir(dir);
  with_space_hint(dir, [&] { write_png_file(frame_path(dir, shot_, frame, "png"), image, look); });
}

}  // namespace lc::farm

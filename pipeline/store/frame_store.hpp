#pragma once
// The output directory of a render: finished frames (DIR/<shot>.<NNNN>.exr
// and .png, each renamed into place only when complete), the journal of
// finished frames (journal.hpp), the lock (dir_lock.hpp) and previews
// (DIR/preview/<shot>.<NNNN>.png).
//
// What is trusted on resume: a frame is finished when the journal has a
// line for it with the current settings and inputs AND both its files exist
// with the sizes the journal recorded.  A frame file without a journal line
// (the render stopped between the rename and the journal append) is rendered
// again and replaced; a journal line whose files are missing or have another
// size is ignored and the frame rendered again.  The EXR and PNG are the
// data; the journal is the record of which of them are complete.

#include <chrono>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "store/dir_lock.hpp"
#include "store/journal.hpp"
#include "image/look.hpp"
#include "image/image.hpp"

namespace lc::farm {

enum class FrameState {
  todo,     // no journal line: render it
  done,     // finished with these settings and inputs: skip it
  stale,    // finished with other settings or inputs: refused unless forced
  damaged,  // journal line present, files missing or of another size: render it
};

class FrameStore {
 public:
  // Creates `dir` if needed, takes its lock, removes temporaries a killed
  // render left behind, and reads the shot's journal.  Throws
  // std::runtime_error naming `flag` and the directory when it cannot be
  // created or written or is locked by another render.
  FrameStore(std::filesystem::path dir, std::string shot, const char* flag = "--out");

  const std::filesystem::path& dir() const { return dir_; }
  const JournalContents& journal() const { return journal_; }

  // What to do with `frame` for a render with these settings and inputs.
  FrameState state(int frame, const FrameSettings& settings, const std::string& inputs) const;

  // Input files (path -> hash) to record in the journal with the next frame
  // line, where they differ from what it already holds (for naming changed
  // files in a later refusal).
  void note_inputs(const std::map<std::string, std::string>& files);

  // Writes a finished frame's EXR and PNG atomically, makes the renames
  // durable, then appends its journal line.  Throws std::runtime_error
  // naming the file (a full disk, a vanished directory).  Thread-safe for
  // different frames (the journal appends are serialised).
  // The PNG shows the image through `look`, at the settings' depth; the
  // line records `cost`, stamped with the time it is written, and `makers`
  // (who rendered it); with `dispatched` (when its first working set was
  // handed out), the wall time from then until its files are stored.
  void write_frame(int frame, const FrameImage& image, const ImageMetadata& metadata, const FrameSettings& settings,
                   const std::string& inputs, const InputParts& parts, FrameCost cost, const Look& look,
                   const FrameMakers& makers = {},
                   std::optional<std::chrono::steady_clock::time_point> dispatched = std::nullopt);

  // Makes a finished frame's PNG again from its EXR through `look`, at the
  // depth it was rendered with (`lightcone develop`): the PNG is replaced
  // atomically and durably, then a journal line like the frame's with the
  // new PNG's size and the look supersedes it, keeping the look the render
  // made the PNG with on record (JournalFrame::render_look).  The same look gives the
  // same PNG to the byte (the EXR holds the floats the render's PNG was
  // made from).  Throws std::runtime_error naming the file when the frame
  // has no journal line, its EXR is missing or not of the size recorded
  // (a half-written or replaced file), or unreadable; nothing is changed
  // then.  Thread-safe for different frames.  With `into` (develop --out)
  // the PNG goes into that folder instead, under the same name, and nothing
  // of this folder changes (no PNG, no journal line).
  void develop_frame(int frame, const Look& look, const std::optional<std::filesystem::path>& into = std::nullopt);

  // Writes DIR/preview/<shot>.<NNNN>.png atomically from a frame of which
  // only `rendered` rows are filled: every other row is copied from the
  // nearest rendered row (the upper one on a tie).
  void write_preview(int frame, FrameImage image, const std::vector<int>& rendered, const Look& look);

  std::filesystem::path preview_dir() const { return dir_ / "preview"; }

 private:
  std::filesystem::path dir_;
  std::string shot_;
  std::unique_ptr<DirLock> lock_;
  JournalContents journal_;
  std::unique_ptr<JournalWriter> writer_;
  std::mutex journal_mutex_;  // writer_, journal_ and pending_input_lines_ after construction
  std::vector<std::string> pending_input_lines_;

  // Appends `jf` (after any pending input lines) and records it.
  void append_frame_line(const JournalFrame& jf);
};

// Removes the temporaries of `shot`'s frame files that a killed process
// left in `dir` (the caller holds the folder's lock: nobody else writes
// them); a link of such a name is removed itself, and a `dir` that is a
// link is not looked into.
void remove_frame_temporaries(const std::filesystem::path& dir, const std::string& shot);

// Rows j of `image` not in `rendered` (sorted, non-empty) copied from the
// nearest rendered row; the upper one on a tie.  Alpha and layers are
// filled alike.
void fill_missing_rows(FrameImage& image, const std::vector<int>& rendered);

}  // namespace lc::farm

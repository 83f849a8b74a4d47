#pragma once
// The order working sets are handed out in, and to whom: the one place that
// decides how frames are assigned.  Sets come out frame by frame (a frame's
// sets all go before the next frame's), so only a few frames are open at
// once; with a preview pass, every k-th stripe of every frame comes first.
// A taker that keeps something between frames (an MPI worker with its
// sample memo) gets back the stripes it had before.  Not thread-safe: the
// work queue (schedule/work_queue.hpp) holds it under its lock.

#include <cstddef>
#include <map>
#include <optional>
#include <vector>

#include "job/stripes.hpp"
#include "schedule/work_item.hpp"

namespace lc::farm {

class HandOut {
 public:
  // `frames` in the order they are to be rendered; `preview_every` k >= 2:
  // a preview pass of every k-th stripe first (else none).
  HandOut(const StripeLayout& layout, std::vector<int> frames, int preview_every);

  struct Next {
    WorkItem item;
    bool opens = false;  // the first set of its frame: the frame needs a canvas and a slot
  };
  // The next set for `taker` (>= 0: of the current frame's stripes, those
  // this taker had last time first, then any nobody had, then the others in
  // order; -1: in order).  nullopt when every set is out, or when the next
  // set would open a frame and `may_open` is false.
  std::optional<Next> next(int taker, bool may_open);
  // Every set of both passes is out.
  bool drained() const { return pass_ > 1 || frames_.empty(); }

  // The stripes a frame of `pass` consists of.
  const std::vector<int>& stripes_of(Pass pass) const { return pass == Pass::preview ? preview_stripes_ : all_stripes_; }
  // Where item's stripe sits in its pass's stripes, or -1 if it is none of them.
  int index_of(const WorkItem& item) const;
  const StripeLayout& layout() const { return layout_; }
  // The frames of each pass.
  int frame_count() const { return static_cast<int>(frames_.size()); }

 private:
  // The index (into the pass's stripes) of the current frame's next set for `taker`.
  std::size_t pick(int taker);

  StripeLayout layout_;
  std::vector<int> frames_;
  int preview_every_;
  std::vector<int> preview_stripes_, all_stripes_;
  // Cursor: pass (0 preview, 1 full), index into frames_; within the frame
  // (open once its first set is out) the sets handed out so far.
  int pass_ = 0;
  std::size_t frame_ = 0;
  bool frame_started_ = false;
  std::vector<char> handed_;                   // per index into the pass's stripes
  std::size_t handed_count_ = 0, lowest_ = 0;  // lowest_: no set below it is left
  std::vector<int> owner_;                     // per stripe: the taker it went to last (-1: none)
  std::map<int, std::vector<std::size_t>> left_for_;  // per owner, the current frame's indices it had, descending
};

}  // namespace lc::farm

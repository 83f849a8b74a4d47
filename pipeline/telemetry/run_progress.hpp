#pragma once
// How far a render is, as the progress lines and the event log say it: the
// values the work queue counts (schedule/work_queue.hpp), read without the
// queue, so telemetry knows nothing of how work is handed out.

#include <optional>
#include <vector>

#include "render/render_settings.hpp"
#include "store/event_file.hpp"

namespace lc::farm {

// Work done and to do, and what the finished sets cost.
struct RunProgress {
  long rows_total = 0, rows_done = 0;  // work, counted in image rows (ETA)
  int frames_total = 0, frames_stored = 0;      // full frames
  int previews_total = 0, previews_stored = 0;  // preview frames
  RenderStats stats;                            // of every finished set
};

// What the event log's progress line records at a moment: the run's
// progress, the frames in flight and, on an MPI farm, what each worker
// holds (none for a local farm).
struct ProgressReading {
  RunProgress progress;
  std::vector<int> open;
  std::optional<std::vector<RankHolding>> held;
};

}  // namespace lc::farm

#pragma once
// The farm's messages between the MPI master (rank 0) and its workers,
// packed as plain bytes (every rank runs the same binary, so native layout
// is shared; a size check guards each unpacking).
//
//   worker -> master  hello    digest, threads     (first message: the job the worker loaded)
//   worker -> master  request  n                   (wants up to n more working sets)
//   master -> worker  work     k sets              (k = 0: no more work will come)
//   worker -> master  result   set, stats, rows    (pixels of a finished set)
//   worker -> master  error    text                (the worker cannot go on)
//   master -> worker  stop                         (finish now, whatever is left)
//   worker -> master  bye                          (last message of a worker)
//   worker -> master  interrupted  signal          (a Ctrl-C or kill reached the worker: stop the job)

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "render/render_settings.hpp"
#include "schedule/work_item.hpp"

namespace lc::farm {

enum class Tag : int { hello = 11, request, work, result, error, stop, bye, interrupted };

using Bytes = std::vector<char>;

struct Hello {
  std::uint64_t digest = 0;
  int threads = 0;
  std::string host;  // the worker's node, for the event log (at most 255 bytes are sent)
};

Bytes pack_hello(const Hello& h);
Hello unpack_hello(std::span<const char> b);

Bytes pack_count(int n);
int unpack_count(std::span<const char> b);

Bytes pack_items(const std::vector<WorkItem>& items);
std::vector<WorkItem> unpack_items(std::span<const char> b);

// A finished set: its item, stats, then for each of its rows (top to
// bottom) the RGB of the row, its alpha (only when some pixel of the set is
// not opaque: the receiving canvas starts opaque), the row of every layer
// and its sky points (where the canvas has them).
Bytes pack_result(const WorkItem& item, const RenderStats& stats, const FrameImage& canvas,
                  const std::vector<int>& rows);
// The item and stats of a result (to find its canvas) ...
WorkItem result_item(std::span<const char> b);
// ... then its rows into the canvas; throws std::runtime_error when the
// size does not fit the canvas and rows.
RenderStats unpack_result(std::span<const char> b, FrameImage& canvas, const std::vector<int>& rows);

}  // namespace lc::farm

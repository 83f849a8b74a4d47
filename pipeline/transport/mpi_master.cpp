#include "transport/mpi_master.hpp"

#include <algorithm>
#include <optional>
#include <thread>
#include <vector>

#include <fmt/format.h>

#include "store/content_hash.hpp"
#include "transport/mpi_link.hpp"

#include <mpi.h>

namespace lc::farm {

namespace {

constexpr auto idle_sleep = std::chrono::milliseconds(1);

struct WorkerState {
  bool hello = false;
  int wanted = 0;  // sets asked for and not yet served
  bool told_no_more = false;
};

}  // namespace

MasterReport run_mpi_master(const MpiSession& mpi, WorkQueue& queue, FarmRun& run, Progress& progress,
                            std::uint64_t digest, EventLog* events, RankBoard* board) {
  MasterReport report;
  std::vector<WorkerState> workers(static_cast<std::size_t>(mpi.size()));

  auto handle = [&](Message& m) {
    WorkerState& w = workers[static_cast<std::size_t>(m.source)];
    switch (m.tag) {
      case Tag::hello: {
        const Hello h = unpack_hello(m.data);
        if (h.digest != digest) {
          run.fail(fmt::format(
              "rank {} loaded a different job (digest {} here, {} there): every rank must read the same shot "
              "script and modules and get the same flags — is the copy on its node out of date?",
              m.source, to_hex(digest), to_hex(h.digest)));
          return;
        }
        w.hello = true;
        ++report.workers;
        report.worker_threads += h.threads;
        report.hosts[m.source] = h.host;
        if (events) events->rank_joined(m.source, h.host, h.threads);
        if (board) board->joined(m.source);
        queue.set_max_open_frames(open_frames_for(report.worker_threads, queue.layout().stripes()));
        return;
      }
      case Tag::request:
        w.wanted = unpack_count(m.data);
        return;
      case Tag::result: {
        const WorkItem item = result_item(m.data);
        const RenderStats stats = unpack_result(m.data, queue.canvas(item), queue.layout().rows(item.stripe));
        if (board) board->returned(m.source, item);
        // The node is the one the worker named once, in its hello.
        run.finish(item, stats, m.source, report.hosts[m.source]);
        return;
      }
      case Tag::error:
        run.fail(fmt::format("rank {}: {}", m.source, std::string(m.data.begin(), m.data.end())));
        return;
      case Tag::interrupted:
        // Under mpirun a Ctrl-C reaches every rank as SIGTERM; a worker
        // that gets one alone stops the job the same way.
        run.interrupt(unpack_count(m.data));
        return;
      default:
        run.fail(fmt::format("rank {} sent an unexpected message (tag {})", m.source, static_cast<int>(m.tag)));
        return;
    }
  };

  // Gives worker r what it asked for, or tells it no more is coming.
  auto serve = [&](int r) {
    WorkerState& w = workers[static_cast<std::size_t>(r)];
    if (!w.hello || w.wanted <= 0 || w.told_no_more) return;
    std::vector<WorkItem> items;
    while (static_cast<int>(items.size()) < w.wanted)
      if (auto item = queue.take_for(r))
        items.push_back(*item);
      else
        break;
    if (!items.empty()) {
      if (board) board->handed(r, items);
      mpi_send(r, Tag::work, pack_items(items));
      w.wanted = 0;
    } else if (queue.drained() || queue.stopped()) {
      mpi_send(r, Tag::work, pack_items({}));
      w.told_no_more = true;
    }  // else: throttled until the writer catches up; serve later
  };

  while (!run.over()) {
    bool busy = false;
    while (auto m = mpi_poll(MPI_ANY_SOURCE)) {
      busy = true;
      try {
        handle(*m);
      } catch (const std::exception& e) {
        run.fail(fmt::format("rank {}: {}", m->source, e.what()));
      }
      if (run.over()) break;
    }
    for (int r = 1; r < mpi.size(); ++r) serve(r);
    progress.tick(queue.progress());
    if (!busy) std::this_thread::sleep_for(idle_sleep);
  }
  return report;
}

std::vector<int> stop_mpi_workers(const MpiSession& mpi, const std::optional<GiveUp>& give_up) {
  const Bytes none;
  for (int r = 1; r < mpi.size(); ++r) mpi_send(r, Tag::stop, none);
  std::vector<char> answered(static_cast<std::size_t>(mpi.size()), 0);
  answered[0] = 1;
  int left = mpi.size() - 1;
  const auto deadline = std::chrono::steady_clock::now() + answer_stop_within;
  std::optional<std::chrono::steady_clock::time_point> last_answer;
  while (left > 0) {
    if (auto m = mpi_poll(MPI_ANY_SOURCE)) {
      if (m->tag == Tag::bye && !answered[static_cast<std::size_t>(m->source)]) {
        answered[static_cast<std::size_t>(m->source)] = 1;
        --left;
        last_answer = std::chrono::steady_clock::now();
      }
      continue;
    }
    const auto now = std::chrono::steady_clock::now();
    if (give_up && (now > deadline || (last_answer && now > *last_answer + answer_stop_after_others))) {
      // Still waiting only for joined ranks: they are lost.  Any other
      // (one still loading its job) is waited for.
      std::vector<int> lost;
      bool only_joined = true;
      for (int r = 1; r < mpi.size(); ++r) {
        if (answered[static_cast<std::size_t>(r)]) continue;
        const bool joined = std::find(give_up->joined.begin(), give_up->joined.end(), r) != give_up->joined.end();
        if (joined)
          lost.push_back(r);
        else
          only_joined = false;
      }
      if (only_joined) return lost;
    }
    std::this_thread::sleep_for(idle_sleep);
  }
  return {};
}

}  // namespace lc::farm

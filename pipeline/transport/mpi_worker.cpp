#include "transport/mpi_worker.hpp"

#include <condition_variable>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <vector>

#include "transport/mpi_link.hpp"
#include "core/parallel_for.hpp"
#include "transport/threads.hpp"

namespace lc::farm {

namespace {

constexpr auto idle_wait = std::chrono::milliseconds(1);

// State shared between the MPI thread and the render threads.
struct WorkerShared {
  std::mutex mutex;
  std::condition_variable work_ready;  // render threads wait here
  std::condition_variable outbox_ready;  // the MPI thread waits here
  std::deque<WorkItem> inbox;
  int in_progress = 0;
  std::deque<std::pair<Tag, Bytes>> outbox;
  struct Canvas {
    std::unique_ptr<FrameImage> image;
    int outstanding = 0;  // sets of this frame received and not yet sent back
  };
  std::map<std::pair<int, int>, Canvas> canvases;  // (pass, frame)
  bool no_more = false, stopping = false, failed = false;
};

std::pair<int, int> key(const WorkItem& i) { return {static_cast<int>(i.pass), i.frame}; }

// A render thread: take a set, render into the frame's canvas, pack its
// rows, hand the message to the MPI thread.
void render_loop(WorkerShared& s, StripeRenderer& renderer, const StripeLayout& layout) {
  std::unique_lock lock(s.mutex);
  for (;;) {
    s.work_ready.wait(lock, [&] { return s.stopping || s.failed || !s.inbox.empty() || s.no_more; });
    if (s.stopping || s.failed || s.inbox.empty()) return;
    const WorkItem item = s.inbox.front();
    s.inbox.pop_front();
    ++s.in_progress;
    FrameImage& canvas = *s.canvases.at(key(item)).image;
    lock.unlock();
    std::pair<Tag, Bytes> message;
    try {
      const RenderStats stats = renderer.render(item, canvas);
      message = {Tag::result, pack_result(item, stats, canvas, layout.rows(item.stripe))};
    } catch (const std::exception& e) {
      const std::string what = e.what();
      message = {Tag::error, Bytes(what.begin(), what.end())};
    }
    lock.lock();
    --s.in_progress;
    if (message.first == Tag::error) s.failed = true;
    if (auto it = s.canvases.find(key(item)); it != s.canvases.end() && --it->second.outstanding == 0)
      s.canvases.erase(it);
    s.outbox.push_back(std::move(message));
    s.outbox_ready.notify_one();
    if (s.failed) s.work_ready.notify_all();
  }
}

}  // namespace

int run_mpi_worker(const MpiSession& /*mpi*/, StripeRenderer* renderer, const RenderSettings& rs,
                   const StripeLayout& layout, int threads, std::uint64_t digest,
                   const std::optional<std::string>& setup_error, int reserve_per_thread,
                   const std::function<int()>& signal_received) {
  WorkerShared s;
  SendQueue out;
  if (setup_error) {
    out.post(0, Tag::error, Bytes(setup_error->begin(), setup_error->end()));
    s.failed = true;
  } else {
    out.post(0, Tag::hello, pack_hello({digest, threads, host_name()}));
  }
  const int reserve = std::max(1, reserve_per_thread) * threads;
  bool asked = false;
  int interrupted = 0;
  // The render threads (none after a failed setup), each a render_loop; this
  // thread, the only one that talks MPI, is their watch and joins them once
  // it has said goodbye: each finishes the set it is on, its result dropped.
  const std::size_t render_threads = setup_error ? 0 : static_cast<std::size_t>(std::max(threads, 0));
  auto render = [&](std::size_t) { render_loop(s, *renderer, layout); };
  parallel_for(render_threads, {.threads = threads, .handout = Handout::by_thread}, render, [&](ParallelRun&) {
    try {
      std::unique_lock lock(s.mutex);
      while (!s.stopping) {
        if (interrupted == 0 && signal_received && (interrupted = signal_received()) != 0) {
          // Sets not begun are dropped (the master hands out no more and will
          // not assemble these frames); the ones on the threads finish.
          s.inbox.clear();
          s.no_more = true;
          out.post(0, Tag::interrupted, pack_count(interrupted));
        }
        // Post what the render threads finished; delivery goes on meanwhile.
        while (!s.outbox.empty()) {
          auto message = std::move(s.outbox.front());
          s.outbox.pop_front();
          out.post(0, message.first, std::move(message.second));
        }
        out.progress();
        const int have = static_cast<int>(s.inbox.size()) + s.in_progress;
        if (!s.failed && !s.no_more && !asked && have < reserve) {
          out.post(0, Tag::request, pack_count(reserve - have));
          asked = true;
        }
        lock.unlock();
        bool got = false;
        while (auto m = mpi_poll(0)) {
          got = true;
          lock.lock();
          if (m->tag == Tag::work) {
            // After a signal, work already on its way is not begun.
            const auto items = interrupted ? std::vector<WorkItem>{} : unpack_items(m->data);
            asked = false;
            if (items.empty()) s.no_more = true;
            for (const auto& item : items) {
              auto& c = s.canvases[key(item)];
              if (!c.image) c.image = std::make_unique<FrameImage>(make_frame(rs));
              ++c.outstanding;
              s.inbox.push_back(item);
            }
            s.work_ready.notify_all();
          } else if (m->tag == Tag::stop) {
            s.stopping = true;
            s.work_ready.notify_all();
            if (renderer) renderer->stop();
          }
          lock.unlock();
          if (m->tag == Tag::stop) break;
        }
        lock.lock();
        if (!got && s.outbox.empty() && !s.stopping) s.outbox_ready.wait_for(lock, idle_wait);
      }
      s.inbox.clear();
      lock.unlock();
      // Goodbye first: the master takes a worker that does not answer its
      // stop at once for lost (mpi_master.hpp).
      out.post(0, Tag::bye, Bytes{});
      out.drain();
    } catch (...) {
      // The render threads wait for work this thread will no longer bring.
      {
        std::lock_guard stop(s.mutex);
        s.stopping = true;
      }
      s.work_ready.notify_all();
      throw;
    }
  });
  return interrupted;
}

}  // namespace lc::farm

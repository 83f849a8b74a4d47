#include "farm_bench_command.hpp"

#include <chrono>
#include <filesystem>
#include <numeric>
#include <stdexcept>

#include <fmt/format.h>
#include <sys/resource.h>
#include <unistd.h>

#include "core/cpu_time.hpp"
#include "core/parallel_for.hpp"
#include "store/content_hash.hpp"
#include "schedule/farm_run.hpp"
#include "store/frame_files.hpp"
#include "store/frame_writer.hpp"
#include "transport/local_farm.hpp"
#include "transport/mpi_master.hpp"
#include "transport/mpi_session.hpp"
#include "transport/mpi_worker.hpp"
#include "transport/threads.hpp"
#include "job/image_size.hpp"

namespace lc {

namespace {

// Completed frames go nowhere: the benchmark times the farm, not the disk.
class DiscardSink final : public farm::FrameSink {
 public:
  void store(const farm::CompletedFrame&) override {}
};

double cpu_seconds() {
  rusage u{};
  ::getrusage(RUSAGE_SELF, &u);
  return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

struct WriteTiming {
  double one = 0;       // seconds for one frame, alone (best of 3)
  double parallel = 0;  // frames per second with `writers` threads at once
};

// Times writing frames of these settings as EXR + PNG the way the frame
// store does (verified, synced), alone and with `writers` threads at once,
// into a scratch folder that is removed afterwards.
WriteTiming time_frame_writes(const RenderSettings& rs, int writers) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / fmt::format("lightcone-farm-bench-{}", ::getpid());
  fs::create_directories(dir);
  FrameImage img = make_frame(rs);
  // A pattern rather than zeros, so compression has something to do.
  for (std::size_t i = 0; i < img.rgb.size(); ++i) img.rgb[i] = static_cast<float>((i * 2654435761u) % 1000) / 1000.0f;
  auto write = [&](int k) {
    farm::write_frame_files(farm::frame_path(dir, "bench", k, "exr"), farm::frame_path(dir, "bench", k, "png"), img,
                            {{"lightcone/shot", "bench"}}, Look{});
  };
  auto since = [](auto t0) { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
  WriteTiming t;
  t.one = 1e30;
  std::exception_ptr failure;
  try {
    for (int k = 0; k < 3; ++k) {
      const auto t0 = std::chrono::steady_clock::now();
      write(k);
      t.one = std::min(t.one, since(t0));
    }
    const int frames = 3 * writers;
    const auto t0 = std::chrono::steady_clock::now();
    parallel_for(static_cast<std::size_t>(frames), {.threads = writers},
                 [&](std::size_t k) { write(100 + static_cast<int>(k)); });
    t.parallel = frames / since(t0);
  } catch (...) {
    failure = std::current_exception();
  }
  std::error_code ec;
  fs::remove_all(dir, ec);
  if (failure) std::rethrow_exception(failure);
  return t;
}

}  // namespace

int run_farm_bench(const FarmBenchCommand& cmd) {
  RenderSettings rs;
  std::tie(rs.width, rs.height) = output_size(1, 1, cmd.size, 1.0);
  rs.layers = cmd.layers;
  if (cmd.stripes < 1) throw std::invalid_argument(fmt::format("--stripes {}: must be at least 1", cmd.stripes));
  if (cmd.frames < 1) throw std::invalid_argument(fmt::format("--frames {}: must be at least 1", cmd.frames));
  const farm::StripeLayout layout(rs.height, cmd.stripes);
  farm::ContentHash digest;
  digest.add(cmd.size).add(std::uint64_t(layout.stripes())).add(std::uint64_t(cmd.frames)).add(std::uint64_t(cmd.layers));

  farm::MpiSession mpi;
  farm::NullStripeRenderer renderer;
  if (mpi.size() > 1 && mpi.rank() != 0) {
    const int threads = cmd.threads > 0 ? cmd.threads : farm::default_threads(mpi.workers_on_node());
    // A deep reserve: the sets cost nothing, so only a full pipeline keeps
    // the master from idling between round trips.
    farm::run_mpi_worker(mpi, &renderer, rs, layout, threads, digest.value(), std::nullopt, 32);
    return 0;
  }

  std::vector<int> frames(static_cast<std::size_t>(cmd.frames));
  std::iota(frames.begin(), frames.end(), 0);
  const int local_threads = cmd.threads > 0 ? cmd.threads : farm::usable_cpus();
  farm::WorkQueue queue(rs, layout, frames, {.preview_every = 0, .max_open_frames = farm::open_frames_for(local_threads, layout.stripes())});
  DiscardSink sink;
  farm::Progress quiet(farm::ProgressStyle::quiet, 0);
  const double cpu0 = cpu_seconds();
  const auto t0 = std::chrono::steady_clock::now();
  std::optional<std::string> error;
  std::string who;
  {
    farm::FarmRun run(queue, sink);
    if (mpi.size() > 1) {
      const auto report = farm::run_mpi_master(mpi, queue, run, quiet, digest.value());
      farm::stop_mpi_workers(mpi);
      who = fmt::format("master + {} worker rank{} ({} threads)", report.workers, report.workers == 1 ? "" : "s",
                        report.worker_threads);
    } else {
      farm::run_local_farm(queue, run, renderer, local_threads, quiet);
      who = fmt::format("one process, {} thread{}", local_threads, local_threads == 1 ? "" : "s");
    }
    run.close();
    error = run.error();
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double cpu = cpu_seconds() - cpu0;
  if (error) throw std::runtime_error(*error);
  const long sets = static_cast<long>(cmd.frames) * layout.stripes();
  const double bytes_per_set = (static_cast<double>(rs.width) * rs.height / layout.stripes()) *
                               (3 + (rs.layers ? 5 : 0)) * sizeof(float);
  fmt::print("farm-bench: {}x{}{}, {} stripes, {} frames = {} working sets; {}\n", rs.width, rs.height,
             rs.layers ? " with layers" : "", layout.stripes(), cmd.frames, sets, who);
  // The farm's rates are wall time (it is the handing out that is timed, not
  // work on a core): the load says how far to trust them.
  fmt::print("  {}\n", describe_load(farm::usable_cpus()));
  fmt::print("  handed out and assembled: {:.0f} working sets/s, {:.1f} frames/s, {:.1f} MB/s of pixels "
             "({:.1f} KB a set), in {:.2f} s\n",
             sets / wall, cmd.frames / wall, sets * bytes_per_set / wall / 1e6, bytes_per_set / 1e3, wall);
  if (mpi.size() > 1)
    fmt::print("  master CPU: {:.2f} s for {:.2f} s of wall time ({:.0f}% of one core)\n", cpu, wall, 100 * cpu / wall);
  const WriteTiming write = time_frame_writes(rs, farm::master_writer_threads);
  fmt::print("  writing frames (EXR + PNG, read back, fsynced): {:.3f} s for one alone; {:.1f} frames/s with the "
             "master's {} writer threads\n",
             write.one, write.parallel, farm::master_writer_threads);
  return 0;
}

}  // namespace lc

#include "render_command.hpp"

#include <algorithm>
#include <cmath>
#include <csignal>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>

#include <unistd.h>

#include <fmt/format.h>

#include "store/content_hash.hpp"
#include "schedule/farm_run.hpp"
#include "store/frame_store.hpp"
#include "transport/local_farm.hpp"
#include "stages/memo_budget.hpp"
#include "core/cpu_time.hpp"
#include "telemetry/event_log.hpp"
#include "job/exposure_meter.hpp"
#include "transport/mpi_master.hpp"
#include "transport/mpi_session.hpp"
#include "transport/mpi_worker.hpp"
#include "telemetry/progress.hpp"
#include "job/resume_plan.hpp"
#include "store/frame_list.hpp"
#include "stages/scene_stripe_renderer.hpp"
#include "job/shot_survey.hpp"
#include "stages/store_sink.hpp"
#include "stages/pausing_stripe_renderer.hpp"
#include "transport/threads.hpp"
#include "job/frame_range.hpp"
#include "job/image_size.hpp"
#include "interrupt.hpp"
#include "job/render_job.hpp"
#include "script/shot.hpp"
#include "stars/star_pass.hpp"
#include "video/encode_options.hpp"

namespace lc {

namespace {

// Says so when frames of this size cannot become a video with `lightcone
// encode`'s default codec, or a video only some players play.  A warning,
// not a refusal: large stills (prints, plates for compositing) are a use
// of their own, and the encode refuses such frames at once anyway.
void warn_if_not_encodable(const RenderSettings& rs) {
  if (const auto why = size_refusal(Codec::h264, rs.width, rs.height))
    fmt::print(stderr,
               "render: warning: these frames cannot be encoded to video by lightcone encode ({}); they are rendered "
               "as asked — for a video, render smaller (--size, --scale)\n",
               *why);
  else if (const auto warning = size_warning(Codec::h264, rs.width, rs.height))
    fmt::print(stderr, "render: warning: lightcone encode will make an H.264 video of these frames, but {}\n", *warning);
}

// A frame whose sky has point stars is drawn on by the star pass, which
// needs pictures (each eye's, or the --region's) of at least
// star_pass_min_side pixels each way: refused before the render starts
// (std::invalid_argument naming the flag or field), not after its first
// frame's rays.  `camera` is the frame's at the whole frame's size.
void check_star_pictures(int frame, const Camera& camera, const RenderSettings& rs) {
  const int least = star_pass_min_side;
  if (rs.window.windowed()) {
    if (rs.width < least || rs.height < least)
      throw std::invalid_argument(fmt::format(
          "--region: {}x{} pixels; frame {}'s sky has point stars, which are drawn on pictures of at least {}x{}: "
          "give a region of at least {} pixels each way",
          rs.width, rs.height, frame, least, least, least));
    return;
  }
  for (const EyePicture& p : camera.pictures()) {
    if (p.width >= least && p.height >= least) continue;
    if (p.eye != 0)
      throw std::invalid_argument(fmt::format(
          "frame {}: the camera's `stereo` puts each eye's picture in {}x{} pixels of the {}x{} frame; its sky has "
          "point stars, which are drawn on pictures of at least {}x{}: render a larger frame (--size, --scale or the "
          "shot's width and height)",
          frame, p.width, p.height, rs.width, rs.height, least, least));
    throw std::invalid_argument(fmt::format(
        "the frame is {}x{} pixels (--size, --scale or the shot's width and height); frame {}'s sky has point stars, "
        "which are drawn on pictures of at least {}x{}",
        rs.width, rs.height, frame, least, least));
  }
}

// What the frames' cameras say of the image size, before anything is
// written: a --region of a stereo frame is refused (std::invalid_argument:
// its window would cut across both eyes' pictures), and so is a picture
// too small for the point stars of a frame's sky (at its moment or any
// instant of its shutter); an odd size for a camera (an equirect frame
// whose pixels are not square) is warned about, once, not refused: the
// frame is what was asked for, a video site or player may just not show it
// as a sphere.
void check_cameras(const farm::ShotSurvey& survey, const RenderSettings& rs) {
  const int width = rs.window.windowed() ? rs.window.frame_width : rs.width;
  const int height = rs.window.windowed() ? rs.window.frame_height : rs.height;
  bool warned = false;
  for (const auto& [frame, facts] : survey.frames) {
    const Camera camera(facts.camera, width, height);
    if (rs.window.windowed() && camera.pictures().size() > 1)
      throw std::invalid_argument(fmt::format("--region: frame {}'s camera is stereo; a region of a stereo frame is "
                                              "not offered (render the shot with stereo = \"mono\" to check a part "
                                              "of it)", frame));
    // (Shot::frame_specs refuses a change of sky or camera kind within a
    // shutter: the frame's own stand for its instants'.)
    if (has_point_stars(facts.sky)) check_star_pictures(frame, camera, rs);
    if (warned) continue;
    if (const auto warning = camera.size_warning()) {
      fmt::print(stderr, "render: warning: frame {}: {} (at {}x{})\n", frame, *warning, width, height);
      warned = true;
    }
  }
}

// The rows a preview frame holds, top to bottom.
std::vector<int> preview_rows(const farm::WorkQueue& queue) {
  std::vector<int> rows;
  for (int s : queue.stripes_of(farm::Pass::preview))
    for (int j : queue.layout().rows(s)) rows.push_back(j);
  std::sort(rows.begin(), rows.end());
  return rows;
}

// Says what resuming keeps and redoes.
void report_plan(const farm::ResumePlan& plan, std::size_t asked, const RenderRequest& cmd) {
  if (!plan.done.empty())
    fmt::print(stderr, "render: resuming: {} of {} frames already finished in {} ({})\n", plan.done.size(), asked,
               cmd.out.string(), farm::format_frame_list(plan.done));
  if (!plan.damaged.empty())
    fmt::print(stderr, "render: frames {}: in the journal but their files are missing or changed; rendering them again\n",
               farm::format_frame_list(plan.damaged));
  if (!plan.stale.empty())
    fmt::print(stderr, "render: --force: frames {} were made from other settings or inputs; rendering them again\n",
               farm::format_frame_list(plan.stale));
}

// Stops the MPI workers once, on whichever way the master leaves (they
// wait for its word however it fails).
class WorkerStop {
 public:
  explicit WorkerStop(const farm::MpiSession* mpi) : mpi_(mpi) {}
  ~WorkerStop() { now(); }
  WorkerStop(const WorkerStop&) = delete;
  WorkerStop& operator=(const WorkerStop&) = delete;
  // The workers given up as lost (farm::stop_mpi_workers).
  std::vector<int> now(const std::optional<farm::GiveUp>& give_up = std::nullopt) {
    std::vector<int> lost;
    if (mpi_ && !done_) lost = farm::stop_mpi_workers(*mpi_, give_up);
    done_ = true;
    return lost;
  }

 private:
  const farm::MpiSession* mpi_;
  bool done_ = false;
};

// A shot with auto_exposure: each frame to render gets the metered
// exposure plus its own (job/exposure_meter.hpp), for its PNG and journal
// line; only the frames its smoothing reaches are metered.  The meter sees
// the whole frame, whatever --region renders.
void meter_exposures(farm::ShotSurvey& survey, Shot& shot, const RenderSettings& rs, const std::filesystem::path& dir,
                     int threads, const std::vector<int>& todo, const farm::MeterProgress& each) {
  const ImageWindow& w = rs.window;
  const farm::MeterReadings meter = farm::shot_readings(shot, dir, w.windowed() ? w.frame_width : rs.width,
                                                        w.windowed() ? w.frame_height : rs.height, threads, todo, each);
  std::map<int, std::optional<double>> own;
  for (const int frame : todo) own[frame] = survey.frames.at(frame).exposure;
  for (const auto& [frame, exposure] : farm::auto_exposures(shot.info(), meter, own))
    survey.frames.at(frame).exposure = exposure;
}

// The local farm, or the master of an MPI farm (mpi non-null): everything
// but the rendering itself.
int render_as_master(const RenderRequest& cmd, const farm::MpiSession* mpi) {
  // A Ctrl-C or kill from here on stops the render once the frames in hand
  // are stored (the farm run watches for it), not mid-write; the guard
  // outlives the workers' stop, which waits for them.
  InterruptGuard interrupts;
  WorkerStop stop_workers(mpi);
  RenderJob job = load_render_job(cmd);
  warn_if_not_encodable(job.rs);
  // A frame that cannot fit the master's memory is refused before the
  // survey, not when its rays are in (a worker elsewhere holds less of it).
  if (const auto memory = farm::memory_available())
    if (const auto refusal = farm::frame_memory_refusal(job.rs, *memory)) throw std::invalid_argument(*refusal);
  if (job.range && job.range->last_taken() != job.range->last) {
    const std::vector<int>& taken = job.frames;
    const std::string list = taken.size() <= 3 ? fmt::format("{}", fmt::join(taken, ", "))
                                               : fmt::format("{}, {}, ..., {}", taken[0], taken[1], taken.back());
    fmt::print(stderr,
               "render: note: --frames {} takes {}: {} is not on the step. To end the sequence on it, render --frames {} "
               "into the same directory too (encode takes a stepped sequence with one last frame after it)\n",
               *cmd.frames, list, job.range->last, job.range->last);
  }
  const ShotInfo& info = job.shot->info();
  // Every frame asked for is evaluated first (a script error anywhere stops
  // the render before it starts): ~3 ms a frame, minutes on a long shot, so
  // said as it goes and stopped by a signal (nothing is written yet).
  farm::ShotSurvey survey;
  const auto check_signal = [&interrupts] { interrupts.check(); };
  try {
    farm::StepProgress step("evaluating the frames", job.frames.size(), cmd.progress, check_signal);
    survey = farm::survey_shot(*job.shot, job.frames, [&step](std::size_t done) { step(done); });
  } catch (const Interrupted& e) {
    fmt::print(stderr, "render: interrupted by {} while evaluating the frames; nothing was rendered\n",
               signal_name(e.signal));
    return 128 + e.signal;
  }
  check_cameras(survey, job.rs);
  farm::FrameStore store(cmd.out, info.name);
  farm::FrameSettings settings = farm::frame_settings(job.rs);
  settings.png_depth = cmd.png_depth();
  settings.delivery = job.delivery;
  settings.shutter = job.shutter;
  const farm::ResumePlan plan = farm::plan_resume(store, survey, settings, job.frames, cmd.force, info.name);

  const int threads = mpi ? 0 : (cmd.threads > 0 ? cmd.threads : farm::usable_cpus());
  const std::string who = mpi ? fmt::format("{} ranks (a master and {} worker{})", mpi->size(), mpi->size() - 1,
                                            mpi->size() == 2 ? "" : "s")
                              : fmt::format("{} thread{}", threads, threads == 1 ? "" : "s");
  const ImageWindow& window = job.rs.window;
  const std::string of = window.windowed() ? fmt::format(" (pixels {},{} to {},{} of the {}x{} frame)", window.x0,
                                                         window.y0, window.x0 + job.rs.width, window.y0 + job.rs.height,
                                                         window.frame_width, window.frame_height)
                                           : "";
  fmt::print(stderr, "render: {} frame{} of '{}' at {}x{}{}, {}x{} samples per pixel, {} stripes, {} -> {}\n",
             job.frames.size(), job.frames.size() == 1 ? "" : "s", info.name, job.rs.width, job.rs.height, of,
             job.rs.supersample, job.rs.supersample, job.layout.stripes(), who, cmd.out.string());
  report_plan(plan, job.frames.size(), cmd);
  if (plan.todo.empty()) {
    fmt::print(stderr, "render: done: nothing to render, all {} frames are finished\n", job.frames.size());
    return 0;
  }
  store.note_inputs(survey.files);
  // What `lightcone monitor` shows of this run (telemetry/event_log.hpp), from
  // before the exposure is metered: a monitor sees the run at once.
  farm::EventLog events(cmd.out, info.name);
  events.run_started({.pid = static_cast<long>(::getpid()), .host = farm::host_name(), .ranks = mpi ? mpi->size() : 1,
                      .threads = threads, .todo = static_cast<int>(plan.todo.size()),
                      .done_before = static_cast<int>(plan.done.size()), .width = job.rs.width, .height = job.rs.height,
                      .script = std::filesystem::absolute(cmd.shot).string(), .command = farm::own_command_line(),
                      .cwd = std::filesystem::current_path().string()});
  if (info.auto_exposure) {
    try {
      farm::StepProgress step("auto exposure: metering", 0, cmd.progress, check_signal);
      meter_exposures(survey, *job.shot, job.rs, cmd.out, mpi ? farm::usable_cpus() : threads, plan.todo,
                      [&step](std::size_t done, std::size_t total) { step(done, total); });
    } catch (const Interrupted& e) {
      events.run_ended("interrupted", 0);
      fmt::print(stderr,
                 "render: interrupted by {} while metering the exposure; nothing was rendered (the readings made are "
                 "kept for the next run)\n",
                 signal_name(e.signal));
      return 128 + e.signal;
    } catch (const std::exception& e) {
      events.error(e.what());
      events.run_ended("error", 0);
      throw;
    }
  }

  farm::WorkQueue queue(job.rs, job.layout, plan.todo,
                        {.preview_every = job.preview, .max_open_frames = farm::open_frames_for(std::max(threads, 1), job.layout.stripes())});
  // A frame's point stars on as many threads as render it (the MPI
  // master's writers draw four frames at once on a worker's node: one each).
  const int star_threads = mpi ? 1 : threads;
  farm::StoreSink sink(store, survey, info, job.rs, settings, preview_rows(queue), job.shot->asset_dirs(), star_threads,
                       &events);
  farm::Progress progress(farm::progress_style_for(stderr, cmd.progress), cmd.progress);
  int cores = threads;
  const double cpu_at_start = process_cpu_seconds();
  std::optional<std::string> error;
  int interrupted = 0;
  std::map<int, std::string> lost;  // workers given up, with their nodes
  {
    // The MPI master has its cores to itself but for a worker's share:
    // writing frames in parallel keeps up with many workers.
    farm::FarmRun run(queue, sink, mpi ? farm::master_writer_threads : 1, [&interrupts] { return interrupts.signal(); });
    farm::RankBoard board;
    const farm::ProgressEvents progress_events(events, [&queue, &board, on_mpi = mpi != nullptr] {
      return farm::ProgressReading{queue.progress(), queue.open_frames(),
                                   on_mpi ? std::optional(board.holdings()) : std::nullopt};
    });
    if (mpi) {
      const farm::MasterReport report = farm::run_mpi_master(*mpi, queue, run, progress, job.digest, &events, &board);
      cores = report.worker_threads;
      // A signal may be a launcher ending the job because a rank died: a
      // worker that does not answer then is lost, not waited for.
      std::optional<farm::GiveUp> give_up;
      if (run.interrupted()) {
        give_up.emplace();
        for (const auto& [rank, host] : report.hosts) give_up->joined.push_back(rank);
      }
      for (const int rank : stop_workers.now(give_up)) {
        lost[rank] = report.hosts.at(rank);
        events.rank_lost(rank, lost[rank]);
      }
    } else {
      // Enough scenes for every frame that can be open at once.
      farm::SceneCache scenes(*job.shot, job.rs.width, job.rs.height,
                              farm::open_frames_for(threads, job.layout.stripes()) + 2, job.rs.window);
      const auto refusal = cmd.no_reuse ? std::nullopt : farm::memo_refusal(job.rs, 1);
      if (refusal) fmt::print(stderr, "render: {}\n", *refusal);
      farm::SceneStripeRenderer renderer(scenes, job.rs, job.layout, !cmd.no_reuse && !refusal);
      const auto paused = farm::paused_for_a_test(renderer, job.test_pause, "render", [&run] { return run.interrupted() != 0 || run.error(); });
      farm::run_local_farm(queue, run, paused ? *paused : static_cast<farm::StripeRenderer&>(renderer), threads, progress);
    }
    run.close();
    error = run.error();
    interrupted = run.interrupted();
  }
  progress.finish();
  const farm::RunProgress p = queue.progress();
  if (error) events.error(*error);
  events.run_ended(error ? "error" : interrupted ? "interrupted" : "done", p.frames_stored);
  for (const auto& [rank, host] : lost)
    fmt::print(stderr,
               "render: rank {} (on {}) was lost: it did not answer the master's stop (killed, out of memory, or its "
               "node failed); the frames it held are rendered when the same command resumes\n",
               rank, host);
  // Whichever way the run ended (an error may land with the launcher's
  // signal), a lost rank means no MPI_Finalize.
  if (!lost.empty()) mpi->end_with_abort(error ? 1 : 128 + interrupted);
  if (error) {
    if (p.frames_stored > 0 || !plan.done.empty())
      fmt::print(stderr, "render: stopped after {} new frame{}; finished frames are kept, the same command resumes\n",
                 p.frames_stored, p.frames_stored == 1 ? "" : "s");
    throw std::runtime_error(*error);
  }
  if (interrupted) {
    fmt::print(stderr, "render: interrupted by {}: {} of {} frames done ({} in this run); run the same command again to resume\n",
               signal_name(interrupted), plan.done.size() + static_cast<std::size_t>(p.frames_stored), job.frames.size(),
               p.frames_stored);
    return 128 + interrupted;
  }
  const double s = progress.elapsed();
  fmt::print(stderr, "render: done: {} frames in {:.2f} s, {} rays, {:.0f} rays/s, {:.0f} rays per core-second ({} core{}){}{}\n",
             p.frames_stored, s, p.stats.rays, p.stats.rays / s, p.stats.rays / s / std::max(1, cores), cores,
             cores == 1 ? "" : "s",
             p.stats.reused ? fmt::format("; {} samples reused from earlier frames", p.stats.reused) : "",
             plan.done.empty() ? "" : fmt::format("; {} more were finished before", plan.done.size()));
  if (const double stars = sink.star_seconds(); stars > 0.0)
    fmt::print(stderr, "render: point stars drawn in {:.2f} core-seconds ({:.1f}% of the CPU time), {:.2f} s of the writer's time; {}\n",
               stars, 100 * stars / (stars + p.stats.seconds), sink.star_wall_seconds(),
               mpi ? "on the master's writers" : fmt::format("on up to {} thread{}", star_threads, star_threads == 1 ? "" : "s"));
  if (mpi)
    fmt::print(stderr, "render: the master used {:.2f} s of CPU in {:.2f} s ({:.0f}% of one core) while {} worker threads rendered\n",
               process_cpu_seconds() - cpu_at_start, s, 100 * (process_cpu_seconds() - cpu_at_start) / s, cores);
  if (p.stats.gave_up)
    fmt::print(stderr,
               "render: {} rays gave up (drawn black): each ran out of steps or its step size fell below what double "
               "precision resolves there; `lightcone trace SHOT --frame F --pixel I,J` shows a pixel's stop reason\n",
               p.stats.gave_up);
  return 0;
}

// A worker rank: loads the same job, renders what the master hands out.
// Prints nothing: the master reports, errors included.
int render_as_worker(const RenderRequest& cmd, const farm::MpiSession& mpi) {
  // Under mpirun a Ctrl-C reaches every rank as SIGTERM: the worker tells
  // the master and waits for its stop, so neither hangs nor is cut off.
  InterruptGuard interrupts;
  std::optional<std::string> setup_error;
  RenderJob job;
  try {
    job = load_render_job(cmd);  // a bad test-pause value too is this rank's setup error
  } catch (const std::exception& e) {
    setup_error = e.what();
  }
  const int threads = cmd.threads > 0 ? cmd.threads : farm::default_threads(mpi.workers_on_node());
  std::unique_ptr<farm::SceneCache> scenes;
  std::unique_ptr<farm::SceneStripeRenderer> renderer;
  if (!setup_error) {
    // Enough scenes for the frames the sets in hand (two per thread) span.
    scenes = std::make_unique<farm::SceneCache>(*job.shot, job.rs.width, job.rs.height,
                                                farm::open_frames_for(threads, job.layout.stripes()) + 2,
                                                job.rs.window);
    // Each worker judges its own node's memory (the master cannot see it).
    const bool reuse = !cmd.no_reuse && !farm::memo_refusal(job.rs, mpi.workers_on_node());
    renderer = std::make_unique<farm::SceneStripeRenderer>(*scenes, job.rs, job.layout, reuse);
  }
  // A worker drops the sets it holds as soon as it sees the signal, so the
  // signal itself may end its pause.
  const auto paused = renderer ? farm::paused_for_a_test(*renderer, job.test_pause, fmt::format("rank {}", mpi.rank()),
                                                   [&interrupts] { return interrupts.signal() != 0; })
                               : nullptr;
  farm::StripeRenderer* used = paused ? static_cast<farm::StripeRenderer*>(paused.get()) : renderer.get();
  const int sig = farm::run_mpi_worker(mpi, used, job.rs, job.layout, threads,
                                       job.digest, setup_error, 2, [&interrupts] { return interrupts.signal(); });
  return sig ? 128 + sig : 0;
}

}  // namespace

int run_render(const RenderRequest& cmd) {
  farm::MpiSession mpi;
  return render_in_session(cmd, mpi);
}

int render_in_session(const RenderRequest& cmd, const farm::MpiSession& mpi) {
  // A file-size limit (ulimit -f) must fail the write with EFBIG and a
  // message, not kill the process with SIGXFSZ.
  std::signal(SIGXFSZ, SIG_IGN);
  if (mpi.size() <= 1) return render_as_master(cmd, nullptr);
  if (mpi.rank() != 0) return render_as_worker(cmd, mpi);
  return render_as_master(cmd, &mpi);
}

}  // namespace lc

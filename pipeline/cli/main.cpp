// The lightcone command line: parses flags (the only file that includes
// CLI11) and hands each subcommand a plain options struct.

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>
#include <cstdio>
#include <exception>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "bench_command.hpp"
#include "contact_sheet_command.hpp"
#include "cost_command.hpp"
#include "develop_command.hpp"
#include "encode_command.hpp"
#include "monitor_command.hpp"
#include "farm_bench_command.hpp"
#include "transport/mpi_session.hpp"
#include "geodesic_command.hpp"
#include "plot_command.hpp"
#include "inspect_command.hpp"
#include "lua/table_reader.hpp"
#include "render/layers.hpp"
#include "script/constructor_docs.hpp"
#include "render_command.hpp"
#include "showcase_command.hpp"
#include "starfield_command.hpp"
#include "trace_command.hpp"

namespace {

// "hit.kind, hit.r, ...": every data layer's name (render/layers.hpp).
std::string layer_list() {
  std::string out;
  for (const lc::LayerSpec& l : lc::layers) out += (out.empty() ? "" : ", ") + std::string(l.name);
  return out;
}

// Whether a word on the command line is meant as a flag ("--frames",
// "-o"), not a value that happens to start with '-' ("-1").
bool looks_like_flag(const std::string& word) {
  auto letter = [](char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; };
  return word.size() >= 2 && word[0] == '-' && (letter(word[1]) || (word[1] == '-' && word.size() > 2 && letter(word[2])));
}

// "unknown option --fram (did you mean --frames?)": `name` among the flags
// `app` (the program, or one command) takes.
std::string unknown_flag(const CLI::App& app, const std::string& name) {
  std::vector<std::string> flags;
  for (const CLI::Option* o : app.get_options()) {
    for (const std::string& l : o->get_lnames()) flags.push_back("--" + l);
    for (const std::string& n : o->get_snames()) flags.push_back("-" + n);
  }
  const std::string near = lc::lua::nearest(name, flags);
  return fmt::format("unknown option {}{}", name, near.empty() ? "" : fmt::format(" (did you mean {}?)", near));
}

// The first word CLI11 could not place, said with what was probably meant
// (CLI11 names neither): an unknown command and the closest one, or an
// unknown flag and the closest flag.  "" when every command and flag is
// known (the error is about something else).  Also returns the chosen
// command, for the help hint.
std::pair<std::string, std::string> unknown_word(CLI::App& app, int argc, char** argv) {
  const std::vector<CLI::App*> commands = app.get_subcommands([](CLI::App*) { return true; });
  std::vector<std::string> names;
  for (const CLI::App* c : commands) names.push_back(c->get_name());
  int k = 1;
  for (; k < argc && argv[k][0] == '-'; ++k)  // the program's own flags (--help, --version)
    if (!app.get_option_no_throw(argv[k])) return {unknown_flag(app, argv[k]), ""};
  if (k == argc) return {fmt::format("no command given; the commands are {}", fmt::join(names, ", ")), ""};
  const std::string command = argv[k];
  const auto it = std::find(names.begin(), names.end(), command);
  if (it == names.end()) {
    const std::string near = lc::lua::nearest(command, names);
    return {fmt::format("unknown command '{}'{}; the commands are {}", command,
                        near.empty() ? "" : fmt::format(" (did you mean '{}'?)", near), fmt::join(names, ", ")),
            ""};
  }
  const CLI::App& chosen = *commands[static_cast<std::size_t>(it - names.begin())];
  for (int i = k + 1; i < argc; ++i) {
    const std::string word = argv[i];
    if (word == "--") break;
    if (!looks_like_flag(word)) continue;
    // "--out=x" names --out; "-ox" is -o with its value attached.
    const std::string name = word[1] == '-' ? word.substr(0, word.find('=')) : word.substr(0, 2);
    if (!chosen.get_option_no_throw(name)) return {command + ": " + unknown_flag(chosen, name), command};
  }
  return {"", command};
}

// One end of a numeric flag's range: its value and whether it is allowed.
struct End {
  double value;
  bool included = true;
};

// "from 1e-15 to 0.01 (both included)", "greater than 0", "at least 1".
std::string range_text(std::optional<End> lo, std::optional<End> hi) {
  auto low = [&] { return fmt::format("{} {:g}", lo->included ? "at least" : "greater than", lo->value); };
  auto high = [&] { return fmt::format("{} {:g}", hi->included ? "at most" : "less than", hi->value); };
  if (lo && hi) {
    if (lo->included && hi->included) return fmt::format("from {:g} to {:g} (both included)", lo->value, hi->value);
    return low() + " and " + high();
  }
  if (lo) return low();
  if (hi) return high();
  return "";
}

// The check every numeric flag takes (CLI11's Range lets NaN through, since
// every comparison with it is false, and prints its ends as %f, 1e-15 as
// 0.000000): the text must be a finite number, within [lo, hi] where given.
// The flag's own type (int, double) is still converted by CLI11 after it.
CLI::Validator number(std::optional<End> lo = std::nullopt, std::optional<End> hi = std::nullopt) {
  const std::string range = range_text(lo, hi);
  return CLI::Validator(
      [lo, hi, range](std::string& text) -> std::string {
        double v = 0.0;
        const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
        const std::string give = range.empty() ? "" : ": give a number " + range;
        if (end != text.data() + text.size() || (ec != std::errc() && ec != std::errc::result_out_of_range))
          return fmt::format("'{}' is not a number{}", text, give);
        if (ec == std::errc::result_out_of_range || !std::isfinite(v))
          return fmt::format("'{}' is not a finite number{}", text, give);
        if ((lo && (lo->included ? v < lo->value : v <= lo->value)) || (hi && (hi->included ? v > hi->value : v >= hi->value)))
          return fmt::format("{} is out of range{}", text, give);
        return "";
      },
      range.empty() ? "a finite number" : "a number " + range);
}

// The check of --png-depth (render's and showcase's): the text must be
// the integer 8 or 16 (CLI11's IsMember refused 16.0 with only "not in
// {8,16}").
CLI::Validator png_depth_bits() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        if (text == "8" || text == "16") return "";
        return fmt::format("'{}' is not a PNG depth: give the bits per channel as the integer 8 or 16", text);
      },
      "8 or 16");
}

// The delivery flags render and trace share (delivery_flags.hpp); `camera`
// is --camera's help, which says what the command does with it.  The ranges
// and the pairings (a dome's flags with the dome) are checked by
// delivery_from_flags, in words of the flag.
void add_delivery_flags(CLI::App* command, lc::DeliveryFlags& flags, const std::string& camera) {
  command->add_option("--camera", flags.camera, camera)->check(CLI::IsMember({"shot", "dome", "360", "ods"}));
  command->add_option("--dome-tilt", flags.dome_tilt,
                      "With --camera dome: the dome's forward tilt in degrees, 0 to 90 (default 0, a level dome; 15 is "
                      "the nominal tilted one)")
      ->check(number());
  command->add_option("--dome-elevation", flags.dome_elevation,
                      "With --camera dome: degrees above the dome's front horizon the shot's subject sits, 0 to 90 "
                      "(default 35, the seated audience's sweet spot; 90: the zenith)")
      ->check(number());
  command->add_option("--separation", flags.separation,
                      "With --camera ods: the distance between the eyes in M (default 1; docs/cameras.md)")
      ->check(number());
  command->add_option("--sky", flags.sky,
                      "kstars: the real stars (KStars' catalogue, Debian's kstars-data) in place of the shot's "
                      "generated ones or checker; default: the shot's (docs/cameras.md)")
      ->check(CLI::IsMember({"shot", "kstars"}));
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"lightcone: general-relativistic black-hole animation, traced along null geodesics", "lightcone"};
  // The version and whether (and with which MPI) the binary runs as a farm.
  app.set_version_flag("--version", [] { return std::string("lightcone ") + LIGHTCONE_VERSION + "\n" + lc::farm::mpi_description(); });
  app.require_subcommand(1);

  lc::GeodesicCommand geo;
  auto* geodesic = app.add_subcommand(
      "geodesic", "Trace one null or timelike geodesic described by a Lua spec and write its samples as CSV");
  geodesic->add_option("spec", geo.spec, "Geodesic spec script (docs/geodesic.md)")->required()->check(CLI::ExistingFile);
  geodesic->add_option("-o,--output", geo.output, "CSV file to write (default: standard output)");

  lc::PlotCommand plot;
  auto* plot_cmd = app.add_subcommand("plot", "Draw the curves of a `lightcone geodesic` CSV as a figure (SVG or PNG)");
  plot_cmd->add_option("csv", plot.csv, "CSV written by lightcone geodesic")->required()->check(CLI::ExistingFile);
  plot_cmd->add_option("-o,--output", plot.output, "Figure to write: FILE.svg or FILE.png")->required();
  // The charts by their CSV names, each with the spacetimes that use it
  // (from the registry: a new spacetime joins the help by itself).
  std::map<std::string, lc::SceneChart> charts;
  for (std::size_t c = 0; c < lc::csv_chart_names.size(); ++c)
    charts.emplace(lc::csv_chart_names[c], static_cast<lc::SceneChart>(c));
  plot_cmd
      ->add_option("--coordinates", plot.coordinates,
                   fmt::format("What the CSV's x1..x3 are when it does not say (a CSV written before lightcone "
                               "geodesic recorded its chart on its first line): {} (r, theta, phi: {}; the default) or "
                               "{} (x, y, z: {}); a CSV that records its chart needs none",
                               lc::csv_chart_name(lc::SceneChart::polar), lc::spacetimes_in_chart(lc::SceneChart::polar),
                               lc::csv_chart_name(lc::SceneChart::cartesian),
                               lc::spacetimes_in_chart(lc::SceneChart::cartesian)))
      ->transform(CLI::CheckedTransformer(charts));
  plot_cmd->add_option("--view", plot.view, "The plane drawn: xz (side view, the default), xy (from above) or yz")
      ->transform(CLI::CheckedTransformer(std::map<std::string, lc::PlotView>{
          {"xz", lc::PlotView::xz}, {"xy", lc::PlotView::xy}, {"yz", lc::PlotView::yz}}));
  plot_cmd->add_option("--size", plot.size, "Figure size WxH in pixels (default 800x600)");
  plot_cmd->add_option("--extent", plot.extent, "Half the width shown, in M (default: every point fits)")->check(number());
  plot_cmd->add_option("--disk", plot.disk,
                       "INNER:OUTER: draw an equatorial disk and end each ray where it first meets it, solid from its top "
                       "side, dashed from its bottom side");
  plot_cmd->add_option("--horizon", plot.horizon, "Radius of the black disc drawn for the hole (default: none)")->check(number());

  lc::RenderRequest render;
  auto* render_cmd = app.add_subcommand(
      "render", "Render frames of a shot to EXR and PNG with every core (or under mpirun, on every rank); resumes");
  render_cmd->add_option("shot", render.shot, "Shot script (docs/shots.md)")->required()->check(CLI::ExistingFile);
  render_cmd->add_option("-o,--out", render.out, "Output directory (created if missing)")->required();
  render_cmd->add_option("--frames", render.frames, "Frames A, A:B or A:B:STEP (inclusive, numbered from 0)");
  render_cmd->add_option("--size", render.size, "Image size WxH instead of the shot's");
  render_cmd->add_option("--scale", render.scale, "Scale the image size by S (previews: 0.25)")->check(number());
  add_delivery_flags(render_cmd, render.delivery,
                     "Deliver the shot through another camera, framed from its own: dome (a 180-degree dome master, "
                     "square), 360 (a 360-degree video frame, 2:1) or ods (360 in omnidirectional stereo, square); "
                     "default: the shot's (docs/cameras.md)");
  render_cmd->add_option("--region", render.region,
                         "Render only pixels X0..X1-1, Y0..Y1-1 of the frame (X0,Y0,X1,Y1), as an image of that size: "
                         "to check part of a large frame (docs/cameras.md)");
  render_cmd->add_option("--supersample", render.supersample, "N x N samples per pixel instead of the shot's")->check(number());
  render_cmd->add_flag("--full-supersample", render.full_supersample,
                       "Trace every sample of the N x N grid (default: one per pixel, the rest only where it differs from a row neighbour's)");
  render_cmd->add_flag("--no-reuse", render.no_reuse,
                       "Trace every sample of every frame (default: frames that differ only in time reuse the rays that cannot change)");
  render_cmd->add_flag("--layers", render.layers, "Add the data layers (" + layer_list() + ") to the EXR: docs/layers.md");
  render_cmd->add_option("--threads", render.threads, "Render threads per process (default: every core; under mpirun the node's share)")
      ->check(number(End{1}, End{1024}));
  render_cmd->add_option("--stripes", render.stripes, "Working sets per frame: interleaved row stripes (default 512, at most the image height)")
      ->check(number());
  render_cmd->add_option("--preview", render.preview, "Render every K-th stripe of every frame first, as DIR/preview/*.png")
      ->check(number());
  render_cmd->add_flag("--force", render.force, "Resume even if the shot or settings changed: re-render the frames that differ");
  render_cmd
      ->add_option("--png-depth", render.png_bits,
                   "Bits per channel of the PNG frames: 8 (the default) or 16 (dome masters: docs/cameras.md)")
      ->check(png_depth_bits());
  render_cmd
      ->add_option("--shutter", render.shutter,
                   "Motion blur: the shutter open this share of each frame interval, 0 to 1 (0.5: the film camera's "
                   "180 degrees; 0: closed), over the shot's and its frames' own (docs/motion_blur.md)");
  render_cmd->add_option("--shutter-position", render.shutter_position,
                         "Where the open shutter lies against each frame's moment: centre (the default), start or "
                         "end, over the shot's");
  render_cmd->add_option("--time-samples", render.time_samples,
                         "Instants the open shutter is cut into (the shot's `time_samples`, default 8): each a scene, "
                         "and at least that many samples in a pixel sampled in full");
  render_cmd->add_option("--progress", render.progress,
                         "Seconds between progress lines when stderr is not a terminal (default 5; 0: none)")
      ->check(number());

  lc::FarmBenchCommand farm_bench;
  auto* farm_bench_cmd = app.add_subcommand(
      "farm-bench", "Time the render farm alone (working sets that cost nothing; run under mpirun for the master)");
  farm_bench_cmd->add_option("--size", farm_bench.size, "Image size WxH (default 1280x720)");
  farm_bench_cmd->add_option("--stripes", farm_bench.stripes, "Working sets per frame (default 512)")->check(number(End{1}, End{16384}));
  farm_bench_cmd->add_option("--frames", farm_bench.frames, "Frames (default 16)")->check(number(End{1}, End{100000}));
  farm_bench_cmd->add_flag("--layers", farm_bench.layers, "Send the data layers too");
  farm_bench_cmd->add_option("--threads", farm_bench.threads, "Worker threads per process")->check(number(End{1}, End{1024}));

  lc::InspectCommand inspect;
  auto* inspect_cmd = app.add_subcommand("inspect", "Print the evaluated scene of each frame as JSON, without rendering");
  inspect_cmd->add_option("shot", inspect.shot, "Shot script")->required()->check(CLI::ExistingFile);
  inspect_cmd->add_option("--frames", inspect.frames, "Frames A, A:B or A:B:STEP (inclusive, numbered from 0)");

  lc::CostCommand cost;
  auto* cost_cmd = app.add_subcommand(
      "cost", "What the frames of render directories cost, from their journals: core-seconds, samples traced and reused");
  cost_cmd->add_option("dirs", cost.dirs, "Render output directories (a render's --out)")->required();
  cost_cmd->add_option("--csv", cost.csv, "Also write one CSV row per frame to this file");

  lc::TraceCommand trace;
  auto* fields_cmd = app.add_subcommand(
      "fields", "Print every scene constructor lc.<name>{...} with its fields, defaults and ranges (Markdown)");

  auto* trace_cmd = app.add_subcommand("trace", "Follow the ray through one pixel: its path as CSV and what it hit");
  trace_cmd->add_option("shot", trace.shot, "Shot script")->required()->check(CLI::ExistingFile);
  trace_cmd->add_option("--frame", trace.frame, "Frame number (from 0)")->required()->check(number());
  trace_cmd->add_option("--pixel", trace.pixel, "Pixel I,J (column from the left, row from the top)")->required();
  trace_cmd->add_option("-o,--output", trace.output, "CSV file to write (default: standard output)");
  trace_cmd->add_option("--size", trace.size, "Image size WxH instead of the shot's");
  trace_cmd->add_option("--scale", trace.scale, "Scale the image size by S")->check(number());
  add_delivery_flags(trace_cmd, trace.delivery,
                     "The pixel of the frame delivered through a dome master, a 360-degree camera or ODS (as render "
                     "--camera, with its --dome-tilt, --dome-elevation, --separation and --sky)");
  trace_cmd->add_flag("--json", trace.json,
                      "Print the report as one JSON object on standard output (the path then only with -o)");

  lc::StarfieldCommand starfield;
  auto* starfield_cmd = app.add_subcommand("starfield", "Write the procedural star field as an equirectangular PNG");
  starfield_cmd->add_option("-o,--output", starfield.output, "PNG file to write")->required();
  starfield_cmd->add_option("--width", starfield.width, "Width in pixels (height is half)")->check(number());
  starfield_cmd->add_option("--seed", starfield.seed, "Catalogue seed")->check(number());

  lc::EncodeCommand encode;
  auto* encode_cmd = app.add_subcommand(
      "encode", "Encode a shot's PNG frames to video (H.264 MP4 by default), join videos, or make a title card");
  encode_cmd->add_option("inputs", encode.inputs, "Frame directory; with --concat, the videos to join in order");
  encode_cmd->add_option("-o,--output", encode.output, "Video file to write (.mp4, .mov, .mkv, .webm)")->required();
  encode_cmd->add_option("--fps", encode.fps, "Frames per second: 30, 29.97 or a fraction such as 30000/1001 (default: the shot's if recorded, else 30)");
  encode_cmd->add_option("--crf", encode.crf, "Constant quality: lower is better (default h264 18, hevc 22, vp9 24, av1 30)")
      ->check(number());
  encode_cmd->add_option("--codec", encode.codec, "h264 (default), hevc, vp9, av1 or prores");
  encode_cmd->add_option("--preset", encode.preset,
                         "Speed/quality: x264/x265 preset (default medium), vp9/av1 speed number, prores profile");
  encode_cmd->add_option("--shot", encode.shot, "The shot whose frames to encode when DIR holds several");
  encode_cmd->add_flag("--allow-stale", encode.allow_stale,
                       "Encode frames rendered from another version of the shot or other settings than the latest render");
  encode_cmd->add_flag("--concat", encode.concat, "Join the videos given, without re-encoding");
  encode_cmd->add_option("--title", encode.title, "Make a title card: one line of text (repeat for more lines)");
  encode_cmd->add_option("--size", encode.size, "Title card size WxH");
  encode_cmd->add_option("--seconds", encode.seconds, "Title card length in seconds (default 3)")->check(number());

  lc::DevelopCommand develop;
  auto* develop_cmd = app.add_subcommand(
      "develop", "Make a rendered shot's PNGs again from its EXRs through another look (exposure, view, white balance, "
                 "saturation, bloom), without tracing: docs/light.md");
  develop_cmd->add_option("dir", develop.dir, "The render's output directory")->required();
  develop_cmd->add_option("--shot", develop.shot, "The shot when DIR holds several");
  develop_cmd->add_option("--frames", develop.frames, "Frames A, A:B or A:B:STEP (default: every finished frame)");
  for (const lc::LookFlag& f : lc::look_flags())
    develop_cmd->add_option(f.flag, develop.look[f.field],
                            f.help + (f.field == "exposure" ? "; replaces every frame's own (see --exposure-shift)" : ""));
  develop_cmd->add_option("--exposure-shift", develop.exposure_shift,
                          "Stops added to the exposure each frame was rendered with (its own, its shot's or the "
                          "metered one), never to the last develop's: running it again shifts nothing more")
      ->check(number());
  develop_cmd->add_flag("--reset", develop.reset,
                        "Start each frame from the look the render made it with, not the last develop's (with no look "
                        "flag: the render's PNGs back)");
  develop_cmd->add_option("--out", develop.out,
                          "Write the developed PNGs into this folder instead (created if missing), leaving DIR's frames "
                          "and journal as they are, so two looks sit side by side");
  develop_cmd->add_option("--threads", develop.threads, "Frames developed at once (default: every core)")
      ->check(number(End{1}, End{1024}));

  lc::MonitorCommand monitor;
  auto* monitor_cmd = app.add_subcommand(
      "monitor", "Serve a web page of the renders in the folders given, live while they render (read only): "
                 "docs/monitor.md");
  monitor_cmd->add_option("dirs", monitor.dirs, "Render output folders (render --out)")->required();
  monitor_cmd->add_option("--port", monitor.port, "TCP port (default 8765; 0: any free port, printed)")
      ->check(number(End{0}, End{65535}));
  monitor_cmd->add_option("--bind", monitor.bind,
                          "Address to listen on (default 127.0.0.1: this machine only; see docs/monitor.md before "
                          "opening it to others)");

  lc::ContactSheetCommand sheet;
  auto* sheet_cmd = app.add_subcommand("contact-sheet", "Write a PNG grid of frames picked evenly across a shot");
  sheet_cmd->add_option("dir", sheet.dir, "Frame directory")->required();
  sheet_cmd->add_option("-o,--output", sheet.output, "PNG file to write")->required();
  sheet_cmd->add_option("--columns", sheet.columns, "Frames per row (default 4)")->check(number());
  sheet_cmd->add_option("--width", sheet.width, "Sheet width in pixels (default 1280)")->check(number());
  sheet_cmd->add_option("--count", sheet.count, "Frames shown at most (default 16)")->check(number());
  sheet_cmd->add_option("--shot", sheet.shot, "The shot when DIR holds several");
  sheet_cmd->add_flag("--allow-stale", sheet.allow_stale,
                      "Show frames rendered from another version of the shot or other settings than the latest render");

  lc::BenchCommand bench;
  auto* bench_cmd = app.add_subcommand(
      "bench", "Measure rays per core-second and accuracy against a tight reference on the benchmark shots");
  bench_cmd->add_option("--shot", bench.shots, "Benchmark shot (repeatable; default: shots/bench/*.lua)")
      ->check(CLI::ExistingFile);
  bench_cmd->add_option("--threads", bench.threads, "Threads for the parallel run (default: every core)")
      ->check(number(End{1}, End{1024}));
  bench_cmd->add_option("--repeats", bench.repeats, "Best of this many runs")->check(number(End{1}, End{100}));
  bench_cmd->add_option("--seconds", bench.seconds,
                        "Each timed run traces the image again until this many seconds have passed (default: once)")
      ->check(number(End{0}, End{3600}));
  bench_cmd->add_option("--tolerance", bench.tolerance, "Integrator tolerance to measure (default: production)")
      ->check(number(End{1e-15}, End{1e-2}));
  bench_cmd->add_option("--kerr-chart", bench.kerr_chart,
                        "How Kerr rays are integrated: bl-mino (default; Boyer-Lindquist, Mino time) or kerr-schild");
  bench_cmd->add_option("--reference-tolerance", bench.reference_tolerance,
                        "Integrator tolerance of the reference render")
      ->check(number(End{1e-15}, End{1e-6}));

  lc::ShowcaseCommand showcase;
  auto* showcase_cmd = app.add_subcommand(
      "showcase", "Render, encode and join the paper's three sequences into showcase.mp4 (resumable; runs under mpirun)");
  showcase_cmd->add_option("--quality", showcase.quality,
                           "preview (the default: 256x144, 3 frames per second of story; minutes) or production (the paper's settings)");
  showcase_cmd->add_option("--size", showcase.size,
                           "Image size WxH instead of the quality's (preview 256x144, production the shots'; with "
                           "--camera dome 256x256 and 4096x4096, with --camera 360 384x192 and 4096x2048)");
  showcase_cmd->add_option("--rate", showcase.rate, "Preview only: frames per second of story (default 3; the video plays at this rate)")
      ->check(number());
  showcase_cmd->add_option("-o,--out", showcase.out,
                           "Output directory (default out/showcase/<quality>, or <quality>-dome, <quality>-360; "
                           "-blur added with --motion-blur)");
  showcase_cmd
      ->add_option("--png-depth", showcase.png_bits, "Bits per channel of the frames' PNGs: 8 (the default) or 16 (as render)")
      ->check(png_depth_bits());
  showcase_cmd->add_flag("--motion-blur", showcase.motion_blur,
                         "Blur motion as a film camera does: every shot's shutter open half of each frame interval "
                         "(render --shutter 0.5; into <quality>-blur: docs/motion_blur.md)");
  showcase_cmd->add_option("--shots", showcase.shots, "Folder holding the three shot scripts (default: the project's shots/)")
      ->check(CLI::ExistingDirectory);
  showcase_cmd->add_option("--threads", showcase.threads, "Render threads per process (as render --threads)")
      ->check(number(End{1}, End{1024}));
  showcase_cmd->add_flag("--force", showcase.force, "Re-render frames made from other settings or inputs (as render --force)");
  showcase_cmd
      ->add_option("--camera", showcase.camera,
                   "Through a dome master (dome: square, the hole above the dome's front horizon) or a 360-degree "
                   "camera (360: 2:1, marked for players) instead of the shots' own (docs/showcase.md)")
      ->check(CLI::IsMember({"shot", "dome", "360"}));
  showcase_cmd->add_flag("--thermal", showcase.thermal,
                         "Add a fourth sequence: the first in light as physics says (kerr_accrDisk_thermal; docs/light.md)");
  showcase_cmd->add_option("--progress", showcase.progress, "Seconds between plain progress lines (0: none)")->check(number());

  // Usage errors in the form of every other error, with a suggestion for a
  // mistyped command or flag and where to find the right ones.
  app.failure_message([&app, argc, argv](const CLI::App*, const CLI::Error& e) {
    const auto [unknown, command] = unknown_word(app, argc, argv);
    return fmt::format("lightcone: error: {}\nRun 'lightcone{} --help' for the {}.\n", unknown.empty() ? e.what() : unknown,
                       command.empty() ? "" : " " + command, command.empty() ? "commands" : "options");
  });
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }

  try {
    if (*geodesic) return lc::run_geodesic(geo);
    if (*plot_cmd) return lc::run_plot(plot);
    if (*render_cmd) return lc::run_render(render);
    if (*farm_bench_cmd) return lc::run_farm_bench(farm_bench);
    if (*inspect_cmd) return lc::run_inspect(inspect);
    if (*cost_cmd) return lc::run_cost(cost);
    if (*fields_cmd) {
      fmt::print("{}", lc::constructor_tables());
      return 0;
    }
    if (*trace_cmd) return lc::run_trace(trace);
    if (*starfield_cmd) return lc::run_starfield(starfield);
    if (*encode_cmd) return lc::run_encode(encode);
    if (*sheet_cmd) return lc::run_contact_sheet(sheet);
    if (*monitor_cmd) return lc::run_monitor(monitor);
    if (*develop_cmd) {
      std::erase_if(develop.look, [](const auto& kv) { return kv.second.empty(); });  // flags not given
      return lc::run_develop(develop);
    }
    if (*bench_cmd) return lc::run_bench(bench);
    if (*showcase_cmd) return lc::run_showcase(showcase);
  } catch (const std::exception& e) {
    fmt::print(stderr, "lightcone: error: {}\n", e.what());
    return 1;
  }
  return 0;
}

#include "monitor/pixel_trace.hpp"

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

extern char** environ;

namespace lc::monitor {

namespace fs = std::filesystem;

namespace {

// The trace runs at this niceness (nice(1)'s scale): a render on the same
// node keeps its CPUs, the trace takes what they leave.
constexpr int trace_niceness = 10;
// coreutils' nice, which sets the niceness and then runs the trace, so the
// trace never runs a moment at the monitor's priority.
constexpr const char* nice_program = "/usr/bin/nice";

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// A scratch directory of the child's output, removed when done.
struct Scratch {
  fs::path dir;
  Scratch() {
    std::string pattern = (fs::temp_directory_path() / "lightcone-monitor-XXXXXX").string();
    if (!::mkdtemp(pattern.data())) throw std::runtime_error(fmt::format("cannot make a temporary directory: {}", std::strerror(errno)));
    dir = pattern;
  }
  ~Scratch() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
};

// The CSV's path as [[x, y, z], ...]: Cartesian columns as they are, a
// Boyer–Lindquist path (chart "bl") converted.
std::string path_json(const std::string& csv, std::string& chart) {
  std::istringstream in(csv);
  std::string line, out;
  bool polar = false;
  while (std::getline(in, line)) {
    if (line.rfind("# chart:", 0) == 0) {
      chart = line.substr(9);
      polar = chart.rfind("bl", 0) == 0;
      continue;
    }
    if (line.empty() || line[0] == '#' || line.rfind("lambda", 0) == 0) continue;
    std::vector<double> v;
    std::istringstream cells(line);
    for (std::string c; std::getline(cells, c, ',');) v.push_back(std::strtod(c.c_str(), nullptr));
    if (v.size() < 5) continue;
    double x = v[2], y = v[3], z = v[4];
    if (polar) {
      const double r = v[2], th = v[3], ph = v[4];
      x = r * std::sin(th) * std::cos(ph);
      y = r * std::sin(th) * std::sin(ph);
      z = r * std::cos(th);
    }
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) continue;
    out += fmt::format("{}[{:.6g}, {:.6g}, {:.6g}]", out.empty() ? "" : ", ", x, y, z);
  }
  return "[" + out + "]";
}

}  // namespace

std::vector<std::string> delivery_flag_words(const Delivery& d) {
  std::vector<std::string> out = {"--camera", std::string(name_of(d.camera))};
  // fmt's shortest text of a double reads back to the same double.
  if (d.dome_tilt != default_dome_tilt) out.insert(out.end(), {"--dome-tilt", fmt::format("{}", d.dome_tilt)});
  if (d.dome_elevation != default_dome_elevation)
    out.insert(out.end(), {"--dome-elevation", fmt::format("{}", d.dome_elevation)});
  if (d.separation != default_ods_separation) out.insert(out.end(), {"--separation", fmt::format("{}", d.separation)});
  if (d.sky != DeliverySky::shot) out.insert(out.end(), {"--sky", std::string(name_of(d.sky))});
  return out;
}

std::string trace_pixel_json(const fs::path& tracer, const PixelRequest& r, double seconds) {
  const Scratch scratch;
  const fs::path out = scratch.dir / "report.json", err = scratch.dir / "stderr.txt", csv = scratch.dir / "path.csv";
  std::vector<std::string> args = {"nice",    "-n",      std::to_string(trace_niceness),
                                   tracer.string(), "trace", r.script.string(),
                                   "--frame", std::to_string(r.frame), "--pixel",
                                   fmt::format("{},{}", r.x, r.y), "--size", fmt::format("{}x{}", r.width, r.height),
                                   "--json", "-o", csv.string()};
  for (std::string& word : delivery_flag_words(r.delivery)) args.push_back(std::move(word));
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, nice_program, &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) throw std::runtime_error(fmt::format("cannot run {}: {}", nice_program, std::strerror(spawned)));
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  int status = 0;
  while (::waitpid(pid, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() > deadline) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      throw std::runtime_error(fmt::format("the trace took longer than {:g} s and was stopped", seconds));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::string why = slurp(err);
    while (!why.empty() && why.back() == '\n') why.pop_back();
    throw std::runtime_error(why.empty() ? "the trace failed" : why);
  }
  std::string report = slurp(out);
  while (!report.empty() && report.back() == '\n') report.pop_back();
  std::string chart;
  const std::string path = path_json(slurp(csv), chart);
  std::string chart_json = "\"";
  for (char c : chart) chart_json += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
  return fmt::format("{{\"report\": {}, \"chart\": {}\", \"path\": {}}}\n", report, chart_json, path);
}

}  // namespace lc::monitor

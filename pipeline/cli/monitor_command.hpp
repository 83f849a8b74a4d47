#pragma once
// `lightcone monitor DIR... [--port N] [--bind ADDRESS]`: a web page of the
// renders in the folders given, live while they render and after
// (docs/monitor.md).  It only reads the folders (monitor/monitor_api.hpp)
// and binds to the loopback address unless told otherwise.

#include <filesystem>
#include <string>
#include <vector>

namespace lc {

struct MonitorCommand {
  std::vector<std::filesystem::path> dirs;
  int port = 8765;                    // 0: any free port
  std::string bind = "127.0.0.1";
};

int run_monitor(const MonitorCommand& cmd);

}  // namespace lc

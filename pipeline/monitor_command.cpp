#include "monitor_command.hpp"

#include <chrono>
#include <stdexcept>
#include <thread>

#include <fmt/format.h>
#include <httplib.h>

#include "interrupt.hpp"
#include "monitor/monitor_api.hpp"

namespace lc {

namespace {

bool loopback(const std::string& address) {
  return address == "127.0.0.1" || address == "::1" || address == "localhost" || address.rfind("127.", 0) == 0;
}

}  // namespace

int run_monitor(const MonitorCommand& cmd) {
  // Input: the folders and where to listen; output: the server, until
  // Ctrl-C.  Every GET goes to the API; nothing else is answered.
  if (cmd.port < 0 || cmd.port > 65535) throw std::invalid_argument(fmt::format("--port {}: must be 0 to 65535", cmd.port));
  // The pixel inspector runs this very binary's `trace` (monitor/pixel_trace.hpp).
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  const monitor::MonitorApi api(cmd.dirs, ec ? std::filesystem::path{} : self);
  httplib::Server server;
  server.Get(".*", [&api](const httplib::Request& req, httplib::Response& res) {
    monitor::Query query;
    for (const auto& [k, v] : req.params) query.emplace(k, v);
    const monitor::Reply reply = api.get(req.path, query);
    res.status = reply.status;
    res.set_header("Cache-Control", "no-store");
    res.set_header("X-Content-Type-Options", "nosniff");
    res.set_content(reply.body, reply.content_type.c_str());
  });
  // Anything but GET (and HEAD, which httplib answers from GET) is refused.
  const auto refuse = [](const httplib::Request&, httplib::Response& res) {
    const monitor::Reply r = monitor::error_reply(405, "the monitor only reads: GET");
    res.status = r.status;
    res.set_content(r.body, r.content_type.c_str());
  };
  server.Post(".*", refuse);
  server.Put(".*", refuse);
  server.Delete(".*", refuse);
  server.Patch(".*", refuse);
  server.set_payload_max_length(64 * 1024);
  // httplib's default also sets SO_REUSEPORT, with which a second monitor
  // on a port in use would share it silently (each answering some of the
  // requests): only SO_REUSEADDR, so a port in use is refused.
  server.set_socket_options([](socket_t sock) {
    int yes = 1;
    ::setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  });

  const int port = cmd.port == 0 ? server.bind_to_any_port(cmd.bind) : (server.bind_to_port(cmd.bind, cmd.port) ? cmd.port : -1);
  if (port < 0)
    throw std::runtime_error(fmt::format("--bind {} --port {}: cannot listen there (in use, or not an address of this "
                                         "machine); try another --port, or --port 0 for any free one",
                                         cmd.bind, cmd.port));
  fmt::print(stderr, "monitor: {} folder{} at http://{}:{}/ (Ctrl-C to stop)\n", api.folders().size(),
             api.folders().size() == 1 ? "" : "s", cmd.bind.find(':') != std::string::npos ? "[" + cmd.bind + "]" : cmd.bind,
             port);
  if (!loopback(cmd.bind))
    fmt::print(stderr,
               "monitor: warning: listening on {}, not only this machine: anyone who can reach it sees the frames and "
               "the folders' paths. Prefer the default 127.0.0.1 and an ssh tunnel (docs/monitor.md)\n",
               cmd.bind);
  InterruptGuard guard;
  std::thread watcher([&server, &guard] {
    while (guard.signal() == 0 && !server.is_running()) std::this_thread::sleep_for(std::chrono::milliseconds(20));
    while (guard.signal() == 0 && server.is_running()) std::this_thread::sleep_for(std::chrono::milliseconds(100));
    server.stop();
  });
  const bool ok = server.listen_after_bind();
  server.stop();
  watcher.join();
  if (guard.signal()) {
    fmt::print(stderr, "monitor: stopped by {}\n", signal_name(guard.signal()));
    return 0;
  }
  if (!ok) throw std::runtime_error("monitor: the server stopped listening");
  return 0;
}

}  // namespace lc

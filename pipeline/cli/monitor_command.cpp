#include "monitor_command.hpp"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <thread>

#include <netdb.h>
#include <sys/socket.h>
#include <unistd.h>

#include <fmt/format.h>
#include <microhttpd.h>

#include "interrupt.hpp"
#include "monitor/folder_file.hpp"
#include "monitor/monitor_api.hpp"
#include "monitor/reply_budget.hpp"

namespace lc {

namespace {

using Clock = std::chrono::steady_clock;

// What one client may cost the monitor (docs/monitor.md, "Safe by
// default").  libmicrohttpd holds a request's line and header lines in the
// connection's own memory: a head larger than this is answered 431 and the
// connection closed.
constexpr std::size_t connection_memory_bytes = 32 * 1024;
constexpr unsigned max_connections = 64;
// A connection that sends or takes nothing for this long is closed
// (libmicrohttpd's timeout, reset by every byte).
constexpr unsigned idle_timeout_seconds = 10;
// From a connection's opening (or its last answer) to the end of a
// request's head, whatever trickles in meanwhile: a client sending a
// header line every few seconds is closed after this.
constexpr auto head_deadline = std::chrono::seconds(5);
// The threads that poll the connections and answer the requests (all but
// the pixel inspector's, which run on a thread of their own).
constexpr unsigned polling_threads = 4;
// What the answers built in memory (JSON, layer pictures, traces) may
// hold at once, until their clients have read them (monitor/reply_budget.hpp):
// beyond it a request is answered 503 at once.  Files are sent from disk
// and not counted: 64 clients that never read a 512 MB frame each would
// otherwise pin 32 GB.
constexpr std::size_t reply_memory_bytes = 256u << 20;
// The 503's Retry-After, in seconds.
constexpr const char* busy_retry_after = "1";

bool loopback(const std::string& address) {
  return address == "127.0.0.1" || address == "::1" || address == "localhost" || address.rfind("127.", 0) == 0;
}

// One connection's wait for a request's head: since when, and whether it
// is waiting (between requests, or in a head) or being answered.
struct HeadWait {
  int fd = -1;
  Clock::time_point since = Clock::now();
  bool waiting = true;
  bool cut = false;
};

// An /api/trace request being answered on a thread of its own (the
// connection suspended meanwhile, so a trace holds no polling thread).
struct Pending {
  std::thread worker;
  monitor::Reply reply;
  std::string range;  // the request's Range header
  std::atomic<bool> done{false};
};

// A body built in memory, held by its libmicrohttpd response: its bytes
// taken from the server's budget, given back as the response is freed.
struct HeldBody {
  std::string bytes;
  monitor::ReplyBudget* budget;
  ~HeldBody() { budget->give(bytes.size()); }
  static void free(void* cls) { delete static_cast<HeldBody*>(cls); }
};

// The HTTP server over the monitor's API, on libmicrohttpd: every request
// is a GET or HEAD without a body (anything else is refused before a byte
// of it is read), each connection's memory and time are bounded, and slow
// clients hold no thread (an internal epoll thread pool).  Range requests:
// one range is answered 206 with that part, several are refused (416)
// (monitor::with_range).  A file is sent from its descriptor as the client
// reads; the bodies built in memory hold at most reply_memory_bytes at once.
class Server {
 public:
  // Inputs: the API (outliving the server), the address and port (0: any
  // free one).  Throws std::runtime_error when it cannot listen there.
  Server(const monitor::MonitorApi& api, const std::string& bind, int port)
      : api_(api),
        budget_(reply_memory_bytes),
        busy_body_(monitor::error_reply(503, fmt::format("the monitor holds {} MiB of answers that their clients have "
                                                         "not read yet: try again in a moment",
                                                         reply_memory_bytes >> 20))
                       .body) {
    addrinfo hints{};
    hints.ai_family = AF_UNSPEC;
    hints.ai_socktype = SOCK_STREAM;
    hints.ai_flags = AI_PASSIVE | AI_NUMERICSERV;
    addrinfo* found = nullptr;
    const std::string service = std::to_string(port);
    if (::getaddrinfo(bind.c_str(), service.c_str(), &hints, &found) != 0 || !found) throw_cannot_listen(bind, port);
    const std::unique_ptr<addrinfo, void (*)(addrinfo*)> address(found, ::freeaddrinfo);
    const unsigned flags = MHD_USE_AUTO_INTERNAL_THREAD | MHD_ALLOW_SUSPEND_RESUME |
                           (found->ai_family == AF_INET6 ? MHD_USE_IPv6 : 0);
    // libmicrohttpd's default sets SO_REUSEADDR alone (not SO_REUSEPORT,
    // with which a second monitor would share a port in use silently).
    daemon_ = MHD_start_daemon(
        flags, static_cast<std::uint16_t>(port), nullptr, nullptr, &Server::answer, this, MHD_OPTION_SOCK_ADDR,
        found->ai_addr, MHD_OPTION_THREAD_POOL_SIZE, polling_threads, MHD_OPTION_CONNECTION_LIMIT, max_connections,
        MHD_OPTION_CONNECTION_MEMORY_LIMIT, connection_memory_bytes, MHD_OPTION_CONNECTION_TIMEOUT,
        idle_timeout_seconds, MHD_OPTION_NOTIFY_CONNECTION, &Server::connection_event, this,
        MHD_OPTION_NOTIFY_COMPLETED, &Server::completed, this, MHD_OPTION_END);
    if (!daemon_) throw_cannot_listen(bind, port);
    const MHD_DaemonInfo* info = MHD_get_daemon_info(daemon_, MHD_DAEMON_INFO_BIND_PORT);
    port_ = info ? info->port : port;
    watchman_ = std::thread([this] { cut_slow_heads(); });
  }

  // Waits for the traces being answered (each cut off after 60 s), then
  // stops: libmicrohttpd must not be stopped with a connection suspended.
  ~Server() {
    {
      std::unique_lock lock(mutex_);
      closing_ = true;  // no trace is suspended from now on
      traces_done_.wait(lock, [this] { return traces_ == 0; });
      stopping_ = true;
    }
    watch_.notify_all();
    watchman_.join();
    MHD_stop_daemon(daemon_);
  }

  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  // The port it listens on (the one chosen, for --port 0).
  int port() const { return port_; }

 private:
  [[noreturn]] static void throw_cannot_listen(const std::string& bind, int port) {
    throw std::runtime_error(fmt::format("--bind {} --port {}: cannot listen there (in use, or not an address of this "
                                         "machine); try another --port, or --port 0 for any free one",
                                         bind, port));
  }

  // A connection opened or closed: its head wait is kept from one to the
  // other (closed is said before libmicrohttpd closes the socket, so the
  // watchman never shuts another connection's).
  static void connection_event(void* cls, MHD_Connection* c, void** socket_context, MHD_ConnectionNotificationCode code) {
    auto* self = static_cast<Server*>(cls);
    const std::lock_guard lock(self->mutex_);
    if (code == MHD_CONNECTION_NOTIFY_STARTED) {
      const MHD_ConnectionInfo* info = MHD_get_connection_info(c, MHD_CONNECTION_INFO_CONNECTION_FD);
      auto wait = std::make_unique<HeadWait>();
      wait->fd = info ? info->connect_fd : -1;
      *socket_context = wait.get();
      self->waits_.emplace(wait.get(), std::move(wait));
    } else if (*socket_context) {
      self->waits_.erase(static_cast<HeadWait*>(*socket_context));
      *socket_context = nullptr;
    }
  }

  // Marks the connection's head received (`waiting` false) or its answer
  // sent (waiting for the next head from now).
  void set_waiting(MHD_Connection* c, bool waiting) {
    const MHD_ConnectionInfo* info = MHD_get_connection_info(c, MHD_CONNECTION_INFO_SOCKET_CONTEXT);
    const std::lock_guard lock(mutex_);
    if (!info || !info->socket_context) return;
    auto* wait = static_cast<HeadWait*>(info->socket_context);
    wait->waiting = waiting;
    wait->since = Clock::now();
  }

  // A request answered (or given up): its trace, if any, is freed, and the
  // connection waits for its next head.
  static void completed(void* cls, MHD_Connection* c, void** req_cls, MHD_RequestTerminationCode) {
    auto* self = static_cast<Server*>(cls);
    if (auto* pending = static_cast<Pending*>(*req_cls)) {
      if (pending->worker.joinable()) pending->worker.join();
      delete pending;
      *req_cls = nullptr;
    }
    self->set_waiting(c, true);
  }

  // The watchman: shuts the socket of each connection whose head has taken
  // longer than head_deadline (libmicrohttpd then closes it); its timeout
  // alone would wait for ever on a client sending a byte now and then.
  void cut_slow_heads() {
    std::unique_lock lock(mutex_);
    while (!stopping_) {
      watch_.wait_for(lock, std::chrono::milliseconds(250));
      const auto now = Clock::now();
      for (auto& [key, wait] : waits_)
        if (wait->waiting && !wait->cut && wait->fd >= 0 && now - wait->since > head_deadline) {
          ::shutdown(wait->fd, SHUT_RDWR);
          wait->cut = true;
        }
    }
  }

  // Queues `ranged` (with the headers every answer has, and `extra`) as the
  // answer of the request on `c`; libmicrohttpd's verdict.  A file's
  // descriptor goes to libmicrohttpd, which reads it as the socket drains
  // and closes it with the response; a body built in memory is moved into
  // the response if the budget has room for it, else the answer is a 503.
  MHD_Result queue(MHD_Connection* c, monitor::Reply reply, const std::map<std::string, std::string>& extra = {}) {
    return queue(c, monitor::RangedReply{std::move(reply), ""}, extra);
  }
  MHD_Result queue(MHD_Connection* c, monitor::RangedReply ranged, const std::map<std::string, std::string>& extra = {}) {
    monitor::Reply& reply = ranged.reply;
    MHD_Response* response = nullptr;
    if (reply.file) {
      const int fd = reply.file->release();
      response = MHD_create_response_from_fd_at_offset64(reply.file_length, fd, reply.file_offset);
      if (!response) {
        ::close(fd);
        return MHD_NO;
      }
    } else {
      const std::size_t size = reply.body.size();
      if (size > budget_.capacity())
        return queue(c, monitor::error_reply(500, fmt::format("the answer would be {} bytes, more than the monitor holds "
                                                              "at once ({} MiB)",
                                                              size, budget_.capacity() >> 20)));
      if (!budget_.take(size)) {
        response = MHD_create_response_from_buffer(busy_body_.size(), const_cast<char*>(busy_body_.data()),
                                                   MHD_RESPMEM_PERSISTENT);
        if (!response) return MHD_NO;
        return send(c, MHD_HTTP_SERVICE_UNAVAILABLE, response, "application/json", "",
                    {{MHD_HTTP_HEADER_RETRY_AFTER, busy_retry_after}});
      }
      auto* held = new HeldBody{std::move(reply.body), &budget_};
      response = MHD_create_response_from_buffer_with_free_callback_cls(held->bytes.size(), held->bytes.data(),
                                                                       &HeldBody::free, held);
      if (!response) {
        delete held;
        return MHD_NO;
      }
    }
    return send(c, static_cast<unsigned>(reply.status), response, reply.content_type, ranged.content_range, extra);
  }

  // Adds the headers every answer has (and `extra`) to `response`, queues
  // it with `status` and lets go of it (libmicrohttpd keeps it until sent).
  static MHD_Result send(MHD_Connection* c, unsigned status, MHD_Response* response, const std::string& content_type,
                         const std::string& content_range, const std::map<std::string, std::string>& extra) {
    MHD_add_response_header(response, MHD_HTTP_HEADER_CONTENT_TYPE, content_type.c_str());
    MHD_add_response_header(response, MHD_HTTP_HEADER_CACHE_CONTROL, "no-store");
    MHD_add_response_header(response, "X-Content-Type-Options", "nosniff");
    MHD_add_response_header(response, MHD_HTTP_HEADER_ACCEPT_RANGES, "bytes");
    if (!content_range.empty()) MHD_add_response_header(response, MHD_HTTP_HEADER_CONTENT_RANGE, content_range.c_str());
    for (const auto& [name, value] : extra) MHD_add_response_header(response, name.c_str(), value.c_str());
    const MHD_Result queued = MHD_queue_response(c, status, response);
    MHD_destroy_response(response);
    return queued;
  }

  // One query argument (unescaped by libmicrohttpd; no value: "") into the
  // Query `cls`.
  static MHD_Result add_argument(void* cls, MHD_ValueKind, const char* key, const char* value) {
    static_cast<monitor::Query*>(cls)->emplace(key ? key : "", value ? value : "");
    return MHD_YES;
  }

  // The request header `name`, "" when absent.
  static std::string header(MHD_Connection* c, const char* name) {
    const char* v = MHD_lookup_connection_value(c, MHD_HEADER_KIND, name);
    return v ? v : "";
  }

  // libmicrohttpd's access handler, called once a request's head is in:
  // the request is refused or answered then, before any body is read
  // (the monitor takes none), except a pixel trace, answered when its
  // thread is done (called again after the connection is resumed).
  static MHD_Result answer(void* cls, MHD_Connection* c, const char* url, const char* method, const char*,
                           const char*, size_t* upload_size, void** req_cls) {
    auto* self = static_cast<Server*>(cls);
    if (auto* pending = static_cast<Pending*>(*req_cls)) {
      if (!pending->done) {  // not expected: resumed before its reply
        MHD_suspend_connection(c);
        return MHD_YES;
      }
      pending->worker.join();
      const bool busy = pending->reply.status == 429;
      return self->queue(c, monitor::with_range(std::move(pending->reply), pending->range),
                   busy ? std::map<std::string, std::string>{{"Retry-After", "1"}} : std::map<std::string, std::string>{});
    }
    self->set_waiting(c, false);
    const std::string verb = method;
    if (verb != "GET" && verb != "HEAD")
      return self->queue(c, monitor::error_reply(405, "the monitor only reads: GET or HEAD"), {{"Allow", "GET, HEAD"}});
    if (!header(c, MHD_HTTP_HEADER_TRANSFER_ENCODING).empty() || !header(c, MHD_HTTP_HEADER_CONTENT_ENCODING).empty() ||
        (!header(c, MHD_HTTP_HEADER_CONTENT_LENGTH).empty() && header(c, MHD_HTTP_HEADER_CONTENT_LENGTH) != "0") ||
        *upload_size != 0)
      return self->queue(c, monitor::error_reply(413, "the monitor takes no request body"));
    const std::string range = header(c, MHD_HTTP_HEADER_RANGE);
    if (range.find(',') != std::string::npos)  // refused before any work is done for it
      return self->queue(c, monitor::error_reply(416, "several ranges in one request are not served"));
    monitor::Query query;
    MHD_get_connection_values(c, MHD_GET_ARGUMENT_KIND, &Server::add_argument, &query);
    const std::string path = url ? url : "";
    if (path != "/api/trace") return self->queue(c, monitor::with_range(self->api_.get(path, query), range));
    // A trace takes up to a minute: on a thread of its own, the connection
    // suspended meanwhile (its polling thread serves the others).
    {
      const std::lock_guard lock(self->mutex_);
      if (self->closing_) return self->queue(c, monitor::error_reply(503, "the monitor is stopping"));
      ++self->traces_;
    }
    auto* pending = new Pending;
    pending->range = range;
    *req_cls = pending;
    MHD_suspend_connection(c);
    pending->worker = std::thread([self, c, pending, query = std::move(query)] {
      pending->reply = self->api_.get("/api/trace", query);
      pending->done = true;
      MHD_resume_connection(c);
      const std::lock_guard lock(self->mutex_);
      --self->traces_;
      self->traces_done_.notify_all();
    });
    return MHD_YES;
  }

  const monitor::MonitorApi& api_;
  monitor::ReplyBudget budget_;  // given back by responses: outlives the daemon (stopped in ~Server)
  const std::string busy_body_;  // the 503's body, sent as it is (never copied, never counted)
  MHD_Daemon* daemon_ = nullptr;
  int port_ = 0;
  std::mutex mutex_;  // guards what follows
  std::map<HeadWait*, std::unique_ptr<HeadWait>> waits_;
  int traces_ = 0;
  bool stopping_ = false;
  bool closing_ = false;  // stopping: traces refused (a suspended connection must not outlive the daemon)
  std::condition_variable traces_done_, watch_;
  std::thread watchman_;
};

}  // namespace

int run_monitor(const MonitorCommand& cmd) {
  // Input: the folders and where to listen; output: the server, until
  // Ctrl-C.  Every GET goes to the API; nothing else is answered.
  if (cmd.port < 0 || cmd.port > 65535) throw std::invalid_argument(fmt::format("--port {}: must be 0 to 65535", cmd.port));
  // The pixel inspector runs this very binary's `trace` (monitor/pixel_trace.hpp).
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  const monitor::MonitorApi api(cmd.dirs, ec ? std::filesystem::path{} : self);
  InterruptGuard guard;
  const Server server(api, cmd.bind, cmd.port);
  fmt::print(stderr, "monitor: {} folder{} at http://{}:{}/ (Ctrl-C to stop)\n", api.folders().size(),
             api.folders().size() == 1 ? "" : "s", cmd.bind.find(':') != std::string::npos ? "[" + cmd.bind + "]" : cmd.bind,
             server.port());
  if (!loopback(cmd.bind))
    fmt::print(stderr,
               "monitor: warning: listening on {}, not only this machine: anyone who can reach it sees the frames and "
               "the folders' paths. Prefer the default 127.0.0.1 and an ssh tunnel (docs/monitor.md)\n",
               cmd.bind);
  while (guard.signal() == 0) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  fmt::print(stderr, "monitor: stopped by {}\n", signal_name(guard.signal()));
  return 0;
}

}  // namespace lc

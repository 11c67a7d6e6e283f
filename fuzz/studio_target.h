// The studio served in-process for its fuzzers: the mutation fuzzer of HTTP requests
// (fuzz/request_fuzzer.cc), the libFuzzer target over raw requests (fuzz/http_fuzzer.cc) and the
// replay of that target's corpus (tests/fuzz_replay_test.cc). A scratch folder ROOT/served is
// served by studies::ServeMain on a free loopback port (request timeout 1 s; runs start the
// camopt binary given); nothing may ever appear beside ROOT/served, nor a link inside it.
//
// One request is sent on its own connection, whose sending side is then closed (a cut request
// ends at once), and judged:
//   answered   a well-formed status line with a status below 500, or 503 (too many connections)
//   closed     the connection closed without an answer (a request the HTTP library could not read)
// Anything else is a failure: a 5xx other than 503 (a handler that failed), no answer and no close
// within 3 s, a malformed status line.
#pragma once

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <stdlib.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <filesystem>
#include <functional>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "studies/serve.h"

namespace camopt::fuzz {

/// The studies the scratch folder serves (small, quick to run).
inline const std::vector<std::string>& StudioStudies() {
  static const std::vector<std::string> names = {"lcr_ii.json", "rigidity_gearbox.json", "disc_cam_translating.json"};
  return names;
}

struct Reply {
  std::string outcome;  ///< "answered", "closed", or a failure
  int status = 0;
  std::string first_line;
};

inline bool RequestFailure(const std::string& outcome) { return outcome != "answered" && outcome != "closed"; }

/// Sends `text` on a new connection to 127.0.0.1:`port`, closes the sending side and reads the
/// answer until the server closes or 3 s pass.
inline Reply Exchange(int port, const std::string& text) {
  Reply r;
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(uint16_t(port));
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  // A connect interrupted by a signal goes on in the background: wait for it and read its result.
  const auto connected = [&] {
    if (::connect(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0) return true;
    if (errno != EINTR) return false;
    pollfd p{fd, POLLOUT, 0};
    int ready;
    do ready = ::poll(&p, 1, 3000);
    while (ready < 0 && errno == EINTR);
    int error = 0;
    socklen_t length = sizeof error;
    return ready > 0 && ::getsockopt(fd, SOL_SOCKET, SO_ERROR, &error, &length) == 0 && error == 0;
  };
  if (fd < 0 || !connected()) {
    if (fd >= 0) ::close(fd);
    r.outcome = "no connection";
    return r;
  }
  // The server may answer (413, 400) and close before the whole request is sent: a failed send is
  // not a failure of the server.
  // A signal (libFuzzer's SIGALRM timer ticks every -timeout/2 s) interrupts poll, send and recv
  // with EINTR: each is tried again, never taken for a silent or closed server.
  for (size_t sent = 0; sent < text.size();) {
    pollfd p{fd, POLLOUT, 0};
    const int ready = ::poll(&p, 1, 3000);
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) break;
    const ssize_t n = ::send(fd, text.data() + sent, text.size() - sent, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    sent += size_t(n);
  }
  ::shutdown(fd, SHUT_WR);
  std::string in;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(3);
  bool closed = false;
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) break;
    pollfd p{fd, POLLIN, 0};
    const int ready = ::poll(&p, 1, int(left.count()));
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) break;
    char buf[65536];
    const ssize_t n = ::recv(fd, buf, sizeof buf, 0);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      closed = true;
      break;
    }
    if (in.size() < (1 << 20)) in.append(buf, size_t(n));
  }
  ::close(fd);
  if (in.empty()) {
    r.outcome = closed ? "closed" : "no answer in 3 s";
    return r;
  }
  r.first_line = in.substr(0, std::min(in.find("\r\n"), size_t{200}));
  if (in.rfind("HTTP/1.1 ", 0) != 0 || in.size() < 12 || !std::isdigit(static_cast<unsigned char>(in[9]))) {
    r.outcome = "malformed answer";
    return r;
  }
  r.status = std::atoi(in.c_str() + 9);
  r.outcome = r.status < 100                        ? "malformed answer"
              : r.status >= 500 && r.status != 503 ? "server error"
                                                   : "answered";
  return r;
}

/// A request's text with every "{{HOST}}" replaced by the server's address (a corpus file cannot
/// know the port): the libFuzzer inputs carry the placeholder.
inline std::string WithHost(std::string text, int port) {
  const std::string placeholder = "{{HOST}}", host = "127.0.0.1:" + std::to_string(port);
  for (size_t at = text.find(placeholder); at != std::string::npos; at = text.find(placeholder, at + host.size()))
    text.replace(at, placeholder.size(), host);
  return text;
}

/// The studio serving a scratch folder in this process until destroyed.
class InProcessStudio {
 public:
  /// `examples`: where StudioStudies() are copied from; `program`: the camopt binary runs start.
  InProcessStudio(const std::filesystem::path& examples, const std::string& program) {
    namespace fs = std::filesystem;
    std::string pattern = (fs::temp_directory_path() / "camopt-request-fuzz-XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("cannot create a scratch folder for the studio");
    root_ = pattern;
    served_ = root_ / "served";
    fs::create_directories(served_);
    for (const std::string& name : StudioStudies()) fs::copy_file(examples / name, served_ / name);
    studies::ServeOptions so;
    so.folder = served_.string();
    so.port = 0;
    so.request_timeout_s = 1;
    so.program = program;
    so.on_listening = [this](int p, std::function<void()> s) {
      std::lock_guard<std::mutex> lock(mutex_);
      port_ = p;
      stop_ = std::move(s);
      listening_.notify_all();
    };
    server_ = std::thread([so] { studies::ServeMain(so); });
    std::unique_lock<std::mutex> lock(mutex_);
    if (!listening_.wait_for(lock, std::chrono::seconds(20), [&] { return port_ > 0; })) {
      lock.unlock();
      server_.detach();
      throw std::runtime_error("the studio did not start within 20 s");
    }
  }
  ~InProcessStudio() {
    if (stop_) stop_();
    if (server_.joinable()) server_.join();
    std::error_code ec;
    std::filesystem::remove_all(root_, ec);
  }
  InProcessStudio(const InProcessStudio&) = delete;
  InProcessStudio& operator=(const InProcessStudio&) = delete;

  int port() const { return port_; }
  const std::filesystem::path& served() const { return served_; }

  /// "" while the server answers GET /api/kinds with 200 within 1 s; else what it did.
  std::string Health() const {
    const auto t0 = std::chrono::steady_clock::now();
    const Reply h = Exchange(port_, "GET /api/kinds HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port_) + "\r\n\r\n");
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (h.status == 200 && s <= 1.0) return "";
    return "/api/kinds " + h.outcome + " " + std::to_string(h.status) + " in " + std::to_string(s) + " s";
  }

  /// Files beside the served folder and links inside it (each a failure).
  std::vector<std::string> Stray() const {
    namespace fs = std::filesystem;
    std::vector<std::string> out;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(root_, ec))
      if (e.path() != served_) out.push_back("a file outside the served folder: " + e.path().string());
    for (auto it = fs::recursive_directory_iterator(served_, ec); !ec && it != fs::recursive_directory_iterator();
         it.increment(ec))
      if (fs::is_symlink(it->symlink_status())) out.push_back("a link in the served folder: " + it->path().string());
    return out;
  }

 private:
  std::filesystem::path root_, served_;
  std::mutex mutex_;
  std::condition_variable listening_;
  int port_ = 0;
  std::function<void()> stop_;
  std::thread server_;
};

}  // namespace camopt::fuzz

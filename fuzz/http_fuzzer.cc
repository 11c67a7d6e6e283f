// libFuzzer entry point over the studio's HTTP requests (see fuzz/studio_target.h; run with
// `bash scripts/fuzz.sh request SECONDS`). One input is the raw bytes of one request, each
// "{{HOST}}" in it replaced by the in-process server's address; it is sent on its own connection.
// A defect: a failed answer (studio_target.h), the server not answering /api/kinds within 1 s
// (checked every 50 inputs), a file beside the served folder or a link in it (checked after every
// input), or a crash or sanitizer report anywhere in the process (the server runs in it).
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include <unistd.h>

#include "fuzz/studio_target.h"

namespace {

camopt::fuzz::InProcessStudio* studio = nullptr;

// The server stops and its scratch folder goes when the process exits normally (the replay's end,
// libFuzzer's -runs or -max_total_time); a defect aborts and leaves it for a look.
void StopStudio() {
  delete studio;
  studio = nullptr;
}

void Defect(const std::string& why) {
  std::fprintf(stderr, "camopt defect: %s\n", why.c_str());
  // A server that stopped answering is seen in its threads: with CAMOPT_FUZZ_STACKS=1 each one's
  // stack (gdb), the runs' processes and whether the server answers again within 10 s.
  if (std::getenv("CAMOPT_FUZZ_STACKS") && studio) {
    const std::string pid = std::to_string(getpid());
    std::fflush(stderr);
    std::system(("ps -o pid,ppid,stat,etime,wchan:20,args --ppid " + pid + " 1>&2").c_str());
    std::system(("gdb -batch -p " + pid + " -ex 'thread apply all bt 25' 1>&2 2>/dev/null").c_str());
    for (int k = 0; k < 5; ++k) {
      const std::string health = studio->Health();
      std::fprintf(stderr, "camopt defect: then /api/kinds: %s\n", health.empty() ? "answered" : health.c_str());
    }
  }
  std::abort();
}

// With CAMOPT_FUZZ_STACKS=1, an exchange still open after 1.5 s is looked at while it hangs: the
// sockets of the server's port (ss) and every thread's stack (gdb).
class Watchdog {
 public:
  Watchdog() : thread_([this] { Loop(); }) {}
  void Arm(int port) {
    std::lock_guard<std::mutex> lock(mutex_);
    port_ = port;
    deadline_ = std::chrono::steady_clock::now() + std::chrono::milliseconds(1500);
    armed_ = true;
    changed_.notify_all();
  }
  void Disarm() {
    std::lock_guard<std::mutex> lock(mutex_);
    armed_ = false;
  }

 private:
  void Loop() {
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      changed_.wait(lock, [&] { return armed_; });
      if (changed_.wait_until(lock, deadline_, [&] { return !armed_; })) continue;
      if (!armed_ || std::chrono::steady_clock::now() < deadline_) continue;
      armed_ = false;
      const std::string port = std::to_string(port_), pid = std::to_string(getpid());
      std::fprintf(stderr, "camopt watchdog: an exchange with port %s open for 1.5 s\n", port.c_str());
      std::fflush(stderr);
      std::system(("ss -tanoi '( sport = :" + port + " or dport = :" + port + " )' 1>&2").c_str());
      std::system(("ss -ltn '( sport = :" + port + " )' 1>&2").c_str());
      std::system(("gdb -batch -p " + pid + " -ex 'thread apply all bt 30' 1>&2 2>/dev/null").c_str());
    }
  }
  std::mutex mutex_;
  std::condition_variable changed_;
  bool armed_ = false;
  int port_ = 0;
  std::chrono::steady_clock::time_point deadline_;
  std::thread thread_;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (!studio) {
    studio = new camopt::fuzz::InProcessStudio(CAMOPT_EXAMPLES_DIR, CAMOPT_BINARY);
    std::atexit(StopStudio);
  }
  static long inputs = 0;
  if (size > (size_t{2} << 20)) return 0;
  const std::string text =
      camopt::fuzz::WithHost(std::string(reinterpret_cast<const char*>(data), size), studio->port());
  static Watchdog* watchdog = std::getenv("CAMOPT_FUZZ_STACKS") ? new Watchdog : nullptr;
  if (watchdog) watchdog->Arm(studio->port());
  const camopt::fuzz::Reply r = camopt::fuzz::Exchange(studio->port(), text);
  if (watchdog) watchdog->Disarm();
  if (camopt::fuzz::RequestFailure(r.outcome)) Defect(r.outcome + ": " + r.first_line);
  for (const std::string& stray : studio->Stray()) Defect(stray);
  if (++inputs % 50 == 0) {
    const std::string health = studio->Health();
    if (!health.empty()) Defect("the server stopped answering: " + health);
  }
  return 0;
}

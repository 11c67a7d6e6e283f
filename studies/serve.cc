// `camopt serve` (studies/serve.h): the studio's HTTP server, its API and its runs.
#include "studies/serve.h"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cctype>
#include <climits>
#include <condition_variable>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <sstream>
#include <random>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <netdb.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/prctl.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <httplib.h>
#include <nlohmann/json.hpp>

#include "studies/input.h"
#include "studies/report.h"
#include "studies/schemas.h"
#include "studies/study.h"
#include "studies/studio_mechanism.h"
#include "studies/sweep.h"

namespace camopt::studies {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// ---- paths inside the folder -------------------------------------------------------------------

// True when `p` (canonical) is `root` (canonical) or below it, compared component by component
// ("/a/bc" is not below "/a/b").
bool IsWithin(const fs::path& root, const fs::path& p) {
  auto r = root.begin(), q = p.begin();
  for (; r != root.end(); ++r, ++q) {
    if (q == p.end() || *q != *r) return false;
  }
  return true;
}

struct Resolved {
  int status = 200;  // 200, 400 (malformed), 403 (outside the folder), 404 (absent)
  fs::path path;     // canonical (weakly canonical when it need not exist)
  std::string message;
};

// A path given by the client, relative to the folder: resolved with every symbolic link followed,
// refused unless it stays inside the folder. must_exist: the file itself must exist (open), else
// only its parent folder (save).
Resolved Resolve(const fs::path& root, const std::string& rel, bool must_exist) {
  Resolved out;
  if (rel.empty() || rel.size() > 4096 || rel.find('\0') != std::string::npos) {
    out.status = 400;
    out.message = "path: expected a file name relative to the studio's folder, found \"" + rel + "\"";
    return out;
  }
  const fs::path given(rel);
  for (const fs::path& part : given) {
    if (part.native().size() > NAME_MAX) {
      out.status = 400;
      out.message = "path: a file or folder name is at most " + std::to_string(NAME_MAX) + " bytes, found one of " +
                    std::to_string(part.native().size()) + " in \"" + rel + "\"";
      return out;
    }
  }
  if (given.is_absolute()) {
    out.status = 403;
    out.message = "path: " + rel + " is outside the studio's folder (expected a path relative to it)";
    return out;
  }
  std::error_code ec;
  const fs::path joined = root / given;
  if (!IsWithin(root, joined.lexically_normal())) {
    out.status = 403;
    out.message = "path: " + rel + " is outside the studio's folder";
    return out;
  }
  fs::path resolved = must_exist ? fs::canonical(joined, ec) : fs::weakly_canonical(joined, ec);
  if (ec) {
    out.status = 404;
    out.message = "path: " + rel + ": " + ec.message();
    return out;
  }
  if (!IsWithin(root, resolved)) {
    out.status = 403;
    out.message = "path: " + rel + " is outside the studio's folder";
    return out;
  }
  if (!must_exist) {
    // The parent must exist and be inside too (weakly_canonical resolved what exists of it).
    fs::path parent = fs::canonical(resolved.parent_path(), ec);
    if (ec || !IsWithin(root, parent)) {
      out.status = ec ? 404 : 403;
      out.message = "path: " + rel + ": " + (ec ? ec.message() : std::string("outside the studio's folder"));
      return out;
    }
    // An existing symbolic link as the target itself: where it points must be inside as well.
    if (fs::is_symlink(joined, ec)) {
      const fs::path target = fs::weakly_canonical(joined, ec);
      if (ec || !IsWithin(root, target)) {
        out.status = 403;
        out.message = "path: " + rel + " links outside the studio's folder";
        return out;
      }
    }
  }
  out.path = resolved;
  return out;
}

std::string Relative(const fs::path& root, const fs::path& p) { return p.lexically_relative(root).generic_string(); }

bool EndsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// Every JSON answer is typed "application/json; charset=utf-8": Debian's cpp-httplib (built with
// brotli) compresses one typed exactly "application/json" at brotli's slowest setting when the
// client accepts it, as browsers do (a 37 kB answer 114 ms instead of 9 ms; the mechanism handler
// below); with a charset it is sent as it is. Loopback needs no compression.
constexpr const char* kJsonType = "application/json; charset=utf-8";

void SendJson(httplib::Response& res, const json& j, int status = 200) {
  res.status = status;
  res.set_content(j.dump(-1, ' ', false, json::error_handler_t::replace), kJsonType);
}

void SendError(httplib::Response& res, int status, const std::string& message) {
  SendJson(res, {{"error", message}}, status);
}

std::string ContentType(const fs::path& p) {
  const std::string ext = p.extension().string();
  if (ext == ".json") return kJsonType;
  if (ext == ".csv") return "text/csv; charset=utf-8";
  if (ext == ".svg") return "image/svg+xml";
  if (ext == ".html") return "text/html; charset=utf-8";
  if (ext == ".txt" || ext == ".md") return "text/plain; charset=utf-8";
  return "application/octet-stream";
}

// ---- runs ----------------------------------------------------------------------------------------

// One `camopt run` child. Its stderr carries one JSON object per progress report (--progress json)
// and the CLI's messages; a reader thread turns them into events and waits for the child's end.
struct Run {
  int id = 0;
  pid_t pid = -1;
  std::string study;  // relative to the folder
  std::string out;    // relative to the folder
  std::mutex mutex;
  std::condition_variable changed;
  std::vector<std::string> events;  // server-sent events, whole ("event: …\ndata: …\n\n")
  std::vector<std::string> messages;
  json last_progress = json::object();
  std::string state = "running";  // running, done, incomplete, error, cancelled, failed
  int exit_code = -1;
  bool cancel_requested = false;
  bool finished = false;
  std::thread reader;
};

std::string Event(const std::string& name, const json& data) {
  return "event: " + name + "\ndata: " + data.dump(-1, ' ', false, json::error_handler_t::replace) + "\n\n";
}

json RunStatus(Run& run) {
  std::lock_guard<std::mutex> lock(run.mutex);
  return {{"id", run.id},         {"pid", run.pid},           {"study", run.study},
          {"out", run.out},       {"state", run.state},       {"exit_code", run.exit_code},
          {"messages", run.messages}, {"progress", run.last_progress}, {"finished", run.finished}};
}

std::string StateOf(int exit_code, bool cancel_requested) {
  switch (exit_code) {
    case 0: return "done";
    case 3: return "incomplete";
    case 2: return "error";
    case 130: return "cancelled";
    default: return cancel_requested ? "cancelled" : "failed";
  }
}

void ReadChild(const std::shared_ptr<Run>& run, int fd) {
  std::string buffer;
  char chunk[4096];
  const auto line_done = [&](const std::string& line) {
    if (line.empty()) return;
    std::lock_guard<std::mutex> lock(run->mutex);
    if (line[0] == '{') {
      json j = json::parse(line, nullptr, false);
      if (j.is_object()) {
        run->last_progress = j;
        run->events.push_back(Event("progress", j));
        run->changed.notify_all();
        return;
      }
    }
    if (run->messages.size() < 200) {
      run->messages.push_back(line.substr(0, 2000));
      run->events.push_back(Event("message", {{"text", line.substr(0, 2000)}}));
      run->changed.notify_all();
    }
  };
  for (;;) {
    const ssize_t n = read(fd, chunk, sizeof chunk);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    buffer.append(chunk, static_cast<size_t>(n));
    size_t start = 0, nl;
    while ((nl = buffer.find('\n', start)) != std::string::npos) {
      line_done(buffer.substr(start, nl - start));
      start = nl + 1;
    }
    buffer.erase(0, start);
    if (buffer.size() > (1u << 20)) buffer.clear();  // no line is that long; never grow without bound
  }
  line_done(buffer);
  close(fd);
  int status = 0;
  while (waitpid(run->pid, &status, 0) < 0 && errno == EINTR) {
  }
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
  std::lock_guard<std::mutex> lock(run->mutex);
  run->exit_code = code;
  run->state = StateOf(code, run->cancel_requested);
  run->finished = true;
  run->events.push_back(Event("end", {{"state", run->state}, {"exit_code", code}, {"out", run->out},
                                      {"messages", run->messages}}));
  run->changed.notify_all();
}

void Cancel(Run& run) {
  std::lock_guard<std::mutex> lock(run.mutex);
  if (run.finished || run.pid <= 0) return;
  run.cancel_requested = true;
  kill(run.pid, SIGINT);  // the CLI removes its temporary folder and exits 130
}

class Studio {
 public:
  Studio(fs::path root, std::string exe) : root_(std::move(root)), exe_(std::move(exe)) {}
  ~Studio() {
    std::map<int, std::shared_ptr<Run>> runs;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      runs.swap(runs_);
    }
    for (auto& [id, run] : runs) {
      Cancel(*run);
      if (run->reader.joinable()) run->reader.join();
    }
  }

  void SetAddress(const std::string& host, int port) {
    const std::string p = std::to_string(port);
    hosts_ = {host + ":" + p, "127.0.0.1:" + p, "localhost:" + p};
    if (host == "::1") hosts_.insert("[::1]:" + p);
    for (const auto& h : hosts_) origins_.insert("http://" + h);
  }

  // Served beyond this machine (--allow-remote): every request needs this token.
  void SetToken(const std::string& token) { token_ = token; }

  // The request's token: the cookie the studio set, the X-Camopt-Token header, or ?token=.
  bool HasToken(const httplib::Request& req) const {
    const std::string cookie = "camopt_token=" + token_;
    const std::string cookies = req.get_header_value("Cookie");
    for (size_t at = 0; (at = cookies.find(cookie, at)) != std::string::npos; at += cookie.size()) {
      const size_t end = at + cookie.size();
      if ((at == 0 || cookies[at - 1] == ' ' || cookies[at - 1] == ';') && (end == cookies.size() || cookies[end] == ';'))
        return true;
    }
    return req.get_header_value("X-Camopt-Token") == token_ || req.get_param_value("token") == token_;
  }

  // 403 for another site's page (Origin) or a name that is not this server's (Host: DNS rebinding);
  // 401 without the token when served beyond this machine. `status` receives the code.
  bool Allowed(const httplib::Request& req, std::string& why, int& status) const {
    const std::string host = req.get_header_value("Host");
    status = 403;
    if (!token_.empty()) {
      // Beyond this machine the Host is whatever name reaches it; the token stands in for the Host
      // check (a rebound name's page has no cookie of this address), and an Origin must be the
      // page's own.
      if (!HasToken(req)) {
        status = 401;
        why = "this studio is served beyond its machine: open the address with ?token=… that camopt serve printed";
        return false;
      }
      if (req.has_header("Origin") && req.get_header_value("Origin") != "http://" + host) {
        why = "requests from " + req.get_header_value("Origin") + " are refused (only the studio's own pages may call it)";
        return false;
      }
      return true;
    }
    if (hosts_.count(host) == 0) {
      why = "Host \"" + host + "\" is not this studio's address";
      return false;
    }
    if (req.has_header("Origin")) {
      const std::string origin = req.get_header_value("Origin");
      if (origins_.count(origin) == 0) {
        why = "requests from " + origin + " are refused (only the studio's own pages may call it)";
        return false;
      }
    }
    if (req.get_header_value("Sec-Fetch-Site") == "cross-site") {
      why = "cross-site requests are refused";
      return false;
    }
    return true;
  }

  json ListFiles() const {
    json files = json::array();
    std::error_code ec;
    fs::recursive_directory_iterator it(root_, fs::directory_options::skip_permission_denied, ec), end;
    int count = 0;
    for (; !ec && it != end && count < 2000; it.increment(ec)) {
      const fs::path& p = it->path();
      const std::string name = p.filename().string();
      if (it->is_directory(ec)) {
        // Run output folders, hidden folders and the front end's packages are not studies.
        if (name.empty() || name[0] == '.' || name == "node_modules" || name == "results" ||
            fs::exists(p / "result.json") || fs::exists(p / ".camopt_manifest") || it.depth() >= 3)
          it.disable_recursion_pending();
        continue;
      }
      if (!EndsWith(name, ".json") || !it->is_regular_file(ec)) continue;
      ++count;
      json entry = {{"path", Relative(root_, p)}};
      if (it->file_size(ec) < (1u << 20)) {
        std::ifstream in(p);
        const json j = json::parse(in, nullptr, false);
        if (j.is_object() && j.contains("study") && j["study"].is_string()) entry["kind"] = j["study"];
        else if (j.is_object() && j.contains("base")) entry["kind"] = "sweep";
        if (j.is_object() && j.contains("name") && j["name"].is_string()) entry["name"] = j["name"];
      }
      files.push_back(entry);
    }
    std::sort(files.begin(), files.end(),
              [](const json& a, const json& b) { return a["path"].get<std::string>() < b["path"].get<std::string>(); });
    return files;
  }

  std::shared_ptr<Run> Start(const fs::path& study, std::string& error) {
    const std::string rel = Relative(root_, study);
    const std::string out_rel = Relative(root_, root_ / "results" / study.stem());
    {
      // One run per output folder at a time: a second would replace the first one's results. The
      // check and the claim are one step under the lock (a run being started holds its claim in
      // starting_ until it is in runs_), so of concurrent requests exactly one is accepted.
      std::lock_guard<std::mutex> lock(mutex_);
      // At most kMaxRunningRuns at once: each is a process as heavy as `camopt run`, and a client
      // that starts one per study file would otherwise starve the machine and the server with it.
      size_t running = starting_.size();
      for (auto& [id, other] : runs_) {
        std::lock_guard<std::mutex> run_lock(other->mutex);
        running += !other->finished;
      }
      if (running >= kMaxRunningRuns) {
        error = "runs: " + std::to_string(running) + " runs are going on, at most " + std::to_string(kMaxRunningRuns) +
                " at once (cancel one or wait for one to finish)";
        return nullptr;
      }
      if (starting_.count(out_rel)) {
        error = "run of " + rel + " is starting and will write " + out_rel + " (cancel it or wait for it)";
        return nullptr;
      }
      for (auto& [id, other] : runs_) {
        std::lock_guard<std::mutex> run_lock(other->mutex);
        if (!other->finished && other->out == out_rel) {
          error = "run " + std::to_string(id) + " of " + other->study + " is still writing " + other->out +
                  " (cancel it or wait for it)";
          return nullptr;
        }
      }
      starting_.insert(out_rel);
    }
    struct Unclaim {
      Studio* studio;
      std::string out;
      ~Unclaim() {
        std::lock_guard<std::mutex> lock(studio->mutex_);
        studio->starting_.erase(out);
      }
    } unclaim{this, out_rel};
    const fs::path out = root_ / "results" / study.stem();
    std::error_code ec;
    fs::create_directories(root_ / "results", ec);
    // A sweep file (its "sweep" names it) runs as `camopt sweep`, a study as `camopt run`.
    std::ifstream in(study);
    const json file = json::parse(in, nullptr, false);
    const bool is_sweep = file.is_object() && file.contains("sweep") && file["sweep"].is_string();
    std::vector<std::string> args = {exe_, is_sweep ? "sweep" : "run", study.string(), "--out", out.string(),
                                     "--quiet", "--progress", "json", "--files-inside", root_.string()};
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    int fds[2];
    if (pipe2(fds, O_CLOEXEC) != 0) {
      error = std::string("cannot start the run: ") + std::strerror(errno);
      return nullptr;
    }
    const std::string folder = root_.string();
    const pid_t parent = getpid();
    // The fallback bound for closing inherited descriptors where close_range is missing (computed here:
    // sysconf is not async-signal-safe).
    const long open_max = std::max(1024L, sysconf(_SC_OPEN_MAX));
    const pid_t pid = fork();
    if (pid < 0) {
      error = std::string("cannot start the run: ") + std::strerror(errno);
      close(fds[0]);
      close(fds[1]);
      return nullptr;
    }
    if (pid == 0) {
      // The child: only async-signal-safe calls until exec. It gets SIGINT when the server ends.
      prctl(PR_SET_PDEATHSIG, SIGINT);
      if (getppid() != parent) _exit(130);
      dup2(fds[1], 2);
      const int null_fd = open("/dev/null", O_RDWR);
      if (null_fd >= 0) {
        dup2(null_fd, 0);
        dup2(null_fd, 1);
      }
      if (chdir(folder.c_str()) != 0) _exit(1);
      // Nothing but 0, 1 and 2 crosses into the run: the listening socket and every client's connection
      // (cpp-httplib opens them without O_CLOEXEC) would otherwise live as long as the run, holding a
      // client's connection open after the server closed it and the port after the server ended.
      if (close_range(3, ~0U, 0) != 0)
        for (long fd = 3; fd < open_max; ++fd) close(static_cast<int>(fd));
      execv(argv[0], argv.data());
      _exit(127);
    }
    close(fds[1]);
    auto run = std::make_shared<Run>();
    run->pid = pid;
    run->study = rel;
    run->out = Relative(root_, out);
    {
      std::lock_guard<std::mutex> lock(mutex_);
      run->id = next_id_++;
    }
    // The reader before the run is listed: a listed run always has a reader to join.
    run->reader = std::thread(ReadChild, run, fds[0]);
    {
      std::lock_guard<std::mutex> lock(mutex_);
      runs_[run->id] = run;
      ForgetOldRuns();
    }
    return run;
  }

  // Beyond kMaxKeptRuns finished runs, the oldest are forgotten: their reader threads (done, or
  // about to return: `finished` is their last step) joined, their entries removed. mutex_ held.
  void ForgetOldRuns() {
    std::vector<int> finished;
    for (auto& [id, run] : runs_) {
      std::lock_guard<std::mutex> run_lock(run->mutex);
      if (run->finished) finished.push_back(id);
    }
    for (size_t k = 0; finished.size() - k > kMaxKeptRuns; ++k) {
      const auto it = runs_.find(finished[k]);
      if (it->second->reader.joinable()) it->second->reader.join();
      runs_.erase(it);
    }
  }

  std::shared_ptr<Run> Find(int id) {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto it = runs_.find(id);
    return it == runs_.end() ? nullptr : it->second;
  }

  json ListRuns() {
    std::vector<std::shared_ptr<Run>> runs;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      for (auto& [id, run] : runs_) runs.push_back(run);
    }
    json out = json::array();
    for (auto& run : runs) out.push_back(RunStatus(*run));
    return out;
  }

  const fs::path& root() const { return root_; }

 private:
  fs::path root_;
  std::string exe_;
  std::set<std::string> hosts_, origins_;
  std::string token_;
  std::mutex mutex_;
  std::map<int, std::shared_ptr<Run>> runs_;
  std::set<std::string> starting_;  ///< output folders of runs being started (Start)
  int next_id_ = 1;
};

// A study's JSON text from a request: parsed with the CLI's limits and messages.
json ParseBodyStudy(const std::string& text, const std::string& file) {
  return ParseStudyText(text, file, CurrentInputLimits().max_depth);
}

json ErrorJson(const StudyError& e) {
  return {{"message", e.what()}, {"file", e.file()}, {"path", e.path()}, {"expected", e.expected()},
          {"found", e.found()}};
}

int IdOf(const httplib::Request& req) {
  try {
    return std::stoi(req.matches[1].str());
  } catch (const std::exception&) {
    return -1;
  }
}

// One lock per saved file: concurrent saves of one study are written one after the other.
std::mutex& SaveLockOf(const fs::path& file) {
  static std::mutex guard;
  static std::map<std::string, std::unique_ptr<std::mutex>> locks;
  const std::lock_guard<std::mutex> lock(guard);
  auto& m = locks[file.string()];
  if (!m) m = std::make_unique<std::mutex>();
  return *m;
}

// Writes `body` to `file` (inside the served folder, resolved) whole or not at all: a temporary
// of a name no other save uses, created under a handle on the folder with O_CREAT | O_EXCL |
// O_NOFOLLOW (a link placed at its name is never followed), then renamed over the file. A link
// at the file's own name is replaced by the file, never written through.
bool SaveFile(const fs::path& file, const std::string& body, std::string& why) {
  static std::atomic<unsigned long> counter{0};
  const std::lock_guard<std::mutex> lock(SaveLockOf(file));
  const int dir = ::open(file.parent_path().c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  if (dir < 0) {
    why = std::strerror(errno);
    return false;
  }
  const std::string name = file.filename().string();
  // A name taken (by a link or a file someone placed there): the next one; never through it.
  std::string tmp;
  int fd = -1;
  for (int attempt = 0; attempt < 64 && fd < 0; ++attempt) {
    // The name's first 100 bytes: the temporary's name stays within NAME_MAX whatever the file's.
    tmp = "." + name.substr(0, 100) + ".camopt-save-" + std::to_string(getpid()) + "-" + std::to_string(++counter);
    fd = ::openat(dir, tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (fd < 0 && errno != EEXIST) break;
  }
  if (fd < 0) {
    why = std::strerror(errno);
    ::close(dir);
    return false;
  }
  size_t done = 0;
  bool ok = true;
  while (ok && done < body.size()) {
    const ssize_t n = ::write(fd, body.data() + done, body.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) ok = false;
    else done += static_cast<size_t>(n);
  }
  if (!ok) why = std::strerror(errno);
  if (::close(fd) != 0 && ok) ok = false, why = std::strerror(errno);
  if (ok && ::renameat(dir, tmp.c_str(), dir, name.c_str()) != 0) ok = false, why = std::strerror(errno);
  if (!ok) ::unlinkat(dir, tmp.c_str(), 0);
  ::close(dir);
  return ok;
}

void Routes(httplib::Server& server, Studio& studio) {
  const fs::path root = studio.root();

  server.Get("/api/kinds", [](const httplib::Request&, httplib::Response& res) {
    SendJson(res, StudyKinds());
  });
  server.Get(R"(/api/schema/([a-z0-9_]+))", [](const httplib::Request& req, httplib::Response& res) {
    try {
      res.set_content(StudySchema(req.matches[1].str()), kJsonType);
    } catch (const StudyError& e) {
      SendError(res, 404, e.what());
    }
  });
  server.Get("/api/files", [&studio](const httplib::Request&, httplib::Response& res) {
    SendJson(res, {{"folder", studio.root().string()}, {"files", studio.ListFiles()}});
  });
  server.Get("/api/file", [root](const httplib::Request& req, httplib::Response& res) {
    const Resolved r = Resolve(root, req.get_param_value("path"), true);
    if (r.status != 200) return SendError(res, r.status, r.message);
    std::error_code ec;
    if (!fs::is_regular_file(r.path, ec)) return SendError(res, 404, "path: not a file");
    try {
      res.set_content(ReadFileCapped(r.path.string(), size_t{64} << 20, "file"), ContentType(r.path));
    } catch (const StudyError& e) {
      SendError(res, 404, e.what());
    }
  });
  server.Put("/api/file", [root](const httplib::Request& req, httplib::Response& res) {
    const std::string rel = req.get_param_value("path");
    if (!EndsWith(rel, ".json")) return SendError(res, 400, "path: expected a study file name ending in .json");
    const Resolved r = Resolve(root, rel, false);
    if (r.status != 200) return SendError(res, r.status, r.message);
    if (json::parse(req.body, nullptr, false).is_discarded())
      return SendError(res, 400, "body: expected the study's JSON text");
    std::string why;
    if (!SaveFile(r.path, req.body, why)) return SendError(res, 500, "cannot write " + rel + ": " + why);
    SendJson(res, {{"saved", Relative(root, r.path)}});
  });
  server.Post("/api/duplicate", [root](const httplib::Request& req, httplib::Response& res) {
    const json body = json::parse(req.body, nullptr, false);
    if (!body.is_object() || !body.contains("from") || !body.contains("to") || !body["from"].is_string() ||
        !body["to"].is_string())
      return SendError(res, 400, "body: expected {\"from\": PATH, \"to\": PATH}");
    const std::string to = body["to"];
    if (!EndsWith(to, ".json")) return SendError(res, 400, "to: expected a file name ending in .json");
    const Resolved from = Resolve(root, body["from"], true);
    if (from.status != 200) return SendError(res, from.status, from.message);
    const Resolved dest = Resolve(root, to, false);
    if (dest.status != 200) return SendError(res, dest.status, dest.message);
    std::error_code ec;
    if (fs::exists(fs::symlink_status(dest.path, ec)))
      return SendError(res, 409, "to: " + to + " exists (duplicate never overwrites)");
    fs::copy_file(from.path, dest.path, fs::copy_options::none, ec);
    if (ec) return SendError(res, 500, "cannot copy to " + to + ": " + ec.message());
    SendJson(res, {{"saved", Relative(root, dest.path)}});
  });
  server.Post("/api/validate", [](const httplib::Request& req, httplib::Response& res) {
    const std::string file = req.has_param("path") ? req.get_param_value("path") : "study";
    try {
      const json study = ParseBodyStudy(req.body, file);
      // A sweep: what `camopt sweep` checks before its first case (each case's study when it runs).
      if (study.is_object() && study.contains("sweep") && !study.contains("study"))
        return SendJson(res, {{"ok", true},
                              {"cases", sweep::CheckSweep(study, file)},
                              {"note", "a sweep: each case's study is checked when it runs"}});
      CheckStudy(study, file);
      SendJson(res, {{"ok", true}});
    } catch (const StudyError& e) {
      SendJson(res, {{"ok", false}, {"error", ErrorJson(e)}});
    }
  });
  server.Post("/api/mechanism", [root](const httplib::Request& req, httplib::Response& res) {
    const double angle = req.has_param("angle") ? std::atof(req.get_param_value("angle").c_str()) : 0.0;
    const int points = req.has_param("points") ? std::atoi(req.get_param_value("points").c_str()) : 360;
    // id=ID: echoed as "request_id" in the answer (an error's too), so that a client can tell
    // which of its requests an answer is for and drop the stale ones.
    std::string id;
    if (req.has_param("id")) {
      id = req.get_param_value("id");
      const bool ok = !id.empty() && id.size() <= kMaxMechanismIdLength &&
                      std::all_of(id.begin(), id.end(), [](unsigned char c) {
                        return std::isalnum(c) || c == '.' || c == '_' || c == '-' || c == ':';
                      });
      if (!ok)
        return SendError(res, 400, "id: expected 1 to " + std::to_string(kMaxMechanismIdLength) +
                                       " letters, digits, '.', '_', '-' or ':'");
    }
    // frames=N: the mechanism at N angles over one revolution, angle + 360 k/N for k = 0 … N − 1,
    // in one answer (the studio's Play draws them without a request per frame).
    int frames = 0;
    if (req.has_param("frames")) {
      const std::string text = req.get_param_value("frames");
      char* end = nullptr;
      const long n = std::strtol(text.c_str(), &end, 10);
      if (text.empty() || *end != '\0' || n < 1 || n > kMaxMechanismFrames)
        return SendError(res, 400, "frames: expected a whole number of frames from 1 to " +
                                       std::to_string(kMaxMechanismFrames));
      const long clamped = std::clamp(points, 36, 4000);
      if (n * clamped > kMaxMechanismFramePoints)
        return SendError(res, 400, "frames: " + std::to_string(n) + " frames of " + std::to_string(clamped) +
                                       " points each are more than " + std::to_string(kMaxMechanismFramePoints) +
                                       " points in all (fewer frames or points)");
      frames = int(n);
    }
    // Sent uncompressed: cpp-httplib (Debian's, built with brotli) compresses an answer typed exactly
    // "application/json" with brotli at its slowest setting when the client accepts it, as browsers
    // do: one angle's 37 kB took 114 ms instead of 9 ms, a revolution's 3.8 MB 15 s instead of
    // 0.4 s (curl -H 'Accept-Encoding: br', by hand). With a charset it is left as it is.
    const auto answer = [&](json j, int status = 200) {
      if (!id.empty()) j["request_id"] = id;
      res.status = status;
      res.set_content(j.dump(-1, ' ', false, json::error_handler_t::replace), "application/json; charset=utf-8");
    };
    try {
      const json study = ParseBodyStudy(req.body, "study");
      // A sizing study with result=FOLDER (its run's output folder): the optimum that run wrote.
      json optimum;
      const std::string kind = study.is_object() && study.contains("study") && study["study"].is_string()
                                   ? study["study"].get<std::string>()
                                   : std::string();
      if (req.has_param("result") && !SizingOptimumFile(kind).empty()) {
        // The file itself resolved (its links followed) inside the folder; absent: not run yet.
        const std::string rel = req.get_param_value("result") + "/" + SizingOptimumFile(kind);
        const Resolved r = Resolve(root, rel, true);
        std::error_code ec;
        if (r.status != 200 && r.status != 404) return SendError(res, r.status, r.message);
        if (r.status == 200 && fs::is_regular_file(r.path, ec))
          optimum = ParseStudyText(ReadFileCapped(r.path.string(), size_t{64} << 20, "file"), rel,
                                   CurrentInputLimits().max_depth);
      }
      // A cycloid_ltca study with result=FOLDER: the pins' loads and pressures of that run's LTCA
      // (its per_angle.csv; result.json's torque checked against the study's).
      std::optional<LoadedRun> run;
      if (req.has_param("result") && kind == "cycloid_ltca") {
        const std::string folder = req.get_param_value("result");
        const Resolved r = Resolve(root, folder + "/per_angle.csv", true);
        std::error_code ec;
        if (r.status != 200 && r.status != 404) return SendError(res, r.status, r.message);
        if (r.status == 200 && fs::is_regular_file(r.path, ec)) {
          run = LoadedRun{folder, ReadFileCapped(r.path.string(), size_t{64} << 20, "file")};
          const Resolved rj = Resolve(root, folder + "/result.json", true);
          if (rj.status == 200 && fs::is_regular_file(rj.path, ec)) {
            const json result = json::parse(ReadFileCapped(rj.path.string(), size_t{64} << 20, "file"), nullptr, false);
            if (result.is_object() && result.contains("torque_Nm") && result["torque_Nm"].is_number())
              run->torque_Nm = result["torque_Nm"].get<double>();
          }
        }
      }
      if (frames == 0) return answer(MechanismAt(study, angle, points, optimum, run ? &*run : nullptr));
      json all = json::array(), angles = json::array();
      for (int k = 0; k < frames; ++k) {
        const double a = angle + 360.0 * k / frames;
        all.push_back(MechanismAt(study, a, points, optimum, run ? &*run : nullptr));
        angles.push_back(a);
      }
      json out = {{"kind", all[0]["kind"]},
                  {"supported", all[0]["supported"]},
                  {"frame_step_deg", 360.0 / frames},
                  {"angles_deg", angles},
                  {"frames", std::move(all)}};
      answer(std::move(out));
    } catch (const StudyError& e) {
      answer({{"error", ErrorJson(e)}}, 422);
    }
  });
  server.Post("/api/runs", [&studio, root](const httplib::Request& req, httplib::Response& res) {
    const json body = json::parse(req.body, nullptr, false);
    if (!body.is_object() || !body.contains("path") || !body["path"].is_string())
      return SendError(res, 400, "body: expected {\"path\": STUDY_FILE}");
    const Resolved r = Resolve(root, body["path"], true);
    if (r.status != 200) return SendError(res, r.status, r.message);
    std::string error;
    const auto run = studio.Start(r.path, error);
    if (!run) return SendError(res, error.rfind("run ", 0) == 0 ? 409 : error.rfind("runs: ", 0) == 0 ? 503 : 500, error);
    SendJson(res, RunStatus(*run), 201);
  });
  server.Get("/api/runs", [&studio](const httplib::Request&, httplib::Response& res) {
    SendJson(res, studio.ListRuns());
  });
  server.Get(R"(/api/runs/(\d+))", [&studio](const httplib::Request& req, httplib::Response& res) {
    const auto run = studio.Find(IdOf(req));
    if (!run) return SendError(res, 404, "no such run");
    SendJson(res, RunStatus(*run));
  });
  server.Post(R"(/api/runs/(\d+)/cancel)", [&studio](const httplib::Request& req, httplib::Response& res) {
    const auto run = studio.Find(IdOf(req));
    if (!run) return SendError(res, 404, "no such run");
    Cancel(*run);
    SendJson(res, RunStatus(*run));
  });
  server.Get(R"(/api/runs/(\d+)/result)", [&studio, root](const httplib::Request& req, httplib::Response& res) {
    const auto run = studio.Find(IdOf(req));
    if (!run) return SendError(res, 404, "no such run");
    json status = RunStatus(*run);
    if (!status["finished"].get<bool>()) return SendJson(res, status, 409);
    const fs::path out = root / status["out"].get<std::string>();
    std::ifstream in(out / "result.json");
    const json result = json::parse(in, nullptr, false);
    if (!result.is_object()) return SendJson(res, status);
    status["result"] = result;
    json files = json::array();
    std::error_code ec;
    for (fs::directory_iterator it(out, ec), end; !ec && it != end; it.increment(ec))
      if (it->is_regular_file(ec)) files.push_back(it->path().filename().string());
    std::sort(files.begin(), files.end());
    status["files"] = files;
    std::ifstream study_in(root / status["study"].get<std::string>());
    json study = json::parse(study_in, nullptr, false);
    if (!study.is_object()) study = json::object();
    const HeadlineTable table = EvaluateHeadlines(result.value("study", std::string()), study, result);
    json rows = json::array();
    for (const HeadlineRow& row : table.rows)
      rows.push_back({{"label", row.label}, {"value", row.value}, {"limit", row.limit}, {"margin", row.margin},
                      {"status", row.status}});
    status["headlines"] = {{"verdict", VerdictOf(table, result)}, {"rows", rows}, {"registered", table.registered}};
    SendJson(res, status);
  });
  // Live progress: server-sent events "progress" (the CLI's JSON progress reports), "message"
  // (its other lines) and "end". A stream closed before "end" cancels the run (a comment line every
  // 0.3 s finds a closed connection even while the run reports nothing).
  server.Get(R"(/api/runs/(\d+)/events)", [&studio](const httplib::Request& req, httplib::Response& res) {
    const auto run = studio.Find(IdOf(req));
    if (!run) return SendError(res, 404, "no such run");
    auto next = std::make_shared<size_t>(0);
    auto ended = std::make_shared<bool>(false);
    res.set_header("Cache-Control", "no-cache");
    res.set_chunked_content_provider(
        "text/event-stream",
        [run, next, ended](size_t, httplib::DataSink& sink) {
          std::vector<std::string> pending;
          bool finished = false;
          {
            std::unique_lock<std::mutex> lock(run->mutex);
            run->changed.wait_for(lock, std::chrono::milliseconds(300),
                                  [&] { return run->events.size() > *next || run->finished; });
            pending.assign(run->events.begin() + static_cast<long>(*next), run->events.end());
            *next = run->events.size();
            finished = run->finished;
          }
          if (pending.empty() && !finished) pending.push_back(": waiting\n\n");
          for (const std::string& e : pending)
            if (!sink.write(e.data(), e.size())) return false;
          if (finished) {
            *ended = true;
            sink.done();
          }
          return true;
        },
        [run, ended](bool success) {
          if (!success || !*ended) Cancel(*run);  // the browser went away mid-run
        });
  });
}

std::string FindWebDir(const std::string& given) {
  if (!given.empty()) return given;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return "";
  for (const fs::path& candidate :
       {exe.parent_path() / "web", exe.parent_path().parent_path() / "share" / "camopt" / "web"})
    if (fs::is_regular_file(candidate / "index.html", ec)) return candidate.string();
  return "";
}

}  // namespace

// A connection's reads, each bounded by the read timeout and all of one request by a deadline:
// a client that sends its request a byte at a time, or never finishes it, holds a worker for at
// most the deadline (the library's own stream bounds each read only, so a byte every few seconds
// held a worker for ever). Reads are buffered: the library reads a request's head a byte at a time.
class DeadlineStream final : public httplib::Stream {
 public:
  using Clock = std::chrono::steady_clock;
  DeadlineStream(int fd, Clock::time_point deadline, std::chrono::milliseconds read_timeout,
                 std::chrono::milliseconds write_timeout)
      : fd_(fd), deadline_(deadline), read_timeout_(read_timeout), write_timeout_(write_timeout) {}

  bool is_readable() const override { return begin_ < end_ || Wait(POLLIN, ReadWait()); }
  bool is_writable() const override { return Wait(POLLOUT, write_timeout_); }
  ssize_t read(char* ptr, size_t size) override {
    if (begin_ == end_) {
      if (!Wait(POLLIN, ReadWait())) return -1;
      ssize_t n;
      do n = ::recv(fd_, buffer_, sizeof buffer_, 0);
      while (n < 0 && errno == EINTR);
      if (n <= 0) return n;
      begin_ = 0;
      end_ = size_t(n);
    }
    const size_t n = std::min(size, end_ - begin_);
    std::memcpy(ptr, buffer_ + begin_, n);
    begin_ += n;
    return ssize_t(n);
  }
  ssize_t write(const char* ptr, size_t size) override {
    if (!is_writable()) return -1;
    ssize_t n;
    do n = ::send(fd_, ptr, size, MSG_NOSIGNAL);
    while (n < 0 && errno == EINTR);
    return n;
  }
  void get_remote_ip_and_port(std::string& ip, int& port) const override { Address(true, ip, port); }
  void get_local_ip_and_port(std::string& ip, int& port) const override { Address(false, ip, port); }
  socket_t socket() const override { return fd_; }
  void set_deadline(Clock::time_point deadline) { deadline_ = deadline; }

 private:
  std::chrono::milliseconds ReadWait() const {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline_ - Clock::now());
    return std::max(std::chrono::milliseconds(0), std::min(left, read_timeout_));
  }
  bool Wait(short events, std::chrono::milliseconds timeout) const {
    pollfd p{fd_, events, 0};
    int r;
    do r = ::poll(&p, 1, int(timeout.count()));
    while (r < 0 && errno == EINTR);
    return r > 0 && (p.revents & (events | POLLHUP | POLLERR));
  }
  void Address(bool remote, std::string& ip, int& port) const {
    sockaddr_storage a{};
    socklen_t n = sizeof a;
    ip.clear();
    port = 0;
    if ((remote ? ::getpeername(fd_, reinterpret_cast<sockaddr*>(&a), &n)
                : ::getsockname(fd_, reinterpret_cast<sockaddr*>(&a), &n)) != 0)
      return;
    char host[NI_MAXHOST], service[NI_MAXSERV];
    if (::getnameinfo(reinterpret_cast<sockaddr*>(&a), n, host, sizeof host, service, sizeof service,
                      NI_NUMERICHOST | NI_NUMERICSERV) == 0) {
      ip = host;
      port = std::atoi(service);
    }
  }

  int fd_;
  Clock::time_point deadline_;
  std::chrono::milliseconds read_timeout_, write_timeout_;
  char buffer_[4096];
  size_t begin_ = 0, end_ = 0;
};

// The studio's server: each connection waits at most the idle time for a request to begin, then
// has `request_timeout` to deliver it (head and body); one client address holds at most
// kConnectionsPerClient connections at once (more are answered 503 at once), fewer than the
// workers, so one client's slow connections cannot hold every worker.
class GuardedServer final : public httplib::Server {
 public:
  static constexpr int kConnectionsPerClient = 48;
  static constexpr int kWorkers = kConnectionsPerClient + 16;
  explicit GuardedServer(std::chrono::milliseconds request_timeout) : request_timeout_(request_timeout) {
    new_task_queue = [] { return new httplib::ThreadPool(kWorkers); };
  }

 private:
  bool process_and_close_socket(socket_t fd) override {
    std::string client;
    int port = 0;
    DeadlineStream(fd, DeadlineStream::Clock::now(), kIdle, kIdle).get_remote_ip_and_port(client, port);
    bool admitted;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      admitted = ++connections_[client] <= kConnectionsPerClient;
    }
    bool ok = true;
    if (!admitted) {
      const std::string body = "{\"error\": \"too many connections from " + client + " at once (at most " +
                               std::to_string(kConnectionsPerClient) + ")\"}";
      const std::string answer = "HTTP/1.1 503 Service Unavailable\r\nContent-Type: application/json\r\n"
                                 "Connection: close\r\nContent-Length: " +
                                 std::to_string(body.size()) + "\r\n\r\n" + body;
      DeadlineStream(fd, DeadlineStream::Clock::now(), kIdle, kIdle).write(answer.data(), answer.size());
    } else {
      // One stream for the connection's requests, so bytes of the next request read with this one
      // stay in its buffer.
      DeadlineStream stream(fd, DeadlineStream::Clock::now() + kIdle, kIdle, kWrite);
      for (size_t left = keep_alive_max_count_; left > 0 && is_running(); --left) {
        // Idle: the next request must begin within the idle time (the first one too).
        stream.set_deadline(DeadlineStream::Clock::now() + kIdle);
        if (!stream.is_readable()) break;
        stream.set_deadline(DeadlineStream::Clock::now() + request_timeout_);
        bool closed = false;
        ok = process_request(stream, left == 1 || !is_running(), closed, nullptr);
        if (!ok || closed) break;
      }
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (--connections_[client] == 0) connections_.erase(client);
    }
    ::shutdown(fd, SHUT_RDWR);
    ::close(fd);
    return ok;
  }

  static constexpr std::chrono::milliseconds kIdle{5000}, kWrite{5000};
  std::chrono::milliseconds request_timeout_;
  std::mutex mutex_;
  std::map<std::string, int> connections_;
};

int ServeMain(const ServeOptions& options) {
  std::error_code ec;
  const fs::path root = fs::canonical(options.folder, ec);
  if (ec || !fs::is_directory(root, ec)) {
    std::cerr << "camopt: error: serve: " << options.folder << ": expected a folder of study files, found "
              << (ec ? ec.message() : std::string("not a folder")) << "\n";
    return 2;
  }
  const fs::path exe = options.program.empty() ? fs::read_symlink("/proc/self/exe", ec) : fs::path(options.program);
  if (ec) {
    std::cerr << "camopt: error: serve: cannot find the program's own file (/proc/self/exe): " << ec.message()
              << "\n";
    return 1;
  }
  std::string web = FindWebDir(options.web_dir);
  if (!web.empty()) web = fs::absolute(web, ec).string();
  // The server works in the folder, as its runs do: a study's relative paths (a roller catalogue,
  // a sweep's base) and its messages' file names are then those of `camopt run` in the folder.
  fs::current_path(root, ec);
  if (ec) {
    std::cerr << "camopt: error: serve: " << options.folder << ": cannot work in it: " << ec.message() << "\n";
    return 2;
  }
  // Beyond this machine only when asked, and then with a token: the API writes and runs files.
  std::string token;
  if (!IsLoopbackHost(options.host)) {
    if (!options.allow_remote) {
      std::cerr << "camopt: error: serve: --host " << options.host
                << " is not this machine's loopback address: anyone who reaches it could write and run the "
                   "studies of "
                << root.string()
                << "; serve on 127.0.0.1 (the default), or add --allow-remote to serve it with a token\n";
      return 2;
    }
    std::random_device random;
    char hex[9];
    for (int i = 0; i < 4; ++i) {
      std::snprintf(hex, sizeof hex, "%08x", unsigned(random()));
      token += hex;
    }
  }
  // The folder is the boundary of what a study may name, in the server's own checks as in its runs.
  CurrentInputLimits().files_inside = root.string();
  Studio studio(root, exe.string());
  if (!token.empty()) studio.SetToken(token);
  // Threads for the connections (GuardedServer::kWorkers): a browser keeps several open
  // (keep-alive) and each run's event stream holds one for as long as the run lasts.
  GuardedServer server(std::chrono::milliseconds(long(options.request_timeout_s * 1000)));
  server.set_payload_max_length(kMaxBodyBytes);
  server.set_pre_routing_handler([&studio, &token](const httplib::Request& req, httplib::Response& res) {
    std::string why;
    int status = 403;
    if (!studio.Allowed(req, why, status)) {
      SendError(res, status, why);
      return httplib::Server::HandlerResponse::Handled;
    }
    // The token given in the address becomes a cookie, so the page's own requests carry it.
    if (!token.empty() && req.get_param_value("token") == token)
      res.set_header("Set-Cookie", "camopt_token=" + token + "; Path=/; HttpOnly; SameSite=Strict");
    // A body must state its length: the library holds a Content-Length to the cap before it reads
    // the body (413), but buffers a chunked body whole. The pre-routing handler runs before any of
    // the body is read, so a chunked one is refused here, unread, and the connection closed.
    if (req.has_header("Transfer-Encoding") && req.get_header_value("Transfer-Encoding") != "identity") {
      SendError(res, 413,
                "a request body must come with its Content-Length, at most " + std::to_string(kMaxBodyBytes) +
                    " bytes (a body in chunks, Transfer-Encoding \"" + req.get_header_value("Transfer-Encoding") +
                    "\", is not accepted)");
      res.set_header("Connection", "close");
      return httplib::Server::HandlerResponse::Handled;
    }
    return httplib::Server::HandlerResponse::Unhandled;
  });
  if (!web.empty()) {
    server.set_mount_point("/", web);
    server.set_file_extension_and_mimetype_mapping("mjs", "text/javascript");
  } else {
    server.Get("/", [](const httplib::Request&, httplib::Response& res) {
      res.set_content("camopt studio: the front end's files were not found (build or install camopt, or give "
                      "--web DIR); the API answers under /api/.",
                      "text/plain");
    });
  }
  Routes(server, studio);
  int port = options.port;
  if (port == 0) {
    port = server.bind_to_any_port(options.host);
    if (port <= 0) {
      std::cerr << "camopt: error: serve: cannot listen on " << options.host << ": no free port\n";
      return 2;
    }
  } else if (!server.bind_to_port(options.host, port)) {
    std::cerr << "camopt: error: serve: cannot listen on " << options.host << ":" << port
              << " (in use, or not an address of this machine); try --port 0 for a free port\n";
    return 2;
  }
  studio.SetAddress(options.host, port);
  const std::string host = options.host.find(':') != std::string::npos ? "[" + options.host + "]" : options.host;
  std::cout << "camopt studio: http://" << host << ":" << port << "/" << std::endl;
  if (!token.empty())
    std::cerr << "camopt: warning: serve: listening on " << host << ":" << port
              << " beyond this machine (--allow-remote): whoever has the token can write and run the studies "
                 "of this folder; the traffic is not encrypted. Open http://<this machine's name>:"
              << port << "/?token=" << token << "\n";
  if (web.empty()) std::cerr << "camopt: warning: serve: the front end's files were not found; API only\n";
  std::cerr << "camopt: serving the study files of " << root.string() << " (Ctrl-C stops)" << std::endl;
  if (options.on_listening) options.on_listening(port, [&server] { server.stop(); });
  server.listen_after_bind();
  return 0;
}

}  // namespace camopt::studies

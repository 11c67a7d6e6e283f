// `camopt serve --port 0 FOLDER` as a child process, for the studio's tests: the port read from its
// first line on stdout, the child stopped with SIGINT when the object goes. Include after Eigen
// (through test_util.h): httplib.h brings <resolv.h>, whose macro _res is a parameter name in
// Eigen's headers.
#pragma once

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <fcntl.h>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <httplib.h>

namespace camopt::testing {

/// The studio of `binary` (the built camopt by default) serving `folder`; `extra` options go
/// before the folder; with `stderr_file`, the child's stderr goes there.
class StudioChild {
 public:
  explicit StudioChild(const std::filesystem::path& folder, const std::vector<std::string>& extra = {},
                       const std::string& stderr_file = "/dev/null", const char* binary = CAMOPT_BINARY) {
    int out[2];
    if (pipe(out) != 0) return;
    std::vector<std::string> args = {"camopt", "serve", "--port", "0"};
    args.insert(args.end(), extra.begin(), extra.end());
    args.push_back(folder.string());
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    pid_ = fork();
    if (pid_ == 0) {
      dup2(out[1], 1);
      const int err_fd = open(stderr_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      dup2(err_fd, 2);
      close(out[0]);
      execv(binary, argv.data());
      _exit(127);
    }
    close(out[1]);
    std::string line;
    pollfd p{out[0], POLLIN, 0};
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (line.find('\n') == std::string::npos && std::chrono::steady_clock::now() < deadline) {
      if (poll(&p, 1, 200) <= 0) continue;
      char c[256];
      const ssize_t n = read(out[0], c, sizeof c);
      if (n <= 0) break;
      line.append(c, static_cast<size_t>(n));
    }
    close(out[0]);
    first_line_ = line;
    // "camopt studio: http://HOST:PORT/"
    const std::string prefix = "camopt studio: http://";
    const size_t slash = line.find('/', prefix.size()), colon = line.rfind(':', slash);
    if (line.rfind(prefix, 0) == 0 && slash != std::string::npos && colon != std::string::npos && colon > prefix.size())
      port_ = std::atoi(line.c_str() + colon + 1);
  }
  ~StudioChild() {
    if (pid_ > 0) {
      kill(pid_, SIGINT);
      int status = 0;
      waitpid(pid_, &status, 0);
    }
  }
  int port() const { return port_; }
  pid_t pid() const { return pid_; }
  const std::string& first_line() const { return first_line_; }
  httplib::Client Client() const {
    httplib::Client c("127.0.0.1", port_);
    c.set_read_timeout(60, 0);
    return c;
  }

 private:
  pid_t pid_ = -1;
  int port_ = 0;
  std::string first_line_;
};

}  // namespace camopt::testing

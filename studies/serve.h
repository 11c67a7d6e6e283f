// `camopt serve`: the studio, a local web app over the study files of one folder (docs/studio.md).
//
// An HTTP server (cpp-httplib) bound to 127.0.0.1 by default serves the front end (web/, installed
// as share/camopt/web) and a JSON API: the kinds and their JSON Schemas, the study files of the
// folder (list, open, save, duplicate), validation with the CLI's messages and JSON paths, runs,
// their live progress as server-sent events, and the mechanism at an input angle
// (studies/studio_mechanism.h). Each run is a child process `camopt run STUDY --out DIR --quiet
// --progress json` (a sweep file: `camopt sweep …`), so it writes exactly the CLI's output folder
// and a crash cannot take the server down; cancelling sends it SIGINT (the CLI removes its
// temporary folder and exits 130).
//
// Refused: a request whose Host or Origin is not the server's own address (403: another web site,
// DNS rebinding), a path outside the folder after resolving symbolic links (403), a body above
// kMaxBodyBytes (413). When the event stream of a run is closed before the run ends, the run is
// cancelled.
#pragma once

#include <cstddef>
#include <functional>
#include <string>

namespace camopt::studies {

struct ServeOptions {
  std::string folder = ".";
  std::string host = "127.0.0.1";
  int port = 8765;      ///< 0: a free port chosen by the system
  std::string web_dir;  ///< empty: the folder "web" beside the program, else "../share/camopt/web" from it
  /// A host that is not a loopback address (127.x, ::1, localhost) is refused (exit 2) unless this
  /// is set; then every request needs the token printed at start (docs/studio.md).
  bool allow_remote = false;
  /// Seconds a connection has to deliver a request (its head and body) once it has begun; a
  /// connection also waits at most 5 s idle for a request to begin (docs/studio.md).
  double request_timeout_s = 10;
  /// The camopt program the runs start; empty: this program (`camopt serve`'s own file). A program
  /// that serves in-process (the request fuzzer) names the camopt binary here.
  std::string program;
  /// Called once the server listens, with its port and a function that stops it (ServeMain then
  /// returns 0); for serving in-process.
  std::function<void(int port, std::function<void()> stop)> on_listening;
};

/// Whether the studio's --host reaches only this machine: 127.0.0.0/8, ::1 or localhost.
inline bool IsLoopbackHost(const std::string& host) {
  return host == "localhost" || host == "::1" || host.rfind("127.", 0) == 0;
}

/// Largest request body the studio reads (a study file is a few kB).
inline constexpr size_t kMaxBodyBytes = size_t{1} << 20;

/// Runs the studio keeps going at once; a run asked for beyond them is refused with 503 (each run
/// is a `camopt run` process: unbounded, a client starting one per study starves the machine).
inline constexpr size_t kMaxRunningRuns = 8;
/// The finished runs the studio remembers (GET /api/runs, their events and results): the oldest
/// beyond this are forgotten (their reader threads joined), so a studio left running for days does
/// not grow with every run it ever made. Their output folders stay.
inline constexpr size_t kMaxKeptRuns = 100;

/// POST /api/mechanism?frames=N: at most this many frames in one answer (one per degree), and at
/// most kMaxMechanismFramePoints outline points over all of them (N × points: 180 frames of 720
/// points; an answer stays a few MB), else 400.
inline constexpr long kMaxMechanismFrames = 360;
inline constexpr long kMaxMechanismFramePoints = 180 * 720;
/// POST /api/mechanism?id=ID: the longest ID echoed (letters, digits, '.', '_', '-', ':').
inline constexpr size_t kMaxMechanismIdLength = 64;

/// Runs the studio until the process is interrupted; prints "camopt studio: http://HOST:PORT/" on
/// stdout once it listens. Returns 2 when the folder or the address cannot be used.
int ServeMain(const ServeOptions& options);

}  // namespace camopt::studies

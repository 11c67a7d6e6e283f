// `camopt serve` (studies/serve.h): the studio's server as a child process on a free port, driven
// with cpp-httplib's client: what it refuses (other origins and hosts, paths outside its folder,
// large bodies), validation with the CLI's message and JSON path, a run that writes the CLI's
// output folder, and a client that disconnects mid-run (the run is cancelled, nothing left).
// The mechanism endpoint's numbers (studies/studio_mechanism.h) against closed forms, the sizings'
// start and optimum among them.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <poll.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "fuzz/studio_target.h"
#include "studies/serve.h"
#include "studies/studio_mechanism.h"
#include "tests/test_util.h"
// After Eigen (through test_util.h): httplib.h brings <resolv.h>, whose macro _res is a parameter
// name in Eigen's headers.
#include <httplib.h>
#include "tests/studio_child.h"

namespace serve_test {

namespace fs = std::filesystem;
using camopt::testing::ReadFile;
using camopt::testing::TempDir;
using camopt::testing::WriteFile;
using nlohmann::json;

fs::path Example(const std::string& name) { return fs::path(CAMOPT_SOURCE_DIR) / "studies" / "examples" / name; }

using Studio = camopt::testing::StudioChild;

// Follows a run's events to its end; returns the "end" event's data.
json FollowToEnd(const Studio& studio, int id) {
  auto c = studio.Client();
  std::string text;
  auto res = c.Get(("/api/runs/" + std::to_string(id) + "/events").c_str(), [&](const char* d, size_t n) {
    text.append(d, n);
    return true;
  });
  EXPECT_TRUE(res) << "events stream";
  const size_t at = text.find("event: end\ndata: ");
  if (at == std::string::npos) return json();
  const size_t start = at + std::string("event: end\ndata: ").size();
  return json::parse(text.substr(start, text.find('\n', start) - start), nullptr, false);
}

TEST(Serve, PrintsItsAddressAndServesTheFrontEndAndTheKinds) {
  const fs::path dir = TempDir("serve-address");
  Studio studio(dir);
  ASSERT_GT(studio.port(), 0) << studio.first_line();
  auto c = studio.Client();
  auto kinds = c.Get("/api/kinds");
  ASSERT_TRUE(kinds);
  EXPECT_EQ(kinds->status, 200);
  const json k = json::parse(kinds->body);
  EXPECT_NE(std::find(k.begin(), k.end(), "lcr_analysis"), k.end());
  auto schema = c.Get("/api/schema/lcr_analysis");
  ASSERT_TRUE(schema);
  EXPECT_EQ(schema->status, 200);
  EXPECT_TRUE(json::parse(schema->body).contains("properties"));
  auto page = c.Get("/");
  ASSERT_TRUE(page);
  EXPECT_EQ(page->status, 200);
  EXPECT_NE(page->body.find("camopt studio"), std::string::npos);
}

TEST(Serve, JsonAnswersAreSentUncompressedToABrowserThatAcceptsBrotli) {
  // A browser sends "Accept-Encoding: gzip, deflate, br"; cpp-httplib would brotli-compress an
  // "application/json" answer at its slowest setting (studies/serve.cc, kJsonType). Read raw.
  const fs::path dir = TempDir("serve-uncompressed");
  WriteFile(dir / "study.json", camopt::testing::Example("lcr_ii.json").dump(2));
  Studio studio(dir);
  ASSERT_GT(studio.port(), 0) << studio.first_line();
  auto c = studio.Client();
  c.set_decompress(false);
  const httplib::Headers browser = {{"Accept-Encoding", "gzip, deflate, br"}};
  for (const std::string url : {"/api/kinds", "/api/files", "/api/schema/lcr_analysis", "/api/file?path=study.json"}) {
    SCOPED_TRACE(url);
    auto r = c.Get(url, browser);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 200);
    EXPECT_FALSE(r->has_header("Content-Encoding")) << r->get_header_value("Content-Encoding");
    EXPECT_EQ(r->get_header_value("Content-Type"), "application/json; charset=utf-8");
    EXPECT_TRUE(json::accept(r->body)) << r->body;
  }
}

TEST(Serve, RefusesOtherOriginsAndHosts) {
  const fs::path dir = TempDir("serve-origin");
  Studio studio(dir);
  ASSERT_GT(studio.port(), 0) << studio.first_line();
  auto c = studio.Client();
  const std::string self = "http://127.0.0.1:" + std::to_string(studio.port());
  auto own = c.Get("/api/kinds", {{"Origin", self}});
  ASSERT_TRUE(own);
  EXPECT_EQ(own->status, 200);
  auto other = c.Get("/api/kinds", {{"Origin", "http://evil.example"}});
  ASSERT_TRUE(other);
  EXPECT_EQ(other->status, 403);
  // Another port of this machine is another origin.
  auto other_port = c.Post("/api/validate", {{"Origin", "http://127.0.0.1:1"}}, "{}", "application/json");
  ASSERT_TRUE(other_port);
  EXPECT_EQ(other_port->status, 403);
  // DNS rebinding: a page of evil.example whose name now points at 127.0.0.1 sends Host evil.example.
  auto rebound = c.Get("/api/files", {{"Host", "evil.example:" + std::to_string(studio.port())}});
  ASSERT_TRUE(rebound);
  EXPECT_EQ(rebound->status, 403);
  auto page = c.Get("/", {{"Host", "evil.example"}});
  ASSERT_TRUE(page);
  EXPECT_EQ(page->status, 403);
}

TEST(Serve, RefusesPathsOutsideItsFolderAlsoThroughSymlinks) {
  const fs::path base = TempDir("serve-paths");
  const fs::path dir = base / "folder";
  fs::create_directories(dir / "sub");
  WriteFile(base / "secret.json", "{\"secret\": 1}");
  WriteFile(dir / "inside.json", "{\"study\": \"lcr_analysis\"}");
  fs::create_symlink(base / "secret.json", dir / "link.json");
  fs::create_symlink(base, dir / "up");
  fs::create_symlink(dir / "inside.json", dir / "sub" / "alias.json");  // inside: allowed
  Studio studio(dir);
  ASSERT_GT(studio.port(), 0) << studio.first_line();
  auto c = studio.Client();
  const auto get = [&](const std::string& p) {
    auto r = c.Get("/api/file", httplib::Params{{"path", p}}, httplib::Headers{});
    return r ? r->status : -1;
  };
  EXPECT_EQ(get("inside.json"), 200);
  EXPECT_EQ(get("sub/alias.json"), 200);
  EXPECT_EQ(get("../secret.json"), 403);
  EXPECT_EQ(get("sub/../../secret.json"), 403);
  EXPECT_EQ(get((base / "secret.json").string()), 403);
  EXPECT_EQ(get("link.json"), 403);
  EXPECT_EQ(get("up/secret.json"), 403);
  EXPECT_EQ(get("absent.json"), 404);
  const auto put = [&](const std::string& p) {
    auto r = c.Put(("/api/file?path=" + p).c_str(), "{\"study\": \"x\"}", "application/json");
    return r ? r->status : -1;
  };
  EXPECT_EQ(put("../written.json"), 403);
  EXPECT_EQ(put("up/written.json"), 403);
  EXPECT_EQ(put("link.json"), 403);
  EXPECT_FALSE(fs::exists(base / "written.json"));
  EXPECT_EQ(ReadFile(base / "secret.json"), "{\"secret\": 1}");
  EXPECT_EQ(put("saved.json"), 200);
  EXPECT_TRUE(fs::exists(dir / "saved.json"));
  auto dup = c.Post("/api/duplicate", "{\"from\": \"inside.json\", \"to\": \"../copy.json\"}", "application/json");
  ASSERT_TRUE(dup);
  EXPECT_EQ(dup->status, 403);
  dup = c.Post("/api/duplicate", "{\"from\": \"inside.json\", \"to\": \"copy.json\"}", "application/json");
  ASSERT_TRUE(dup);
  EXPECT_EQ(dup->status, 200);
  EXPECT_EQ(ReadFile(dir / "copy.json"), ReadFile(dir / "inside.json"));
  dup = c.Post("/api/duplicate", "{\"from\": \"inside.json\", \"to\": \"copy.json\"}", "application/json");
  ASSERT_TRUE(dup);
  EXPECT_EQ(dup->status, 409);  // never overwrites
  auto run = c.Post("/api/runs", "{\"path\": \"link.json\"}", "application/json");
  ASSERT_TRUE(run);
  EXPECT_EQ(run->status, 403);
}

// A save writes a temporary of its own (O_CREAT | O_EXCL | O_NOFOLLOW under the folder's handle):
// a link placed at the temporary's old name, or at the next names, is never written through, and
// the study stays a regular file inside the folder.
TEST(Serve, ASaveNeverWritesThroughALinkAtItsTemporaryName) {
  const fs::path base = TempDir("serve-save-link");
  const fs::path dir = base / "folder";
  fs::create_directories(dir);
  WriteFile(base / "outside.txt", "untouched");
  WriteFile(dir / "s.json", "{\"study\": \"lcr_analysis\"}");
  Studio studio(dir);
  ASSERT_GT(studio.port(), 0) << studio.first_line();
  fs::create_symlink(base / "outside.txt", dir / ".s.json.camopt-save");
  for (int k = 1; k <= 8; ++k)
    fs::create_symlink(base / "outside.txt",
                       dir / (".s.json.camopt-save-" + std::to_string(studio.pid()) + "-" + std::to_string(k)));
  auto c = studio.Client();
  auto r = c.Put("/api/file?path=s.json", "{\"study\": \"disc_cam\"}", "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200) << r->body;
  EXPECT_EQ(ReadFile(base / "outside.txt"), "untouched");
  EXPECT_FALSE(fs::is_symlink(dir / "s.json"));
  EXPECT_EQ(ReadFile(dir / "s.json"), "{\"study\": \"disc_cam\"}");
}

// The fuzzers' exchange (fuzz/studio_target.h) under a timer signal every 0.2 ms, as libFuzzer's
// SIGALRM ticks interrupt it: an interrupted poll, send, recv or connect is tried again, so every
// request is answered (taking EINTR for a silent server was the request target's "no answer in 3 s").
TEST(Serve, TheFuzzersExchangeIsAnsweredUnderATimerSignal) {
  const fs::path dir = TempDir("serve-exchange-signals");
  Studio studio(dir);
  ASSERT_GT(studio.port(), 0) << studio.first_line();
  struct sigaction tick{}, before{};
  tick.sa_handler = [](int) {};
  sigemptyset(&tick.sa_mask);
  tick.sa_flags = 0;  // no SA_RESTART, as libFuzzer's handler
  ASSERT_EQ(sigaction(SIGALRM, &tick, &before), 0);
  itimerval every{{0, 200}, {0, 200}}, off{};
  ASSERT_EQ(setitimer(ITIMER_REAL, &every, nullptr), 0);
  std::map<std::string, int> outcomes;
  for (int k = 0; k < 300; ++k) {
    const camopt::fuzz::Reply r = camopt::fuzz::Exchange(
        studio.port(), camopt::fuzz::WithHost("GET /api/kinds HTTP/1.1\r\nHost: {{HOST}}\r\n\r\n", studio.port()));
    ++outcomes[r.outcome + " " + std::to_string(r.status)];
  }
  setitimer(ITIMER_REAL, &off, nullptr);
  sigaction(SIGALRM, &before, nullptr);
  EXPECT_EQ(outcomes["answered 200"], 300) << ::testing::PrintToString(outcomes);
}

// A name as long as the file system allows is saved (its temporary's name stays within the limit);
// a longer one, in a save or a duplicate, is the client's error (400 naming the limit), not the
// server's (it was a 500 "File name too long").
TEST(Serve, LongFileNamesAreSavedUpToTheLimitAndRefusedBeyondIt) {
  const fs::path dir = TempDir("serve-long-names");
  WriteFile(dir / "s.json", "{\"study\": \"lcr_analysis\"}");
  Studio studio(dir);
  ASSERT_GT(studio.port(), 0) << studio.first_line();
  auto c = studio.Client();
  const std::string longest = std::string(NAME_MAX - 5, 'a') + ".json", beyond = std::string(NAME_MAX, 'b') + ".json";
  auto r = c.Put(("/api/file?path=" + longest).c_str(), "{\"study\": \"disc_cam\"}", "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200) << r->body;
  EXPECT_EQ(ReadFile(dir / longest), "{\"study\": \"disc_cam\"}");
  for (const std::string& rel : {beyond, "sub/" + beyond, beyond + "/s.json"}) {
    r = c.Put(("/api/file?path=" + rel).c_str(), "{}", "application/json");
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 400) << rel << ": " << r->body;
    EXPECT_NE(r->body.find("at most " + std::to_string(NAME_MAX) + " bytes"), std::string::npos) << r->body;
  }
  r = c.Post("/api/duplicate", json{{"from", "s.json"}, {"to", beyond}}.dump(), "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400) << r->body;
  r = c.Post("/api/duplicate", json{{"from", "s.json"}, {"to", "copy-" + longest.substr(5)}}.dump(),
             "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200) << r->body;
  r = c.Get(("/api/file?path=" + beyond).c_str());
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400) << r->body;
  // Nothing else was left in the folder (no temporary).
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  EXPECT_EQ(names.size(), 3u) << ::testing::PrintToString(names);
}

// Eight concurrent saves of one study, thirty times: the file is always one whole body, never a
// mix of two.
TEST(Serve, ConcurrentSavesOfOneStudyNeverMixTheirBodies) {
  const fs::path dir = TempDir("serve-save-race");
  Studio studio(dir);
  ASSERT_GT(studio.port(), 0) << studio.first_line();
  std::vector<std::string> bodies;
  for (int k = 0; k < 8; ++k)
    bodies.push_back("{\"study\": \"lcr_analysis\", \"description\": \"" + std::string(200000, char('a' + k)) + "\"}");
  for (int trial = 0; trial < 30; ++trial) {
    std::vector<std::thread> savers;
    std::vector<int> codes(8, -1);
    for (int k = 0; k < 8; ++k)
      savers.emplace_back([&, k] {
        auto c = studio.Client();
        auto r = c.Put("/api/file?path=s.json", bodies[k], "application/json");
        codes[k] = r ? r->status : -1;
      });
    for (auto& t : savers) t.join();
    for (int k = 0; k < 8; ++k) EXPECT_EQ(codes[k], 200) << "trial " << trial << " save " << k;
    const std::string saved = ReadFile(dir / "s.json");
    EXPECT_NE(std::find(bodies.begin(), bodies.end(), saved), bodies.end()) << "trial " << trial;
  }
  for (const auto& e : fs::directory_iterator(dir))
    EXPECT_EQ(e.path().filename().string().find(".camopt-save"), std::string::npos) << e.path();
}

// Six concurrent requests to run one study: exactly one is accepted, the others get 409.
TEST(Serve, OfSixConcurrentRunsOfOneStudyOneIsAccepted) {
  const fs::path dir = TempDir("serve-run-race");
  fs::copy_file(Example("cycloid_min_size_paper.json"), dir / "s.json");
  Studio studio(dir);
  ASSERT_GT(studio.port(), 0) << studio.first_line();
  std::vector<std::thread> starters;
  std::vector<int> codes(6, -1);
  std::vector<std::string> bodies(6);
  for (int k = 0; k < 6; ++k)
    starters.emplace_back([&, k] {
      auto c = studio.Client();
      auto r = c.Post("/api/runs", "{\"path\": \"s.json\"}", "application/json");
      codes[k] = r ? r->status : -1;
      if (r) bodies[k] = r->body;
    });
  for (auto& t : starters) t.join();
  EXPECT_EQ(std::count(codes.begin(), codes.end(), 201), 1);
  EXPECT_EQ(std::count(codes.begin(), codes.end(), 409), 5);
  auto c = studio.Client();
  for (int k = 0; k < 6; ++k)
    if (codes[k] == 201) {
      const int id = json::parse(bodies[k])["id"].get<int>();
      c.Post(("/api/runs/" + std::to_string(id) + "/cancel").c_str(), "", "application/json");
      FollowToEnd(studio, id);
    }
}

// Sends `request` as it is on a new connection to the studio and returns the first response (its
// head and a body of its Content-Length), or what came before the server closed the connection or
// 5 s passed.
std::string RawExchange(int port, const std::string& request) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  if (fd < 0) return "";
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(uint16_t(port));
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  timeval t{5, 0};
  ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &t, sizeof t);
  std::string out;
  if (::connect(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0 &&
      ::send(fd, request.data(), request.size(), MSG_NOSIGNAL) == ssize_t(request.size())) {
    char buf[4096];
    for (ssize_t n; (n = ::recv(fd, buf, sizeof buf, 0)) > 0;) {
      out.append(buf, size_t(n));
      const size_t end = out.find("\r\n\r\n"), length = out.find("Content-Length: ");
      if (end != std::string::npos && length != std::string::npos && length < end &&
          out.size() >= end + 4 + std::stoul(out.substr(length + 16)))
        break;
    }
  }
  ::close(fd);
  return out;
}

TEST(Serve, RefusesBodiesAboveTheLimit) {
  const fs::path dir = TempDir("serve-body");
  Studio studio(dir);
  ASSERT_GT(studio.port(), 0) << studio.first_line();
  auto c = studio.Client();
  const std::string big(camopt::studies::kMaxBodyBytes + 1, ' ');
  auto res = c.Post("/api/validate", big, "application/json");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 413);
  res = c.Put("/api/file?path=big.json", big, "application/json");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 413);
  EXPECT_FALSE(fs::exists(dir / "big.json"));
  res = c.Post("/api/validate", std::string(1000, ' ') + "{}", "application/json");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 200);  // under the limit: answered
  // A body in chunks (no Content-Length): refused before it is read. Sent by hand: a whole small
  // one, and the first 64 KiB chunk of what would be 20 MiB, with the answer read before the rest.
  const std::string head = "PUT /api/file?path=NAME HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(studio.port()) +
                           "\r\nContent-Type: application/json\r\nTransfer-Encoding: chunked\r\n\r\n";
  auto named = [&](const std::string& name) {
    std::string h = head;
    h.replace(h.find("NAME"), 4, name);
    return h;
  };
  std::string answer = RawExchange(studio.port(), named("small.json") + "10\r\n" + std::string(16, ' ') + "\r\n0\r\n\r\n");
  EXPECT_EQ(answer.rfind("HTTP/1.1 413", 0), 0u) << answer;
  EXPECT_NE(answer.find("Content-Length, at most"), std::string::npos) << answer;
  EXPECT_FALSE(fs::exists(dir / "small.json"));
  answer = RawExchange(studio.port(), named("huge.json") + "10000\r\n" + std::string(65536, ' ') + "\r\n");
  EXPECT_EQ(answer.rfind("HTTP/1.1 413", 0), 0u) << answer;
  EXPECT_FALSE(fs::exists(dir / "huge.json"));
  // The server still answers.
  res = studio.Client().Post("/api/validate", "{}", "application/json");
  ASSERT_TRUE(res);
  EXPECT_NE(res->status, 413);
}

// A connection to the studio that has sent `head` (an unfinished request) and stays open.
int SlowClient(int port, const std::string& head) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  if (fd < 0) return -1;
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(uint16_t(port));
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::connect(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0 ||
      ::send(fd, head.data(), head.size(), MSG_NOSIGNAL) != ssize_t(head.size())) {
    ::close(fd);
    return -1;
  }
  return fd;
}

// What the server has sent on `fd` so far ("" if nothing yet) and whether it closed the connection.
std::pair<std::string, bool> Received(int fd) {
  std::string out;
  char buf[4096];
  for (;;) {
    pollfd p{fd, POLLIN, 0};
    if (::poll(&p, 1, 0) <= 0) return {out, false};
    const ssize_t n = ::recv(fd, buf, sizeof buf, 0);
    if (n <= 0) return {out, true};
    out.append(buf, size_t(n));
  }
}

// Slow clients (a request begun and sent a byte at a time, never finished) neither hold the
// workers nor stay: with 40 of them connected a normal request is answered within 1 s, and each is
// disconnected once the request timeout (2 s here) has passed although it keeps sending.
TEST(Serve, SlowClientsNeitherHoldTheWorkersNorStayConnected) {
  const fs::path dir = TempDir("serve-slow");
  Studio studio(dir, {"--request-timeout", "2"});
  ASSERT_GT(studio.port(), 0) << studio.first_line();
  const std::string head = "GET /api/files HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(studio.port()) + "\r\nX-Slow: ";
  std::vector<int> slow;
  for (int i = 0; i < 40; ++i) slow.push_back(SlowClient(studio.port(), head));
  for (int fd : slow) ASSERT_GE(fd, 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));  // each has a worker now
  const auto t0 = std::chrono::steady_clock::now();
  auto res = studio.Client().Get("/api/kinds");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 200);
  EXPECT_LT(seconds, 1.0);
  // A byte every 0.2 s from each: all are closed by the server after 2 s, none answered.
  std::vector<bool> closed(slow.size(), false);
  const auto start = std::chrono::steady_clock::now();
  size_t open = slow.size();
  while (open > 0 && std::chrono::steady_clock::now() - start < std::chrono::seconds(6)) {
    for (size_t i = 0; i < slow.size(); ++i) {
      if (closed[i]) continue;
      ::send(slow[i], "x", 1, MSG_NOSIGNAL);
      const auto [got, eof] = Received(slow[i]);
      EXPECT_EQ(got.find("200 OK"), std::string::npos);
      if (eof) closed[i] = true, --open;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  const double held = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(open, 0u) << "still connected after " << held << " s";
  EXPECT_GT(held, 1.5);  // not before the timeout
  for (int fd : slow) ::close(fd);
}

// One client address holds at most 48 connections at once: the ones beyond are answered 503 at
// once, and the studio answers again once they are gone.
TEST(Serve, OneClientsConnectionsAreBounded) {
  const fs::path dir = TempDir("serve-bound");
  Studio studio(dir, {"--request-timeout", "3"});
  ASSERT_GT(studio.port(), 0) << studio.first_line();
  const std::string head = "GET /api/files HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(studio.port()) + "\r\n";
  std::vector<int> fds;
  for (int i = 0; i < 52; ++i) fds.push_back(SlowClient(studio.port(), head));
  std::this_thread::sleep_for(std::chrono::milliseconds(1000));
  int refused = 0;
  for (int fd : fds) {
    ASSERT_GE(fd, 0);
    const auto [got, eof] = Received(fd);
    if (got.rfind("HTTP/1.1 503", 0) == 0) {
      ++refused;
      EXPECT_NE(got.find("too many connections from 127.0.0.1"), std::string::npos) << got;
      EXPECT_TRUE(eof);
    } else {  // nothing, or (a connection made seconds ago: the listen queue is short) a 400 at the timeout
      EXPECT_TRUE(got.empty() || got.rfind("HTTP/1.1 400", 0) == 0) << got;
    }
  }
  EXPECT_EQ(refused, 4);
  for (int fd : fds) ::close(fd);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  auto res = studio.Client().Get("/api/kinds");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 200);
}

// The studio's memory after 500 mixed requests (reads, writes, validations, refusals, 404s, bodies
// above the cap) is within 16 MiB of what it was after the first 100: nothing grows per request.
TEST(Serve, MemoryStaysBoundedOverFiveHundredMixedRequests) {
#if defined(__SANITIZE_ADDRESS__)
  // AddressSanitizer keeps freed memory in its quarantine (256 MB by default): the resident size
  // then grows with every request by design, so it measures the sanitizer, not the server.
  GTEST_SKIP() << "resident memory is measured without AddressSanitizer's quarantine";
#endif
  const fs::path dir = TempDir("serve-memory");
  fs::copy_file(Example("lcr_ii.json"), dir / "a.json");
  Studio studio(dir);
  ASSERT_GT(studio.port(), 0) << studio.first_line();
  auto rss_kib = [&] {
    std::ifstream status("/proc/" + std::to_string(studio.pid()) + "/status");
    std::string line;
    while (std::getline(status, line))
      if (line.rfind("VmRSS:", 0) == 0) return std::stol(line.substr(6));
    return -1L;
  };
  const std::string study = ReadFile(dir / "a.json");
  const std::string big(camopt::studies::kMaxBodyBytes + 1, ' ');
  auto c = studio.Client();
  long after100 = 0;
  for (int i = 0; i < 500; ++i) {
    auto request = [&]() -> httplib::Result {
      switch (i % 8) {
        case 0: return c.Get("/api/files");
        case 1: return c.Get("/api/file?path=a.json");
        case 2: return c.Post("/api/validate", study, "application/json");
        case 3: return c.Put("/api/file?path=b" + std::to_string(i % 5) + ".json", study, "application/json");
        case 4: return c.Post("/api/validate", "{\"study\": ", "application/json");
        case 5: return c.Get("/api/file?path=../outside.json");
        case 6: return c.Get("/api/nothing-here");
        default: return c.Post("/api/validate", big, "application/json");
      }
    };
    const httplib::Result r = request();
    ASSERT_TRUE(r) << i;
    EXPECT_LT(r->status, 500) << i;
    if (i == 99) after100 = rss_kib();
  }
  const long after500 = rss_kib();
  ASSERT_GT(after100, 0);
  EXPECT_LT(after500, after100 + 16 * 1024) << after100 << " KiB after 100, " << after500 << " after 500";
}

TEST(Serve, ValidateGivesTheCliMessageWithItsJsonPath) {
  const fs::path dir = TempDir("serve-validate");
  json study = json::parse(ReadFile(Example("lcr_ii.json")));
  study["reducer"]["input"]["roller_diameter_mm"] = -12;
  WriteFile(dir / "bad.json", study.dump(2));
  const std::string cmd = "cd " + dir.string() + " && " + CAMOPT_BINARY + " run bad.json --quiet --out out 2> err.txt";
  const int status = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  std::string cli = ReadFile(dir / "err.txt");
  ASSERT_EQ(cli.rfind("camopt: error: ", 0), 0u) << cli;
  cli = cli.substr(std::string("camopt: error: ").size());
  cli = cli.substr(0, cli.find('\n'));

  Studio studio(dir);
  ASSERT_GT(studio.port(), 0) << studio.first_line();
  auto c = studio.Client();
  auto res = c.Post("/api/validate?path=bad.json", study.dump(), "application/json");
  ASSERT_TRUE(res);
  const json v = json::parse(res->body);
  EXPECT_FALSE(v["ok"].get<bool>());
  EXPECT_EQ(v["error"]["message"], cli);
  EXPECT_EQ(v["error"]["path"], "/reducer/input/roller_diameter_mm");
  res = c.Post("/api/validate?path=lcr_ii.json", ReadFile(Example("lcr_ii.json")), "application/json");
  ASSERT_TRUE(res);
  EXPECT_TRUE(json::parse(res->body)["ok"].get<bool>());
  res = c.Post("/api/validate?path=x.json", "{\"study\": ", "application/json");
  ASSERT_TRUE(res);
  EXPECT_FALSE(json::parse(res->body)["ok"].get<bool>());  // a syntax error, with line and column
  EXPECT_NE(json::parse(res->body)["error"]["message"].get<std::string>().find("x.json"), std::string::npos);
}

// The server works in its folder: a study's relative file (a roller catalogue) is found as
// `camopt run` in the folder finds it.
TEST(Serve, ValidateFindsAStudysRelativeFilesInTheFolder) {
  const fs::path dir = TempDir("serve-relative");
  fs::copy_file(Example("lcr_min_size_catalogue.json"), dir / "study.json");
  fs::copy_file(Example("needle_rollers.json"), dir / "needle_rollers.json");
  Studio studio(dir);
  ASSERT_GT(studio.port(), 0) << studio.first_line();
  auto c = studio.Client();
  auto res = c.Post("/api/validate?path=study.json", ReadFile(dir / "study.json"), "application/json");
  ASSERT_TRUE(res);
  EXPECT_TRUE(json::parse(res->body)["ok"].get<bool>()) << res->body;
  fs::remove(dir / "needle_rollers.json");
  res = c.Post("/api/validate?path=study.json", ReadFile(dir / "study.json"), "application/json");
  ASSERT_TRUE(res);
  EXPECT_FALSE(json::parse(res->body)["ok"].get<bool>()) << res->body;
}

// A sweep is checked when opened as `camopt sweep` checks it before its first case: a good one is
// ok with its number of cases (3 × 3 factorial), a bad one gives the CLI's own message (the text
// after "camopt: error: " of `camopt sweep --dry-run` in the folder), its file and JSON path.
TEST(Serve, ValidateChecksASweepAsCamoptSweepDoes) {
  const fs::path dir = TempDir("serve-sweep");
  fs::copy_file(Example("lcr_ii.json"), dir / "lcr_ii.json");
  const std::string good =
      R"({"sweep": "e", "base": "lcr_ii.json", "vary": [{"path": "/reducer/eccentricity_mm", "values": [1.8, 2, 2.2]},
          {"path": "/load/output_torque_Nm", "range": [40, 80], "count": 3}], "design": "factorial",
          "outputs": ["/max_contact_stress_MPa"]})";
  const std::string bad =
      R"({"sweep": "e", "base": "lcr_ii.json", "vary": [{"path": "/reducer/eccentricity_mm", "values": [1.8], "range": [1, 2]}]})";
  const std::string no_base = R"({"sweep": "e", "base": "missing.json", "vary": [{"path": "/x", "values": [1]}]})";
  WriteFile(dir / "good.json", good);
  WriteFile(dir / "bad.json", bad);
  WriteFile(dir / "no_base.json", no_base);
  Studio studio(dir);
  ASSERT_GT(studio.port(), 0) << studio.first_line();
  auto c = studio.Client();
  auto res = c.Post("/api/validate?path=good.json", good, "application/json");
  ASSERT_TRUE(res);
  json v = json::parse(res->body);
  EXPECT_TRUE(v["ok"].get<bool>()) << res->body;
  EXPECT_EQ(v["cases"], 9);
  for (const std::string name : {"bad", "no_base"}) {
    const std::string text = ReadFile(dir / (name + ".json"));
    res = c.Post(("/api/validate?path=" + name + ".json").c_str(), text, "application/json");
    ASSERT_TRUE(res);
    v = json::parse(res->body);
    ASSERT_FALSE(v["ok"].get<bool>()) << res->body;
    const std::string cmd = "cd " + dir.string() + " && " + CAMOPT_BINARY + " sweep " + name +
                            ".json --out o --dry-run > /dev/null 2> " + name + ".err";
    EXPECT_EQ(WEXITSTATUS(std::system(cmd.c_str())), 2) << name;
    std::string cli = ReadFile(dir / (name + ".err"));
    ASSERT_EQ(cli.rfind("camopt: error: ", 0), 0u) << cli;
    cli = cli.substr(std::string("camopt: error: ").size());
    while (!cli.empty() && cli.back() == '\n') cli.pop_back();
    EXPECT_EQ(v["error"]["message"].get<std::string>(), cli) << name;
  }
  EXPECT_EQ(v["error"]["message"].get<std::string>().rfind("no_base.json: /base: ", 0), 0u) << v.dump();
  res = c.Post("/api/validate?path=bad.json", bad, "application/json");
  v = json::parse(res->body);
  EXPECT_EQ(v["error"]["file"], "bad.json") << res->body;
  EXPECT_EQ(v["error"]["path"], "/vary/0") << res->body;
}

TEST(Serve, ARunWritesTheSameOutputFolderAsTheCli) {
  const fs::path dir = TempDir("serve-run");
  fs::copy_file(Example("lcr_ii.json"), dir / "lcr_ii.json");
  const std::string cmd = "cd " + dir.string() + " && " + CAMOPT_BINARY +
                          " run lcr_ii.json --quiet --out cli_out > /dev/null 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  Studio studio(dir);
  ASSERT_GT(studio.port(), 0) << studio.first_line();
  auto c = studio.Client();
  auto res = c.Post("/api/runs", "{\"path\": \"lcr_ii.json\"}", "application/json");
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 201) << res->body;
  const json run = json::parse(res->body);
  EXPECT_EQ(run["out"], "results/lcr_ii");
  const json end = FollowToEnd(studio, run["id"].get<int>());
  EXPECT_EQ(end["state"], "done") << end.dump();
  EXPECT_EQ(end["exit_code"], 0);
  std::vector<std::string> ours, cli;
  for (const auto& e : fs::directory_iterator(dir / "results" / "lcr_ii")) ours.push_back(e.path().filename());
  for (const auto& e : fs::directory_iterator(dir / "cli_out")) cli.push_back(e.path().filename());
  std::sort(ours.begin(), ours.end());
  std::sort(cli.begin(), cli.end());
  EXPECT_EQ(ours, cli);
  for (const std::string f : {"result.json", "series.csv"})
    EXPECT_EQ(ReadFile(dir / "results" / "lcr_ii" / f), ReadFile(dir / "cli_out" / f)) << f;
  auto result = c.Get(("/api/runs/" + std::to_string(run["id"].get<int>()) + "/result").c_str());
  ASSERT_TRUE(result);
  const json r = json::parse(result->body);
  EXPECT_EQ(r["result"]["study"], "lcr_analysis");
  EXPECT_FALSE(r["headlines"]["rows"].empty());
}

// The studio's runs follow the CLI's output-folder rule: a results folder that holds a user's file
// is not replaced (the run ends with the CLI's exit 2 and its message), and the file stays.
TEST(Serve, ARunNeverReplacesAResultsFolderHoldingAUsersFile) {
  const fs::path dir = TempDir("serve-user-file");
  fs::copy_file(Example("rigidity_gearbox.json"), dir / "rigidity_gearbox.json");
  fs::create_directories(dir / "results" / "rigidity_gearbox");
  WriteFile(dir / "results" / "rigidity_gearbox" / "notes.txt", "mine");
  WriteFile(dir / "results" / "rigidity_gearbox" / "result.json", "{\"mine\": true}");
  Studio studio(dir);
  ASSERT_GT(studio.port(), 0) << studio.first_line();
  auto c = studio.Client();
  auto res = c.Post("/api/runs", "{\"path\": \"rigidity_gearbox.json\"}", "application/json");
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 201) << res->body;
  const json end = FollowToEnd(studio, json::parse(res->body)["id"].get<int>());
  EXPECT_EQ(end["exit_code"], 2) << end.dump();
  EXPECT_NE(end.dump().find("files of yours"), std::string::npos) << end.dump();
  EXPECT_EQ(ReadFile(dir / "results" / "rigidity_gearbox" / "notes.txt"), "mine");
  EXPECT_EQ(ReadFile(dir / "results" / "rigidity_gearbox" / "result.json"), "{\"mine\": true}");
}

// A 2.5 kB sweep that asks for a million Sobol samples over eleven fields is refused by the
// studio's check before it is expanded: within a second, naming the cap (as `camopt sweep`).
TEST(Serve, AHugeSampledSweepIsRefusedBeforeItIsExpanded) {
  const fs::path dir = TempDir("serve-huge-sweep");
  fs::copy_file(Example("lcr_ii.json"), dir / "lcr_ii.json");
  json s = {{"sweep", "huge"}, {"base", "lcr_ii.json"}, {"design", "sobol"}, {"samples", 1000000}};
  s["vary"] = json::array();
  for (const char* p : {"/reducer/eccentricity_mm", "/load/output_torque_Nm", "/load/friction_coefficient",
                        "/material/youngs_modulus_GPa", "/material/poisson_ratio", "/reducer/input/turret_radius_mm",
                        "/reducer/output/turret_radius_mm", "/reducer/input/roller_diameter_mm",
                        "/reducer/output/roller_diameter_mm", "/reducer/input/roller_length_mm",
                        "/reducer/output/roller_length_mm"})
    s["vary"].push_back({{"path", p}, {"range", {1.0, 1.1}}});
  WriteFile(dir / "huge.json", s.dump());
  Studio studio(dir);
  ASSERT_GT(studio.port(), 0) << studio.first_line();
  auto c = studio.Client();
  const auto t0 = std::chrono::steady_clock::now();
  auto res = c.Post("/api/validate?path=huge.json", s.dump(), "application/json");
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 1.0);
  ASSERT_TRUE(res);
  const json v = json::parse(res->body);
  EXPECT_FALSE(v["ok"].get<bool>()) << res->body;
  EXPECT_NE(v.dump().find("more than the cap of 1e+07"), std::string::npos) << res->body;
}

// Runs are processes as heavy as `camopt run`: at most kMaxRunningRuns go on at once, a further
// one is refused with 503 (a client starting one per study file starved the machine and the
// server with it under the request fuzzer), and one finished or cancelled frees its place.
TEST(Serve, RunsBeyondTheCapAreRefusedWith503) {
  const fs::path dir = TempDir("serve-run-cap");
  const size_t n = camopt::studies::kMaxRunningRuns + 2;
  for (size_t k = 0; k < n; ++k)  // about 8 s each on one core
    fs::copy_file(Example("cycloid_ltca_nnm_tolerances.json"), dir / ("slow" + std::to_string(k) + ".json"));
  Studio studio(dir);
  ASSERT_GT(studio.port(), 0) << studio.first_line();
  auto c = studio.Client();
  std::vector<int> started;
  std::vector<int> statuses;
  for (size_t k = 0; k < n; ++k) {
    auto res = c.Post("/api/runs", "{\"path\": \"slow" + std::to_string(k) + ".json\"}", "application/json");
    ASSERT_TRUE(res);
    statuses.push_back(res->status);
    if (res->status == 201) started.push_back(json::parse(res->body)["id"].get<int>());
    else EXPECT_NE(res->body.find("at most " + std::to_string(camopt::studies::kMaxRunningRuns) + " at once"),
                   std::string::npos) << res->body;
  }
  EXPECT_EQ(started.size(), camopt::studies::kMaxRunningRuns);
  EXPECT_EQ(std::count(statuses.begin(), statuses.end(), 503), 2);
  // The server answers meanwhile, and a cancelled run frees a place.
  auto kinds = c.Get("/api/kinds");
  ASSERT_TRUE(kinds);
  EXPECT_EQ(kinds->status, 200);
  ASSERT_FALSE(started.empty());
  auto cancel = c.Post(("/api/runs/" + std::to_string(started[0]) + "/cancel").c_str(), "", "application/json");
  ASSERT_TRUE(cancel);
  FollowToEnd(studio, started[0]);
  auto again = c.Post("/api/runs", "{\"path\": \"slow" + std::to_string(n - 1) + ".json\"}", "application/json");
  ASSERT_TRUE(again);
  EXPECT_EQ(again->status, 201) << again->body;
  if (again->status == 201) started.push_back(json::parse(again->body)["id"].get<int>());
  for (size_t k = 1; k < started.size(); ++k)
    c.Post(("/api/runs/" + std::to_string(started[k]) + "/cancel").c_str(), "", "application/json");
  for (size_t k = 1; k < started.size(); ++k) FollowToEnd(studio, started[k]);
}

// A studio remembers at most kMaxKeptRuns finished runs: 110 quick runs (a study camopt refuses,
// exit 2) leave the newest 100 listed, the oldest forgotten (404), the newest one still readable.
TEST(Serve, OnlyTheNewestFinishedRunsAreRemembered) {
  const fs::path dir = TempDir("serve-kept-runs");
  WriteFile(dir / "bad.json", "{\"study\": \"lcr_analysis\"}");
  Studio studio(dir);
  ASSERT_GT(studio.port(), 0) << studio.first_line();
  auto c = studio.Client();
  const size_t n = camopt::studies::kMaxKeptRuns + 10;
  int last = 0;
  for (size_t k = 0; k < n; ++k) {
    auto res = c.Post("/api/runs", "{\"path\": \"bad.json\"}", "application/json");
    ASSERT_TRUE(res);
    ASSERT_EQ(res->status, 201) << res->body;
    last = json::parse(res->body)["id"].get<int>();
    const json end = FollowToEnd(studio, last);  // one output folder: one run at a time
    EXPECT_EQ(end["exit_code"], 2) << end.dump();
  }
  // Forgetting happens at a start: the last start kept 100 finished runs and itself.
  auto list = c.Get("/api/runs");
  ASSERT_TRUE(list);
  const json runs = json::parse(list->body);
  ASSERT_TRUE(runs.is_array()) << list->body;
  EXPECT_LE(runs.size(), camopt::studies::kMaxKeptRuns + 1);
  EXPECT_GE(runs.size(), camopt::studies::kMaxKeptRuns);
  auto first = c.Get("/api/runs/1");
  ASSERT_TRUE(first);
  EXPECT_EQ(first->status, 404);
  auto newest = c.Get(("/api/runs/" + std::to_string(last)).c_str());
  ASSERT_TRUE(newest);
  EXPECT_EQ(newest->status, 200);
  EXPECT_EQ(json::parse(newest->body)["state"], "error");
}

TEST(Serve, AClientThatDisconnectsMidRunCancelsItAndNothingIsLeft) {
  const fs::path dir = TempDir("serve-disconnect");
  // About 8 s on one core (its tolerance Monte Carlo reports progress all along).
  fs::copy_file(Example("cycloid_ltca_nnm_tolerances.json"), dir / "slow.json");
  Studio studio(dir);
  ASSERT_GT(studio.port(), 0) << studio.first_line();
  auto c = studio.Client();
  auto res = c.Post("/api/runs", "{\"path\": \"slow.json\"}", "application/json");
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 201) << res->body;
  const json run = json::parse(res->body);
  const int id = run["id"];
  const pid_t child = run["pid"];
  ASSERT_GT(child, 0);
  // A second run into the same output folder while the first one writes it: refused.
  auto second = c.Post("/api/runs", "{\"path\": \"slow.json\"}", "application/json");
  ASSERT_TRUE(second);
  EXPECT_EQ(second->status, 409) << second->body;
  std::string text;
  {
    auto events = studio.Client();
    auto r = events.Get(("/api/runs/" + std::to_string(id) + "/events").c_str(), [&](const char* d, size_t n) {
      text.append(d, n);
      return text.find("event: progress") == std::string::npos;  // the first report, then hang up
    });
    EXPECT_FALSE(r);  // cancelled by us
  }
  EXPECT_NE(text.find("event: progress"), std::string::npos);
  const auto hung_up = std::chrono::steady_clock::now();
  json status;
  for (int i = 0; i < 200; ++i) {
    auto s = c.Get(("/api/runs/" + std::to_string(id)).c_str());
    ASSERT_TRUE(s);
    status = json::parse(s->body);
    if (status["finished"].get<bool>()) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - hung_up).count();
  EXPECT_TRUE(status["finished"].get<bool>());
  EXPECT_EQ(status["state"], "cancelled");
  EXPECT_EQ(status["exit_code"], 130);
  EXPECT_LT(seconds, 5.0);
  EXPECT_EQ(kill(child, 0), -1);  // the child is gone (and reaped by the server)
  EXPECT_FALSE(fs::exists(dir / "results" / "slow"));
  for (const auto& e : fs::directory_iterator(dir / "results"))
    ADD_FAILURE() << "left behind: " << e.path();
  // The server lives on.
  auto kinds = c.Get("/api/kinds");
  ASSERT_TRUE(kinds);
  EXPECT_EQ(kinds->status, 200);
}

// A run is a process of its own: it inherits the server's standard streams (stderr a pipe to the server)
// and nothing else, so no client's connection or the listening socket outlives the server's own use.
TEST(Serve, ARunsProcessHoldsNoneOfTheServersSockets) {
  const fs::path dir = TempDir("serve-run-fds");
  fs::copy_file(Example("cycloid_ltca_nnm_tolerances.json"), dir / "slow.json");  // about 8 s
  Studio studio(dir);
  ASSERT_GT(studio.port(), 0) << studio.first_line();
  auto c = studio.Client();
  // Other clients hold connections while the run starts.
  std::vector<int> held;
  for (int k = 0; k < 3; ++k) held.push_back(SlowClient(studio.port(), "GET /api/kinds HTTP/1.1\r\n"));
  auto res = c.Post("/api/runs", "{\"path\": \"slow.json\"}", "application/json");
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 201) << res->body;
  const json run = json::parse(res->body);
  const pid_t child = run["pid"];
  ASSERT_GT(child, 0);
  const fs::path proc = "/proc/" + std::to_string(child);
  // Wait until the child is the run (its command line names the output folder), not the forked server.
  bool is_run = false;
  for (int i = 0; i < 200 && !is_run; ++i) {
    is_run = ReadFile(proc / "cmdline").find("--files-inside") != std::string::npos;
    if (!is_run) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ASSERT_TRUE(is_run);
  std::vector<std::string> fds;
  for (const auto& e : fs::directory_iterator(proc / "fd")) {
    std::error_code ec;
    const std::string target = fs::read_symlink(e.path(), ec).string();
    if (!ec) fds.push_back(e.path().filename().string() + " -> " + target);
  }
  int sockets = 0;
  for (const auto& f : fds) sockets += f.find("socket:") != std::string::npos;
  EXPECT_EQ(sockets, 0) << ::testing::PrintToString(fds);
  for (int fd : held) close(fd);
  auto cancel = c.Post(("/api/runs/" + std::to_string(run["id"].get<int>()) + "/cancel").c_str(), "",
                       "application/json");
  ASSERT_TRUE(cancel);
  FollowToEnd(studio, run["id"].get<int>());
}

// The mechanism at an input angle against closed forms: the input turret stands, the output turret
// turns by θ_o = (1 − n_A m_B/(m_A n_B)) θ (paper eq. 2); the cam's centre is e u(θ); every roller
// centre lies on the pitch curve, so the nearest profile point is a roller radius from it and none
// is nearer (conjugate profiles, paper eqs. 4–9); the rollers' forces, each along the line to the
// pitch point I = e n/(n − m) u(θ), have the moments T_o (output turret, eq. 25) and
// T_o m_B n_A/(n_B m_A) (fixed turret, eq. 24) about the axis.
TEST(Serve, MechanismMatchesTheClosedForms) {
  const json study = json::parse(ReadFile(Example("lcr_ii.json")));
  const double e = 2, theta_deg = 37.5, theta = theta_deg * M_PI / 180;
  const json m = camopt::studies::MechanismAt(study, theta_deg, 4000);
  ASSERT_TRUE(m["supported"].get<bool>());
  EXPECT_NEAR(m["cam_centre_mm"][0].get<double>(), e * std::cos(theta), 1e-6);
  EXPECT_NEAR(m["cam_centre_mm"][1].get<double>(), e * std::sin(theta), 1e-6);
  struct Side {
    int m, n;
    double rd, turn;
  };
  const double turn_out = (1.0 - 13.0 * 14.0 / (12.0 * 15.0)) * theta;
  const Side sides[2] = {{12, 13, 37, 0.0}, {14, 15, 42, turn_out}};
  for (int s = 0; s < 2; ++s) {
    const json& side = m["sides"][s];
    const json& rollers = side["rollers_at"];
    ASSERT_EQ(rollers.size(), size_t(sides[s].n));
    double torque = 0;
    const double k = double(sides[s].n) / (sides[s].n - sides[s].m);
    const double ix = e * k * std::cos(theta), iy = e * k * std::sin(theta);
    for (int i = 0; i < sides[s].n; ++i) {
      const double a = 2 * M_PI * i / sides[s].n + sides[s].turn;
      const double x = rollers[i]["x"], y = rollers[i]["y"];
      EXPECT_NEAR(x, sides[s].rd * std::cos(a), 1e-9) << s << " " << i;
      EXPECT_NEAR(y, sides[s].rd * std::sin(a), 1e-9) << s << " " << i;
      double nearest = 1e9;
      for (const json& p : side["profile_mm"])
        nearest = std::min(nearest, std::hypot(p[0].get<double>() - x, p[1].get<double>() - y));
      EXPECT_NEAR(nearest, 6.0, 2e-3) << "roller " << i << " of side " << s;
      const double dx = ix - x, dy = iy - y, len = std::hypot(dx, dy);
      torque += rollers[i]["force_N"].get<double>() * std::abs(x * dy / len - y * dx / len);
    }
    if (s == 1) { EXPECT_NEAR(torque, 80000.0, 1e-6 * 80000.0); }  // T_o = 80 N·m in N·mm
    // The fixed turret's reaction T_A = T_o m_B n_A/(n_B m_A) (eq. 24).
    if (s == 0) { EXPECT_NEAR(torque, 80000.0 * 14 * 13 / (15.0 * 12), 1e-6 * 80000.0); }
  }
  const json other = camopt::studies::MechanismAt(json::parse(ReadFile(Example("globoidal_cam_paper.json"))), 0, 100);
  EXPECT_FALSE(other["supported"].get<bool>());
  // A sizing without its run: an LCR's start needs the lobe combination the run chooses.
  const json sizing = camopt::studies::MechanismAt(json::parse(ReadFile(Example("lcr_min_size.json"))), 0, 100);
  EXPECT_EQ(sizing["kind"], "sizing");
  EXPECT_FALSE(sizing["start"]["supported"].get<bool>());
  EXPECT_TRUE(sizing["optimum"].is_null());
}

// One revolution in one answer (frames=N, the studio's Play): frame k is the mechanism at
// angle + 360 k/N — its cam centre at e u(θ_k) and its output turret turned by
// (1 − n_A m_B/(m_A n_B)) θ_k (paper eq. 2), each frame the same as the single angle's answer —
// and the id a client gives is echoed on answers and errors; too many frames or points, and an id
// of other characters, are refused.
TEST(Serve, MechanismFramesCoverOneRevolutionAndEchoTheRequestId) {
  const fs::path dir = TempDir("serve-frames");
  fs::copy_file(Example("lcr_ii.json"), dir / "lcr_ii.json");
  const std::string body = ReadFile(dir / "lcr_ii.json");
  Studio studio(dir);
  ASSERT_GT(studio.port(), 0) << studio.first_line();
  auto c = studio.Client();
  auto res = c.Post("/api/mechanism?angle=5&points=100&frames=12&id=g2.s7", body, "application/json");
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 200) << res->body.substr(0, 300);
  const json m = json::parse(res->body);
  EXPECT_EQ(m["request_id"], "g2.s7");
  EXPECT_EQ(m["kind"], "lcr");
  EXPECT_TRUE(m["supported"].get<bool>());
  EXPECT_EQ(m["frame_step_deg"].get<double>(), 30.0);
  ASSERT_EQ(m["frames"].size(), 12u);
  ASSERT_EQ(m["angles_deg"].size(), 12u);
  const double e = 2;
  for (int k = 0; k < 12; ++k) {
    const double deg = 5 + 30 * k, theta = deg * M_PI / 180;
    const json& f = m["frames"][k];
    EXPECT_EQ(m["angles_deg"][k].get<double>(), deg);
    EXPECT_EQ(f["input_angle_deg"].get<double>(), deg);
    EXPECT_NEAR(f["cam_centre_mm"][0].get<double>(), e * std::cos(theta), 1e-6) << k;
    EXPECT_NEAR(f["cam_centre_mm"][1].get<double>(), e * std::sin(theta), 1e-6) << k;
    EXPECT_NEAR(f["output_turret_rotation_deg"].get<double>(), (1.0 - 13.0 * 14.0 / (12.0 * 15.0)) * deg, 1e-9) << k;
    const double turn = (1.0 - 13.0 * 14.0 / (12.0 * 15.0)) * theta;  // output roller 0 at 42 u(turn)
    EXPECT_NEAR(f["sides"][1]["rollers_at"][0]["x"].get<double>(), 42 * std::cos(turn), 1e-9) << k;
    EXPECT_NEAR(f["sides"][1]["rollers_at"][0]["y"].get<double>(), 42 * std::sin(turn), 1e-9) << k;
    if (k % 4 == 1) {  // a few against the single angle's answer
      auto one = c.Post(("/api/mechanism?points=100&angle=" + std::to_string(int(deg))).c_str(), body, "application/json");
      ASSERT_TRUE(one);
      EXPECT_EQ(json::parse(one->body), f) << k;
    }
  }
  // A study the kind refuses: its error, with the id.
  res = c.Post("/api/mechanism?id=abc&frames=3", R"({"study": "lcr_analysis"})", "application/json");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 422);
  EXPECT_EQ(json::parse(res->body)["request_id"], "abc");
  // Refused: no frames, too many, too many points in all, an id of other characters or too long.
  for (const std::string& q : std::vector<std::string>{"frames=0", "frames=361", "frames=2x", "frames=180&points=1000", "id=a%22b", "id=a%20b",
                              "id=" + std::string(65, 'x')}) {
    res = c.Post(("/api/mechanism?" + q).c_str(), body, "application/json");
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, 400) << q << ": " << res->body;
    EXPECT_FALSE(json::parse(res->body).contains("request_id")) << q;
  }
  res = c.Post(("/api/mechanism?points=720&frames=180&id=" + std::string(64, 'x')).c_str(), body, "application/json");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 200);
  EXPECT_EQ(json::parse(res->body)["frames"].size(), 180u);
}

// The cycloid disc on its pins at crank 50°: pins at a u(2πi/n1), the disc's centre at e u(φ),
// turned by −φ/n2; without profile modification every pin touches the disc (the tooth is the
// envelope of the pin circle, the paper's eqs. 1–2): the nearest profile point is ρ from each pin.
TEST(Serve, CycloidMechanismMatchesTheClosedForms) {
  json study = json::parse(ReadFile(Example("cycloid_ltca_nnm_none.json")));
  study.erase("modification");
  const double phi = 50 * M_PI / 180, a = 90, rho = 7.2, e = 4.5;
  const json m = camopt::studies::MechanismAt(study, 50.0, 4000);
  ASSERT_TRUE(m["supported"].get<bool>());
  EXPECT_NEAR(m["disc_centre_mm"][0].get<double>(), e * std::cos(phi), 1e-6);
  EXPECT_NEAR(m["disc_centre_mm"][1].get<double>(), e * std::sin(phi), 1e-6);
  EXPECT_NEAR(m["disc_rotation_deg"].get<double>(), -50.0 / 15, 1e-12);
  ASSERT_EQ(m["pins"].size(), 16u);
  for (int i = 0; i < 16; ++i) {
    const double x = m["pins"][i]["x"], y = m["pins"][i]["y"];
    EXPECT_NEAR(x, a * std::cos(2 * M_PI * i / 16), 1e-12);
    EXPECT_NEAR(y, a * std::sin(2 * M_PI * i / 16), 1e-12);
    double nearest = 1e9;
    for (const json& p : m["profile_mm"])
      nearest = std::min(nearest, std::hypot(p[0].get<double>() - x, p[1].get<double>() - y));
    EXPECT_NEAR(nearest, rho, 2e-3) << "pin " << i;
  }
}

// The pins' forces at crank 50° are the rigid disc's load sharing: every contact normal passes
// through the pitch point I = n1 e u(φ) (Aronhold–Kennedy), pin i's arm about the disc centre is
// l_i = (O_i − D) × unit(O_i − I); the loaded pins are those with l_i > 0, and their moment
// Σ F_i l_i balances the disc's torque T (load.torque_Nm / discs) — computed here from the geometry.
// The file's profile modification does not change them (nominal tooth, docs/studio.md).
TEST(Serve, CycloidMechanismPinForcesBalanceTheTorque) {
  const json study = json::parse(ReadFile(Example("cycloid_ltca_nnm_none.json")));
  const double phi = 50 * M_PI / 180, a = 90, e = 4.5;
  const int n1 = 16;
  const double torque = study["load"]["torque_Nm"].get<double>() * 1e3 / study.value("discs", 1);
  const json m = camopt::studies::MechanismAt(study, 50.0, 400);
  ASSERT_EQ(m["pins"].size(), size_t(n1));
  EXPECT_NEAR(m["disc_torque_Nmm"].get<double>(), torque, 1e-9 * torque);
  double moment = 0, largest = 0;
  int loaded = 0;
  for (int i = 0; i < n1; ++i) {
    const double ox = a * std::cos(2 * M_PI * i / n1), oy = a * std::sin(2 * M_PI * i / n1);
    const double nx = ox - n1 * e * std::cos(phi), ny = oy - n1 * e * std::sin(phi), nn = std::hypot(nx, ny);
    const double arm = ((ox - e * std::cos(phi)) * ny - (oy - e * std::sin(phi)) * nx) / nn;
    const double f = m["pins"][i]["force_N"].get<double>();
    EXPECT_GE(f, 0.0) << "pin " << i;
    if (arm <= 0) { EXPECT_EQ(f, 0.0) << "pin " << i << " on the unloaded flank"; }
    if (f > 0) ++loaded;
    moment += f * arm;
    largest = std::max(largest, f);
  }
  EXPECT_GT(loaded, 2);
  EXPECT_NEAR(moment, torque, 1e-9 * torque);
  EXPECT_EQ(m["max_pin_force_N"].get<double>(), largest);
}

// Each loaded pin's Hertz pressure at crank 50°, by hand: the tooth's curvature at the nominal
// contact t_i = 2πi/n1 + φ/n2 from the closed form (C1) of docs/cycloid.md (λ = e n1/a, ψ = (n1 − 1) t,
// κ_X = (1 + n1 λ² − (n1 + 1) λ cos ψ) / (a (1 + λ² − 2 λ cos ψ)^{3/2}), the tooth the inner offset by ρ:
// κ = κ_X/(1 − ρ κ_X)), 1/R' = κ + 1/ρ, p0 = sqrt(F E*/(π B R')) with E* = E/(2(1 − ν²)) and the
// pin's force as drawn (checked above).
TEST(Serve, CycloidMechanismPinPressuresMatchHertzByHand) {
  const json study = json::parse(ReadFile(Example("cycloid_ltca_nnm_none.json")));
  const double phi = 50 * M_PI / 180, a = 90, e = 4.5, rho = 7.2, B = 17, E = 206000, nu = 0.3;
  const int n1 = 16, n2 = 15;
  const double e_star = E / (2 * (1 - nu * nu)), lambda = e * n1 / a;
  const json m = camopt::studies::MechanismAt(study, 50.0, 400);
  ASSERT_EQ(m["pins"].size(), size_t(n1));
  EXPECT_NEAR(m["composite_modulus_MPa"].get<double>(), e_star, 1e-9 * e_star);
  double largest = 0;
  int loaded = 0;
  for (int i = 0; i < n1; ++i) {
    const json& pin = m["pins"][i];
    const double f = pin["force_N"];
    if (!(f > 0)) {
      EXPECT_EQ(pin["pressure_MPa"].get<double>(), 0.0) << "pin " << i;
      continue;
    }
    ++loaded;
    const double t = 2 * M_PI * i / n1 + phi / n2, c = std::cos((n1 - 1) * t);
    const double kx = (1 + n1 * lambda * lambda - (n1 + 1) * lambda * c) /
                      (a * std::pow(1 + lambda * lambda - 2 * lambda * c, 1.5));
    const double r_eff = 1 / (kx / (1 - rho * kx) + 1 / rho);
    const double p0 = std::sqrt(f * e_star / (M_PI * B * r_eff));
    EXPECT_NEAR(pin["effective_radius_mm"].get<double>(), r_eff, 1e-9 * r_eff) << "pin " << i;
    EXPECT_NEAR(pin["pressure_MPa"].get<double>(), p0, 1e-9 * p0) << "pin " << i;
    largest = std::max(largest, p0);
  }
  EXPECT_EQ(loaded, 8);
  EXPECT_NEAR(m["max_pressure_MPa"].get<double>(), largest, 1e-9 * largest);
}

// The disc cam with its translating roller follower drawn standing: at 145° (the dwell after the
// 24 mm rise of disc_cam_translating.json) the roller centre is at (√((r_b + r_f)² − e²) + 24, e)
// (Rzine et al. eq. 5 turned by −θ), the pressure angle atan(−e/L) (eq. 3 with dS/dθ = 0), and the
// profile passes a roller radius from the roller centre and nowhere nearer.
TEST(Serve, DiscCamMechanismMatchesTheClosedForms) {
  const json study = json::parse(ReadFile(Example("disc_cam_translating.json")));
  const json m = camopt::studies::MechanismAt(study, 145.0, 4000);
  ASSERT_TRUE(m["supported"].get<bool>());
  const double rb = 40, rf = 10, e = 12, L = std::sqrt((rb + rf) * (rb + rf) - e * e) + 24;
  const double x = m["roller_centre_mm"][0], y = m["roller_centre_mm"][1];
  EXPECT_NEAR(x, L, 1e-5);
  EXPECT_NEAR(y, e, 1e-5);
  EXPECT_NEAR(m["pressure_angle_deg"].get<double>(), std::atan(-e / L) * 180 / M_PI, 1e-9);
  EXPECT_NEAR(m["follower_direction"][0].get<double>(), 1.0, 1e-12);
  double nearest = 1e9;
  for (const json& p : m["profile_mm"])
    nearest = std::min(nearest, std::hypot(p[0].get<double>() - x, p[1].get<double>() - y));
  EXPECT_NEAR(nearest, rf, 2e-3);
}

// The nearest point of a closed polyline (the drawn profile) to q.
double DistanceToPolyline(const json& pts, double qx, double qy) {
  double best = 1e18;
  for (size_t i = 0; i < pts.size(); ++i) {
    const json &a = pts[i], &b = pts[(i + 1) % pts.size()];
    const double ax = a[0], ay = a[1], bx = double(b[0]) - ax, by = double(b[1]) - ay;
    const double len2 = bx * bx + by * by;
    const double t = len2 > 0 ? std::clamp(((qx - ax) * bx + (qy - ay) * by) / len2, 0.0, 1.0) : 0.0;
    best = std::min(best, std::hypot(qx - ax - t * bx, qy - ay - t * by));
  }
  return best;
}

// The translating flat face of disc_cam_flat_faced.json at 60° (half way up the cycloidal 24 mm rise
// over 120°, by hand S = 12 mm, S' = 2h/β = 22.918 mm): the face is the line x = r_b + S = 52 mm
// (the follower standing), its ends at y = ±25 (the 50 mm face centred on the axis), the contact
// (52, S') on it and on the drawn profile, and the face a supporting line of the convex profile: no
// profile point beyond it (tangent at the contact).
TEST(Serve, FlatFacedFollowerIsTangentToTheProfileAtTheContact) {
  const json m = camopt::studies::MechanismAt(json::parse(ReadFile(Example("disc_cam_flat_faced.json"))), 60.0, 3600);
  ASSERT_TRUE(m["supported"].get<bool>()) << m.dump().substr(0, 300);
  EXPECT_TRUE(m["flat_face"].get<bool>());
  const double rb = 40, h = 24, beta = 120 * M_PI / 180, x = 0.5;
  const double S = h * (x - std::sin(2 * M_PI * x) / (2 * M_PI)), dS = h / beta * (1 - std::cos(2 * M_PI * x));
  EXPECT_NEAR(m["lift"].get<double>(), S, 1e-9);
  for (const json& end : m["face_mm"]) EXPECT_NEAR(end[0].get<double>(), rb + S, 1e-6);
  EXPECT_NEAR(m["face_mm"][0][1].get<double>(), -25.0, 1e-6);
  EXPECT_NEAR(m["face_mm"][1][1].get<double>(), 25.0, 1e-6);
  const double cx = m["contact_mm"][0], cy = m["contact_mm"][1];
  EXPECT_NEAR(cx, rb + S, 1e-6);
  EXPECT_NEAR(cy, dS, 1e-6);
  EXPECT_LT(DistanceToPolyline(m["profile_mm"], cx, cy), 1e-6);
  double beyond = -1e9;
  for (const json& p : m["profile_mm"]) beyond = std::max(beyond, p[0].get<double>() - (rb + S));
  EXPECT_LE(beyond, 1e-6);
  EXPECT_GT(beyond, -1e-6);  // the contact is a profile sample (60° is on the 3600-point grid)
}

// The flat face on an arm of disc_cam_oscillating_flat_faced.json at 60° (f = 100 mm, d = 10 mm,
// r_b = 40 mm; by hand ξ₀ = asin((r_b + d)/f) = 30°, half way up the 10° cycloidal swing ξ = 35°):
// drawn with the pivot standing at (f, 0), the face's unit normal toward the cam m = (−sin ξ, −cos ξ),
// the face the line (P − O₃) · m = d through both drawn ends and the contact, the contact on the
// profile, and every profile point on the cam's side of it ((P − O₃) · m ≥ d: tangent at the contact).
TEST(Serve, OscillatingFlatFaceIsTangentToTheProfileAtTheContact) {
  const json m =
      camopt::studies::MechanismAt(json::parse(ReadFile(Example("disc_cam_oscillating_flat_faced.json"))), 60.0, 3600);
  ASSERT_TRUE(m["supported"].get<bool>()) << m.dump().substr(0, 300);
  const double f = 100, d = 10, xi = (30.0 + 5.0) * M_PI / 180;
  EXPECT_NEAR(std::asin((40 + d) / f), 30 * M_PI / 180, 1e-15);
  EXPECT_NEAR(m["arm_angle_deg"].get<double>(), 35.0, 1e-9);
  EXPECT_NEAR(m["pivot_mm"][0].get<double>(), f, 1e-6);
  EXPECT_NEAR(m["pivot_mm"][1].get<double>(), 0.0, 1e-6);
  const double mx = -std::sin(xi), my = -std::cos(xi);
  EXPECT_NEAR(m["face_normal"][0].get<double>(), mx, 1e-12);
  EXPECT_NEAR(m["face_normal"][1].get<double>(), my, 1e-12);
  const auto side = [&](const json& p) { return (p[0].get<double>() - f) * mx + p[1].get<double>() * my; };
  for (const json& end : m["face_mm"]) EXPECT_NEAR(side(end), d, 2e-6);
  EXPECT_NEAR(side(m["contact_mm"]), d, 2e-6);
  EXPECT_LT(DistanceToPolyline(m["profile_mm"], m["contact_mm"][0], m["contact_mm"][1]), 1e-6);
  double nearest = 1e9;
  for (const json& p : m["profile_mm"]) nearest = std::min(nearest, side(p));
  EXPECT_GE(nearest, d - 2e-6);
  EXPECT_LE(nearest, d + 2e-6);
}

// The smallest-base-circle sizing drawn through the server: disc_cam_min_size.json run by the CLI
// into results/, then /api/mechanism?result=results/… draws its start (the file's design: r_b = 40,
// e = 12, r_f = 10) under the run's optimum (r_b and e of result.json "best"). At 145° (the dwell
// after the 24 mm rise) each roller centre is at (√((r_b + r_f)² − e²) + 24, e) (Rzine et al. eq. 5
// turned by −θ), and each profile's smallest radius is its r_b (the low dwell is the base circle).
TEST(Serve, SizingMechanismDrawsTheDiscCamOptimumAgainstItsStart) {
  const fs::path dir = TempDir("serve-sizing");
  fs::copy_file(Example("disc_cam_min_size.json"), dir / "disc_cam_min_size.json");
  const std::string cmd = "cd " + dir.string() + " && " + CAMOPT_BINARY +
                          " run disc_cam_min_size.json --quiet --out results/disc_cam_min_size > /dev/null 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  const json best = json::parse(ReadFile(dir / "results" / "disc_cam_min_size" / "result.json"))["best"];
  const double rb_opt = best["base_circle_radius_mm"], e_opt = best["offset_mm"], rf = 10;
  ASSERT_LT(rb_opt, 39.0);  // the optimum is well below the start: the two drawings differ
  Studio studio(dir);
  ASSERT_GT(studio.port(), 0) << studio.first_line();
  auto c = studio.Client();
  auto res = c.Post("/api/mechanism?angle=145&points=4000&result=results/disc_cam_min_size",
                    ReadFile(dir / "disc_cam_min_size.json"), "application/json");
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 200) << res->body;
  const json m = json::parse(res->body);
  EXPECT_EQ(m["kind"], "sizing");
  EXPECT_EQ(m["analysis_kind"], "disc_cam");
  struct Want {
    const char* which;
    double rb, e;
  };
  for (const Want& w : {Want{"start", 40.0, 12.0}, Want{"optimum", rb_opt, e_opt}}) {
    const json& d = m[w.which];
    ASSERT_TRUE(d["supported"].get<bool>()) << w.which << " " << d.dump().substr(0, 300);
    EXPECT_EQ(d["base_radius_mm"].get<double>(), w.rb) << w.which;
    EXPECT_EQ(d["study"]["study"], "disc_cam");
    const double L = std::sqrt((w.rb + rf) * (w.rb + rf) - w.e * w.e) + 24;
    EXPECT_NEAR(d["roller_centre_mm"][0].get<double>(), L, 1e-5) << w.which;
    EXPECT_NEAR(d["roller_centre_mm"][1].get<double>(), w.e, 1e-5) << w.which;
    double smallest = 1e9;
    for (const json& p : d["profile_mm"]) smallest = std::min(smallest, std::hypot(p[0].get<double>(), p[1].get<double>()));
    EXPECT_NEAR(smallest, w.rb, 1e-5) << w.which;
  }
  // Without a run folder: the start alone; a folder outside the studio's is refused.
  res = c.Post("/api/mechanism?angle=0&result=results/none", ReadFile(dir / "disc_cam_min_size.json"), "application/json");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 200);
  EXPECT_TRUE(json::parse(res->body)["optimum"].is_null());
  res = c.Post("/api/mechanism?angle=0&result=../..", ReadFile(dir / "disc_cam_min_size.json"), "application/json");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 403) << res->body;
}

// The LCR sizing's optimum against its start: lcr_min_size.json run by the CLI, its
// best_lcr_analysis.json given as the optimum. The optimum's rollers stand at r_d of result.json
// "best" (input and output turrets, the output one turned by (1 − n_A m_B/(m_A n_B)) θ, paper
// eq. 2); the start is the best combination's first smooth-phase start (objectives/lcr_sizing.h,
// LcrStartingPoints: d_r the middle of its range, each turret 1.3 (d_r + gap)/(2 sin(π/n)) within
// its range, e = 0.5 min(r_dA, r_dB)/max(n/(n − m)) within its range), computed here from that rule.
TEST(Serve, SizingMechanismDrawsTheLcrOptimumAgainstItsStart) {
  const fs::path dir = TempDir("serve-sizing-lcr");
  const std::string cmd = "cd " + dir.string() + " && " + CAMOPT_BINARY + " run " +
                          Example("lcr_min_size.json").string() + " --quiet --out out > /dev/null 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  const json best = json::parse(ReadFile(dir / "out" / "result.json"))["best"];
  const json optimum = json::parse(ReadFile(dir / "out" / "best_lcr_analysis.json"));
  const json sizing = json::parse(ReadFile(Example("lcr_min_size.json")));
  const double theta_deg = 30, theta = theta_deg * M_PI / 180;
  const json m = camopt::studies::MechanismAt(sizing, theta_deg, 720, optimum);
  ASSERT_EQ(m["kind"], "sizing");
  const int ma = best["input"]["lobes"], na = best["input"]["rollers"], mb = best["output"]["lobes"],
            nb = best["output"]["rollers"];
  const double turn_out = (1.0 - double(na) * mb / (double(ma) * nb)) * theta;
  // The start from the rule: d_r = (3 + 20)/2, gap 1 mm, turrets within [15, 80], e within [0.5, 5].
  const double d0 = 11.5, gap = 1.0;
  const auto turret = [&](int n) { return std::clamp(1.3 * (d0 + gap) / (2 * std::sin(M_PI / n)), 15.0, 80.0); };
  const double k = std::max(double(na) / (na - ma), double(nb) / (nb - mb));
  const double e0 = std::clamp(0.5 * std::min(turret(na), turret(nb)) / k, 0.5, 5.0);
  struct Want {
    const char* which;
    double e, rd[2], d;
  };
  const Want wants[2] = {{"optimum", best["eccentricity_mm"], {best["input"]["turret_radius_mm"], best["output"]["turret_radius_mm"]},
                          best["input"]["roller_diameter_mm"]},
                         {"start", e0, {turret(na), turret(nb)}, d0}};
  for (const Want& w : wants) {
    const json& d = m[w.which];
    ASSERT_TRUE(d["supported"].get<bool>()) << w.which << " " << d.dump().substr(0, 400);
    EXPECT_NEAR(d["eccentricity_mm"].get<double>(), w.e, 1e-12 * w.e) << w.which;
    for (int s = 0; s < 2; ++s) {
      const json& side = d["sides"][s];
      const int n = s == 0 ? na : nb;
      ASSERT_EQ(side["rollers_at"].size(), size_t(n)) << w.which;
      EXPECT_NEAR(side["roller_radius_mm"].get<double>(), w.d / 2, 1e-12 * w.d) << w.which;
      for (int i = 0; i < n; ++i) {
        const double a = 2 * M_PI * i / n + (s == 0 ? 0.0 : turn_out);
        EXPECT_NEAR(side["rollers_at"][i]["x"].get<double>(), w.rd[s] * std::cos(a), 1e-9) << w.which << s << i;
        EXPECT_NEAR(side["rollers_at"][i]["y"].get<double>(), w.rd[s] * std::sin(a), 1e-9) << w.which << s << i;
      }
    }
  }
}

// per_angle.csv as text cells and numbers by column name (the test's own reading of the file).
struct CsvTable {
  std::vector<std::string> names;
  std::vector<std::vector<std::string>> text;  // rows of cells
  double At(size_t row, const std::string& name) const {
    const size_t c = size_t(std::find(names.begin(), names.end(), name) - names.begin());
    EXPECT_LT(c, names.size()) << name;
    return c < names.size() ? std::stod(text[row][c]) : NAN;
  }
};
CsvTable ReadCsv(const fs::path& file) {
  std::istringstream in(ReadFile(file));
  CsvTable t;
  std::string line, cell;
  for (bool header = true; std::getline(in, line); header = false) {
    std::vector<std::string> cells;
    for (std::istringstream r(line); std::getline(r, cell, ',');) cells.push_back(cell);
    if (header) t.names = cells;
    else t.text.push_back(cells);
  }
  return t;
}

// The cycloid view from a run: cycloid_ltca_nnm_none.json run by the CLI, then drawn through the
// server with result=its folder. At one of the run's crank angles every pin's force and pressure
// are per_angle.csv's row (load_roller_i_N, max_pressure_roller_i_MPa); between two rows the linear
// interpolation of docs/studio.md, computed here; past the run's mesh period τ = 22.5° the drive's
// symmetry: pin i at φ + mτ carries what pin i − m carries at φ (the wrap from the last row to
// φ_0 + τ too). The new pressure columns' largest in each row is the row's max_contact_stress_MPa.
TEST(Serve, CycloidMechanismTakesThePinsFromTheLoadedRun) {
  const fs::path dir = TempDir("serve-cycloid-run");
  fs::copy_file(Example("cycloid_ltca_nnm_none.json"), dir / "nnm.json");
  const std::string cmd = "cd " + dir.string() + " && " + CAMOPT_BINARY +
                          " run nnm.json --quiet --out results/nnm > /dev/null 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  const CsvTable csv = ReadCsv(dir / "results" / "nnm" / "per_angle.csv");
  const int n1 = 16;
  const size_t rows = csv.text.size();
  ASSERT_EQ(rows, 64u);  // 32 angles per mesh period, refined to 64 by the error estimate
  const auto load = [&](size_t k, int i) { return csv.At(k, "load_roller_" + std::to_string(i + 1) + "_N"); };
  const auto press = [&](size_t k, int i) { return csv.At(k, "max_pressure_roller_" + std::to_string(i + 1) + "_MPa"); };
  // The new columns against the row's overall peak (and zero off contact).
  for (size_t k = 0; k < rows; ++k) {
    double largest = 0;
    int loaded = 0;
    for (int i = 0; i < n1; ++i) {
      largest = std::max(largest, press(k, i));
      EXPECT_EQ(press(k, i) > 0, load(k, i) > 0) << "row " << k << " pin " << i;
      loaded += load(k, i) > 0;
    }
    const double peak = csv.At(k, "max_contact_stress_MPa");
    EXPECT_NEAR(largest, peak, 1e-9 * peak) << "row " << k;
    EXPECT_EQ(loaded, int(csv.At(k, "pairs_in_contact"))) << "row " << k;
  }
  Studio studio(dir);
  ASSERT_GT(studio.port(), 0) << studio.first_line();
  auto c = studio.Client();
  const std::string body = ReadFile(dir / "nnm.json");
  const auto at = [&](const std::string& angle, const std::string& result = "&result=results/nnm") {
    auto res = c.Post(("/api/mechanism?angle=" + angle + "&points=400" + result).c_str(), body, "application/json");
    EXPECT_TRUE(res);
    EXPECT_EQ(res->status, 200) << res->body;
    return json::parse(res->body);
  };
  const auto expect_pins = [&](const json& m, const std::function<double(int, bool)>& want, const std::string& what) {
    ASSERT_EQ(m["pin_source"], "run") << what << " " << m.value("run_note", "");
    ASSERT_EQ(m["pins"].size(), size_t(n1));
    double largest = 0;
    for (int i = 0; i < n1; ++i) {
      const double f = m["pins"][i]["force_N"], p = m["pins"][i]["pressure_MPa"];
      const double wf = want(i, false), wp = want(i, true);
      EXPECT_NEAR(f, wf, 1e-9 * std::max(1.0, wf)) << what << " pin " << i;
      EXPECT_NEAR(p, wp, 1e-9 * std::max(1.0, wp)) << what << " pin " << i;
      EXPECT_EQ(m["pins"][i]["loaded"].get<bool>(), wf > 0) << what << " pin " << i;
      largest = std::max(largest, wp);
    }
    EXPECT_NEAR(m["max_pressure_MPa"].get<double>(), largest, 1e-9 * largest) << what;
  };
  // The run's own angles: its rows.
  for (const size_t k : {size_t(0), size_t(17), size_t(63)}) {
    const json m = at(csv.text[k][0]);
    expect_pins(m, [&](int i, bool p) { return p ? press(k, i) : load(k, i); }, "row " + std::to_string(k));
    EXPECT_EQ(m["run"]["weight"].get<double>(), 0.0);
    EXPECT_NE(m["pin_source_label"].get<std::string>().find("loaded run"), std::string::npos);
  }
  // Between rows 17 and 18, 30% of the way: (1 − t) row 17 + t row 18.
  const double a17 = csv.At(17, "crank_angle_deg"), a18 = csv.At(18, "crank_angle_deg"), t = 0.3;
  const auto lerp = [&](size_t k0, int s0, size_t k1, int s1, int i, bool p) {
    const int i0 = ((i - s0) % n1 + n1) % n1, i1 = ((i - s1) % n1 + n1) % n1;
    return p ? (1 - t) * press(k0, i0) + t * press(k1, i1) : (1 - t) * load(k0, i0) + t * load(k1, i1);
  };
  char angle[64];
  std::snprintf(angle, sizeof angle, "%.17g", a17 + t * (a18 - a17));
  expect_pins(at(angle), [&](int i, bool p) { return lerp(17, 0, 18, 0, i, p); }, "between rows 17 and 18");
  // Three mesh periods later (and a revolution before): the same rows, the pins turned by three.
  std::snprintf(angle, sizeof angle, "%.17g", a17 + t * (a18 - a17) + 3 * 22.5);
  expect_pins(at(angle), [&](int i, bool p) { return lerp(17, 3, 18, 3, i, p); }, "three periods on");
  std::snprintf(angle, sizeof angle, "%.17g", a17 + t * (a18 - a17) - 360 + 3 * 22.5);
  expect_pins(at(angle), [&](int i, bool p) { return lerp(17, 3, 18, 3, i, p); }, "a revolution before");
  // Past the last row (22.1484375°) toward 22.5°: the last row and row 0 with the pins turned by one.
  const double a63 = csv.At(63, "crank_angle_deg");
  std::snprintf(angle, sizeof angle, "%.17g", a63 + t * (22.5 - a63));
  expect_pins(at(angle), [&](int i, bool p) { return lerp(63, 0, 0, 1, i, p); }, "the wrap");
  // The symmetry against the model itself: a second run over two mesh periods (0° to 39.375° by
  // 5.625°, no error estimate) at 28.125° = 22.5° + 5.625° equals the first run's row at 5.625°
  // (row 16) with the pins turned by one, as drawn, to the LTCA's compatibility tolerance (1e-3).
  json two = json::parse(body);
  two["analysis"] = {{"crank_angle_steps", 8}, {"crank_span_deg", 45}, {"grid", {40, 40}}, {"estimate_error", false}};
  WriteFile(dir / "two.json", two.dump());
  ASSERT_EQ(std::system(("cd " + dir.string() + " && " + CAMOPT_BINARY +
                         " run two.json --quiet --out results/two > /dev/null 2>&1").c_str()), 0);
  const CsvTable second = ReadCsv(dir / "results" / "two" / "per_angle.csv");
  ASSERT_EQ(second.At(5, "crank_angle_deg"), 28.125);
  const json sym = at("28.125");
  EXPECT_EQ(sym["run"]["pin_shift"], 1);
  for (int i = 0; i < n1; ++i) {
    const double want = second.At(5, "load_roller_" + std::to_string(i + 1) + "_N");
    EXPECT_NEAR(sym["pins"][i]["force_N"].get<double>(), want, 1e-3 * 2600) << "pin " << i;
    const double wp = second.At(5, "max_pressure_roller_" + std::to_string(i + 1) + "_MPa");
    EXPECT_NEAR(sym["pins"][i]["pressure_MPa"].get<double>(), wp, 2e-3 * 1300) << "pin " << i;
  }
  // Without a run folder (or with one not written yet): the nominal rigid disc.
  EXPECT_EQ(at("10", "")["pin_source"], "nominal");
  const json none = at("10", "&result=results/none");
  EXPECT_EQ(none["pin_source"], "nominal");
  EXPECT_EQ(none["pin_source_label"], "nominal rigid disc, no run");
  // A study edited since its run (another torque): the run is not used, and the view says why.
  json edited = json::parse(body);
  edited["load"]["torque_Nm"] = 300;
  auto res = c.Post("/api/mechanism?angle=10&result=results/nnm", edited.dump(), "application/json");
  ASSERT_TRUE(res);
  const json m = json::parse(res->body);
  EXPECT_EQ(m["pin_source"], "nominal");
  EXPECT_NE(m.value("run_note", "").find("torque"), std::string::npos) << res->body.substr(0, 300);
  // A drive edited since its run (the profile modification Δa): its unloaded TE differs, not used.
  edited = json::parse(body);
  edited["modification"]["delta_position_um"] = -20;
  res = c.Post("/api/mechanism?angle=10&result=results/nnm", edited.dump(), "application/json");
  ASSERT_TRUE(res);
  const json moved = json::parse(res->body);
  EXPECT_EQ(moved["pin_source"], "nominal");
  EXPECT_NE(moved.value("run_note", "").find("unloaded transmission error"), std::string::npos) << res->body.substr(0, 300);
  // A folder outside the studio's is refused.
  res = c.Post("/api/mechanism?angle=0&result=../..", body, "application/json");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 403) << res->body;
}

// A run whose crank angles are not whole mesh periods uniformly (explicit angles 0°, 10°, 30° of a
// 4-pin drive, τ = 90°): interpolated between its neighbouring rows only, 360° periodic, refused
// outside them with the reason.
TEST(Serve, CycloidRunAnglesOutsideWholePeriodsInterpolateWithinTheirRange) {
  const std::string csv =
      "crank_angle_deg,load_roller_1_N,load_roller_2_N,load_roller_3_N,load_roller_4_N,"
      "max_pressure_roller_1_MPa,max_pressure_roller_2_MPa,max_pressure_roller_3_MPa,max_pressure_roller_4_MPa\n"
      "0,10,20,0,0,100,200,0,0\n10,30,40,0,0,300,400,0,0\n30,50,0,60,0,500,0,600,0\n";
  const json at20 = camopt::studies::CycloidRunAt(csv, 4, 20.0 + 720.0);
  ASSERT_FALSE(at20.contains("why")) << at20.dump();
  EXPECT_DOUBLE_EQ(at20["weight"].get<double>(), 0.5);
  const double f[4] = {40, 20, 30, 0}, p[4] = {400, 200, 300, 0};
  for (int i = 0; i < 4; ++i) {
    EXPECT_DOUBLE_EQ(at20["force_N"][i].get<double>(), f[i]) << i;
    EXPECT_DOUBLE_EQ(at20["pressure_MPa"][i].get<double>(), p[i]) << i;
  }
  EXPECT_EQ(camopt::studies::CycloidRunAt(csv, 4, 30.0)["force_N"][2].get<double>(), 60.0);
  EXPECT_NE(camopt::studies::CycloidRunAt(csv, 4, 45.0).value("why", "").find("do not reach 45"), std::string::npos);
  EXPECT_TRUE(camopt::studies::CycloidRunAt(csv, 5, 0.0).contains("why"));  // a fifth pin's column missing
  EXPECT_TRUE(camopt::studies::CycloidRunAt(csv, 3, 0.0).contains("why"));  // more pins than the study's
}

// The cycloid sizing's start (no run): the pins of cycloid_min_size_paper.json's start, 16 at
// a = 90 mm of radius 7.2 mm, the disc at e u(φ) with e = 4.5 mm.
TEST(Serve, SizingMechanismDrawsTheCycloidStart) {
  const json m = camopt::studies::MechanismAt(json::parse(ReadFile(Example("cycloid_min_size_paper.json"))), 20.0, 400);
  ASSERT_EQ(m["kind"], "sizing");
  EXPECT_TRUE(m["optimum"].is_null());
  const json& d = m["start"];
  ASSERT_TRUE(d["supported"].get<bool>()) << d.dump().substr(0, 300);
  ASSERT_EQ(d["pins"].size(), size_t(16));
  EXPECT_EQ(d["roller_radius_mm"].get<double>(), 7.2);
  for (int i = 0; i < 16; ++i) {
    EXPECT_NEAR(d["pins"][i]["x"].get<double>(), 90 * std::cos(2 * M_PI * i / 16), 1e-9);
    EXPECT_NEAR(d["pins"][i]["y"].get<double>(), 90 * std::sin(2 * M_PI * i / 16), 1e-9);
  }
  EXPECT_NEAR(d["disc_centre_mm"][0].get<double>(), 4.5 * std::cos(20 * M_PI / 180), 1e-6);
  EXPECT_NEAR(d["disc_centre_mm"][1].get<double>(), 4.5 * std::sin(20 * M_PI / 180), 1e-6);
}

// A host beyond this machine: refused without --allow-remote (exit 2, saying what to do); with it,
// a warning with the token on start, and every request refused (401) without the token, answered
// with it (header, address or the cookie the address sets), a foreign Origin still refused (403).
TEST(Serve, AHostBeyondThisMachineNeedsAFlagAndATokenOnEveryRequest) {
  const fs::path dir = TempDir("serve-remote");
  const auto refused = camopt::testing::RunCamopt("serve --host 0.0.0.0 --port 0 " + dir.string());
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.stderr_text.find("add --allow-remote"), std::string::npos) << refused.stderr_text;
  EXPECT_TRUE(camopt::studies::IsLoopbackHost("127.0.0.1") && camopt::studies::IsLoopbackHost("::1") &&
              camopt::studies::IsLoopbackHost("localhost") && !camopt::studies::IsLoopbackHost("0.0.0.0") &&
              !camopt::studies::IsLoopbackHost("192.168.1.5"));

  const std::string err_file = (dir.parent_path() / (dir.filename().string() + ".stderr")).string();
  Studio studio(dir, {"--host", "0.0.0.0", "--allow-remote"}, err_file);
  ASSERT_GT(studio.port(), 0) << studio.first_line();
  std::string err;
  for (int i = 0; i < 250 && err.find("?token=") == std::string::npos; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    err = ReadFile(err_file);
  }
  ASSERT_NE(err.find("warning: serve: listening on 0.0.0.0"), std::string::npos) << err;
  const size_t at = err.find("?token=") + 7;
  const std::string token = err.substr(at, err.find_first_of(" \n", at) - at);
  ASSERT_EQ(token.size(), 32u) << err;

  auto c = studio.Client();
  auto res = c.Get("/api/kinds");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 401);
  // A wrong token: the first character changed (a fixed "0" would be the token itself when its
  // first hex digit is 0, one start in 16).
  const std::string wrong = std::string(1, token[0] == '0' ? '1' : '0') + token.substr(1);
  res = c.Get("/api/kinds", {{"X-Camopt-Token", wrong}});
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 401);  // a wrong token
  res = c.Get("/api/kinds", {{"X-Camopt-Token", token}});
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 200);
  res = c.Get(("/api/kinds?token=" + token).c_str());
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 200);
  EXPECT_NE(res->get_header_value("Set-Cookie").find("camopt_token=" + token + ";"), std::string::npos);
  EXPECT_NE(res->get_header_value("Set-Cookie").find("HttpOnly"), std::string::npos);
  res = c.Get("/api/files", {{"Cookie", "other=1; camopt_token=" + token}});
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 200);
  res = c.Get("/api/files", {{"Cookie", "camopt_token=" + token + "x"}});
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 401);
  res = c.Post("/api/validate", {{"X-Camopt-Token", token}, {"Origin", "http://evil.example"}}, "{}", "application/json");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 403);
}

// The folder is the boundary: a roller catalogue or a sweep's base outside the served folder (by
// path, by "..", or through a link inside the folder) is refused, with the same words whether the
// outside file exists or not; inside, the same files are read (ValidateFindsAStudysRelativeFiles…).
TEST(Serve, FilesAStudyNamesOutsideTheFolderAreRefusedWithoutRevealingThem) {
  const fs::path dir = TempDir("serve-boundary"), outside = TempDir("serve-boundary-outside");
  fs::copy_file(Example("needle_rollers.json"), outside / "needle_rollers.json");
  fs::copy_file(Example("lcr_ii.json"), outside / "lcr_ii.json");
  fs::create_symlink(outside / "needle_rollers.json", dir / "linked_rollers.json");
  Studio studio(dir);
  ASSERT_GT(studio.port(), 0) << studio.first_line();
  auto c = studio.Client();
  const auto message_for = [&](json study) {
    WriteFile(dir / "study.json", study.dump());
    auto res = c.Post("/api/validate?path=study.json", study.dump(), "application/json");
    EXPECT_TRUE(res);
    if (!res) return std::string();
    const json body = json::parse(res->body);
    EXPECT_FALSE(body["ok"].get<bool>()) << res->body;
    return body["error"].value("message", std::string());
  };
  json study = json::parse(ReadFile(Example("lcr_min_size_catalogue.json")));
  std::map<std::string, std::string> said;
  for (const std::string& path : {(outside / "needle_rollers.json").string(), (outside / "missing.json").string(),
                                 "../" + outside.filename().string() + "/needle_rollers.json",
                                 std::string("linked_rollers.json")}) {
    study["roller_catalogue"]["file"] = path;
    std::string m = message_for(study);
    EXPECT_NE(m.find("found a path that leads outside it"), std::string::npos) << path << ": " << m;
    EXPECT_EQ(m.find("line"), std::string::npos) << m;  // nothing of the file's content
    m.replace(m.find(path), path.size(), "PATH");
    said[path] = m;
  }
  EXPECT_EQ(said[(outside / "needle_rollers.json").string()], said[(outside / "missing.json").string()]);
  // A sweep's base, checked as camopt sweep checks it, and run: the run refuses it too.
  const json sweep = {{"sweep", "e"}, {"base", (outside / "lcr_ii.json").string()},
                      {"vary", {{{"path", "/reducer/eccentricity_mm"}, {"values", {1.8, 2.0}}}}}};
  WriteFile(dir / "sweep.json", sweep.dump());
  auto res = c.Post("/api/validate?path=sweep.json", sweep.dump(), "application/json");
  ASSERT_TRUE(res);
  EXPECT_NE(res->body.find("found a path that leads outside it"), std::string::npos) << res->body;
  study["roller_catalogue"]["file"] = (outside / "needle_rollers.json").string();
  WriteFile(dir / "study.json", study.dump());
  res = c.Post("/api/runs", "{\"path\": \"study.json\"}", "application/json");
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 201) << res->body;
  const json end = FollowToEnd(studio, json::parse(res->body)["id"].get<int>());
  EXPECT_EQ(end["exit_code"], 2) << end.dump();
  // The command line without --files-inside reads it (the boundary is the studio's).
  EXPECT_EQ(camopt::testing::RunCamopt("run " + (dir / "study.json").string() + " --quiet --out " +
                                       (dir / "cli").string() + " --max-work-factor 1")
                .stderr_text.find("leads outside"),
            std::string::npos);
}

}  // namespace serve_test

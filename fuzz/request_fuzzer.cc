// camopt_request_fuzz: the mutation fuzzer of the studio's HTTP requests. It serves a scratch
// folder in-process (studies/serve.h ServeMain, on a free loopback port, the camopt binary for its
// runs), sends mutated requests — from a template of every route, with the method, the path and
// its query, the headers (Host, Origin, Content-Length, Transfer-Encoding, huge and many), the body
// (a study cut, retyped, nested 10 000 deep, megabytes) and the bytes themselves (cut, line ends,
// a stray byte) changed — each on its own connection, and judges each answer as
// fuzz/studio_target.h does; also a failure: the server no longer answering /api/kinds within 1 s
// (checked every 20 cases), a file written outside the served folder or a link in it (checked at
// the end), the process dying (a crash ends the fuzzer itself: the test fails).
//
//   camopt_request_fuzz [--cases N] [--seed S] [--save DIR] [--record FILE] [--quiet]
//   camopt_request_fuzz --show I [--seed S]   (print case I's bytes: a failure is reproducible)
// Exit 0 when every case passed, 1 when any failed, 2 on bad arguments. docs/reliability.md has the
// record of the long runs.
#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fuzz/studio_target.h"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

struct Options {
  long cases = 2000;
  unsigned long long seed = 1;
  long show = -1;
  fs::path save, record;
  bool quiet = false;
};

std::string ReadFile(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

size_t Pick(std::mt19937_64& rng, size_t n) { return n == 0 ? 0 : std::uniform_int_distribution<size_t>(0, n - 1)(rng); }
bool Chance(std::mt19937_64& rng, double p) { return std::uniform_real_distribution<double>(0, 1)(rng) < p; }

// One request as parts, mutated part by part, then joined (Content-Length from the body unless a
// mutation set it).
struct Request {
  std::string method, path, version = "HTTP/1.1";
  std::vector<std::pair<std::string, std::string>> headers;
  std::string body;
  bool own_length = false;  // a mutation wrote Content-Length itself
  std::string Text() const {
    std::string t = method + " " + path + " " + version + "\r\n";
    for (const auto& [k, v] : headers) t += k + ": " + v + "\r\n";
    if (!own_length && !body.empty()) t += "Content-Length: " + std::to_string(body.size()) + "\r\n";
    return t + "\r\n" + body;
  }
};

class Generator {
 public:
  Generator(int port, std::vector<std::string> studies) : port_(port), studies_(std::move(studies)) {}

  std::string Case(unsigned long long seed, long index) const {
    std::mt19937_64 rng(seed * 0x9E3779B97F4A7C15ULL + static_cast<unsigned long long>(index));
    Request r = Template(rng);
    const int count = 1 + static_cast<int>(std::geometric_distribution<int>(0.5)(rng) % 4);
    for (int m = 0; m < count; ++m) Mutate(r, rng);
    std::string text = r.Text();
    const double u = std::uniform_real_distribution<double>(0, 1)(rng);
    if (u < 0.05 && !text.empty()) {
      text.resize(Pick(rng, text.size()));  // cut anywhere
    } else if (u < 0.08) {
      static const char kBytes[] = {'\0', '\r', '\n', ' ', ':', '\x7f', '\xff', '\xc3', '%', '?', '#'};
      text.insert(text.begin() + static_cast<long>(Pick(rng, text.size() + 1)), kBytes[Pick(rng, sizeof kBytes)]);
    } else if (u < 0.10) {
      std::string bare;  // bare line feeds
      for (char c : text)
        if (c != '\r') bare += c;
      text = bare;
    }
    return text;
  }

 private:
  std::string Study(std::mt19937_64& rng) const { return studies_[Pick(rng, studies_.size())]; }

  Request Template(std::mt19937_64& rng) const {
    Request r;
    r.headers = {{"Host", "127.0.0.1:" + std::to_string(port_)}};
    const std::string name = camopt::fuzz::StudioStudies()[Pick(rng, camopt::fuzz::StudioStudies().size())];
    switch (Pick(rng, 13)) {
      case 0: r.method = "GET", r.path = "/api/kinds"; break;
      case 1: r.method = "GET", r.path = "/api/schema/lcr_analysis"; break;
      case 2: r.method = "GET", r.path = "/api/files"; break;
      case 3: r.method = "GET", r.path = "/api/file?path=" + name; break;
      case 4: r.method = "PUT", r.path = "/api/file?path=m" + std::to_string(Pick(rng, 4)) + ".json", r.body = Study(rng); break;
      case 5: r.method = "POST", r.path = "/api/validate", r.body = Study(rng); break;
      case 6:
        r.method = "POST", r.path = "/api/duplicate";
        r.body = json{{"from", name}, {"to", "copy" + std::to_string(Pick(rng, 4)) + ".json"}}.dump();
        break;
      case 7: r.method = "POST", r.path = "/api/mechanism", r.body = Study(rng); break;
      case 8: r.method = "POST", r.path = "/api/runs", r.body = json{{"path", name}}.dump(); break;
      case 9: r.method = "GET", r.path = "/api/runs"; break;
      case 10: r.method = "GET", r.path = "/api/runs/" + std::to_string(Pick(rng, 3)) + "/result"; break;
      case 11: r.method = "POST", r.path = "/api/runs/" + std::to_string(Pick(rng, 3)) + "/cancel"; break;
      default: r.method = "GET", r.path = "/"; break;
    }
    if (!r.body.empty()) r.headers.push_back({"Content-Type", "application/json"});
    return r;
  }

  void Mutate(Request& r, std::mt19937_64& rng) const {
    static const char* const kMethods[] = {"GET", "POST", "PUT", "DELETE", "PATCH", "OPTIONS", "HEAD",
                                           "TRACE", "CONNECT", "get", "", "G\x01T", "POSTX"};
    static const char* const kPaths[] = {"../../etc/passwd", "/etc/passwd", "%2e%2e/%2e%2e/etc/passwd",
                                         "..%2f..%2fetc%2fpasswd", "results/../../x.json", "a%00.json",
                                         "", "dir/", ".", "..", "x.json/..", "\xc3\x28.json",
                                         "/proc/self/environ", "lcr_ii.json#frag", "m0.json?x=1"};
    static const char* const kVersions[] = {"HTTP/1.0", "HTTP/2.0", "HTTP/9", "http/1.1", "", "HTTP/1.1 extra"};
    switch (Pick(rng, 16)) {
      case 0: r.method = kMethods[Pick(rng, std::size(kMethods))]; break;
      case 1: {  // the file a path= names
        const size_t q = r.path.find("path=");
        const std::string p = kPaths[Pick(rng, std::size(kPaths))];
        r.path = q == std::string::npos ? "/api/file?path=" + p : r.path.substr(0, q + 5) + p;
        break;
      }
      case 2: r.path += std::string(Pick(rng, 3) == 0 ? 70000 : 300, 'a'); break;
      case 3: r.path = "/api/" + std::string(kPaths[Pick(rng, std::size(kPaths))]); break;
      case 4: r.version = kVersions[Pick(rng, std::size(kVersions))]; break;
      case 5:  // another host, or none
        if (r.headers.empty() || r.headers[0].first != "Host") r.headers.insert(r.headers.begin(), {"Host", "localhost"});
        if (Chance(rng, 0.5)) r.headers.erase(r.headers.begin());
        else r.headers[0].second = Chance(rng, 0.5) ? "evil.example" : "127.0.0.1.evil.example";
        break;
      case 6: r.headers.push_back({"Origin", Chance(rng, 0.5) ? "http://evil.example" : "null"}); break;
      case 7: {  // a Content-Length that lies
        static const char* const kLengths[] = {"0", "-1", "1", "99999999999999999999", "18446744073709551615",
                                               "2097152", "1048577", "abc", "5, 6"};
        r.own_length = true;
        r.headers.push_back({"Content-Length", kLengths[Pick(rng, std::size(kLengths))]});
        break;
      }
      case 8: r.headers.push_back({"Transfer-Encoding", Chance(rng, 0.5) ? "chunked" : "gzip, chunked"}); break;
      case 9: r.headers.push_back({"X-Big", std::string(Chance(rng, 0.5) ? 9000 : 200000, 'h')}); break;
      case 10:
        for (int i = 0; i < 300; ++i) r.headers.push_back({"X-" + std::to_string(i), "v"});
        break;
      case 11: r.body = r.body.substr(0, Pick(rng, r.body.size() + 1)); break;  // a cut body
      case 12: r.body = std::string(10000, '[') + std::string(10000, ']'); break;
      case 13: r.body = Chance(rng, 0.5) ? std::string((1 << 20) + 1, ' ') : "{\"a\": 1e400}"; break;
      case 14: {  // a study with a value retyped (not the nested brackets: dump() recurses)
        if (r.body.find("[[[[[[[[") != std::string::npos) break;
        json j = json::parse(r.body.empty() ? Study(rng) : r.body, nullptr, false);
        if (j.is_object() && !j.empty()) {
          auto it = j.begin();
          std::advance(it, static_cast<long>(Pick(rng, j.size())));
          static const json kValues[] = {json(nullptr), json(-1), json(1e308), json("x"), json::array(), json::object(),
                                         json(std::string(5000, 'z'))};
          *it = kValues[Pick(rng, std::size(kValues))];
        }
        r.body = j.is_discarded() ? r.body : j.dump();
        break;
      }
      default: r.headers.push_back({"Cookie", "camopt_token=" + std::string(Pick(rng, 100), 'x')}); break;
    }
  }

  int port_;
  std::vector<std::string> studies_;
};

int Usage(const std::string& why) {
  std::cerr << "camopt_request_fuzz: " << why << "\n"
            << "usage: camopt_request_fuzz [--cases N] [--seed S] [--save DIR] [--record FILE] [--quiet]\n"
               "       camopt_request_fuzz --show I [--seed S]\n";
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const auto next = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
      return argv[++i];
    };
    try {
      if (a == "--cases") o.cases = std::stol(next());
      else if (a == "--seed") o.seed = std::stoull(next());
      else if (a == "--show") o.show = std::stol(next());
      else if (a == "--save") o.save = next();
      else if (a == "--record") o.record = next();
      else if (a == "--quiet") o.quiet = true;
      else return Usage("unknown argument " + a);
    } catch (const std::exception& e) {
      return Usage(a + ": " + e.what());
    }
  }
  const fs::path examples = fs::path(CAMOPT_SOURCE_DIR) / "studies" / "examples";
  std::vector<std::string> studies;
  for (const std::string& name : camopt::fuzz::StudioStudies()) studies.push_back(ReadFile(examples / name));
  if (o.show >= 0) {
    std::cout << Generator(8765, studies).Case(o.seed, o.show);
    return 0;
  }

  if (!o.save.empty()) fs::create_directories(o.save);
  std::unique_ptr<camopt::fuzz::InProcessStudio> studio;
  try {
    studio = std::make_unique<camopt::fuzz::InProcessStudio>(examples, CAMOPT_BINARY);
  } catch (const std::exception& e) {
    std::cerr << "camopt_request_fuzz: " << e.what() << "\n";
    return 2;
  }
  const int port = studio->port();
  const Generator generator(port, studies);

  std::map<std::string, long> outcomes;
  std::map<int, long> statuses;
  std::vector<std::string> failures;
  const auto t0 = std::chrono::steady_clock::now();
  auto last_progress = t0;
  double slowest = 0;
  auto fail = [&](const std::string& line, const std::string& text, long index) {
    failures.push_back(line);
    if (!o.quiet) std::cerr << "camopt_request_fuzz: FAILURE " << line << "\n";
    if (!o.save.empty())
      std::ofstream(o.save / ("request-seed" + std::to_string(o.seed) + "-case" + std::to_string(index) + ".http"),
                    std::ios::binary)
          << text;
  };
  for (long i = 0; i < o.cases; ++i) {
    const std::string text = generator.Case(o.seed, i);
    const auto t = std::chrono::steady_clock::now();
    const camopt::fuzz::Reply r = camopt::fuzz::Exchange(port, text);
    slowest = std::max(slowest, std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count());
    ++outcomes[r.outcome];
    if (r.status) ++statuses[r.status];
    if (camopt::fuzz::RequestFailure(r.outcome)) fail("case " + std::to_string(i) + ": " + r.outcome + ": " + r.first_line, text, i);
    if (i % 20 == 19) {  // the server still answers, promptly
      const std::string health = studio->Health();
      if (!health.empty()) fail("after case " + std::to_string(i) + ": " + health, text, i);
    }
    const auto now = std::chrono::steady_clock::now();
    if (!o.quiet && std::chrono::duration<double>(now - last_progress).count() > 10) {
      last_progress = now;
      const double e = std::chrono::duration<double>(now - t0).count();
      std::fprintf(stderr, "camopt_request_fuzz: %ld/%ld cases, %zu failures, elapsed %.0f s, ETA %.0f s\n", i + 1,
                   o.cases, failures.size(), e, e / double(i + 1) * double(o.cases - i - 1));
    }
  }
  // Nothing beside the served folder, no link in it.
  for (const std::string& stray : studio->Stray()) fail(stray, "", -1);
  studio.reset();

  json rec;
  rec["seed"] = o.seed;
  rec["cases"] = o.cases;
  rec["wall_s"] = std::round(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() * 10) / 10;
  rec["outcomes"] = outcomes;
  json st = json::object();
  for (const auto& [code, n] : statuses) st[std::to_string(code)] = n;
  rec["statuses"] = st;
  rec["slowest_s"] = slowest;
  rec["failures"] = static_cast<long>(failures.size());
  json fl = json::array();
  for (size_t k = 0; k < failures.size() && k < 50; ++k) fl.push_back(failures[k]);
  rec["first_failures"] = fl;
  if (!o.record.empty()) std::ofstream(o.record) << rec.dump(2) << "\n";
  std::cout << rec.dump(2) << "\n";
  return failures.empty() ? 0 : 1;
}

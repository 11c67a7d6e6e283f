// camopt_mutate: the mutation fuzzer of the command line. It mutates every example study (drop,
// duplicate, retype, scale and push fields to extremes, breed in a field of another example,
// change the kind, grow arrays, cut or corrupt the text), runs each mutant through exactly what
// `camopt run MUTANT --out DIR --quiet --max-work-factor F` does (studies/cli.h, in a forked
// child: no exec, no loading, so a case costs what the study costs) under a wall-time and an
// address-space limit, and classifies the outcome:
//   ran         exit 0, result.json written
//   refused     exit 2, "camopt: error: …" on stderr, nothing written, within 1 s CPU and 500 MB
//   incomplete  exit 3, "camopt: finished, but …", result.json written
// Anything else is a failure: exit 1 (a camopt defect), a signal, a timeout, a missing message,
// a refusal that was slow, big or left files, another exit code. The work factor F (default
// 0.01) scales every work cap of studies/work_limits.h: a study the estimate admits then runs in
// about F minutes, so a timeout means the estimate missed work.
//
// The time limit is CPU time (T s, default 10; the wall clock at 4 T).
//
// --memory-mb M is the address-space limit of a case (RLIMIT_AS; a case past it ends "out of memory",
// exit 1); --budget-mb B makes any case whose peak resident memory exceeds B a failure.
//
//   camopt_mutate --cases N [--seed S] [--jobs J] [--timeout-s T] [--memory-mb M] [--budget-mb B]
//                 [--sweeps DIR: mutate the sweep files of DIR and run `camopt sweep` on them]
//   camopt_mutate --fields [...]    (every numeric leaf of every kind's `camopt init` study set to
//                                    0, -1, ±1e-300, 1e308, -0, 5e-324, a string, a deep array)
//                 [--kind KIND] [--sample N] (one kind's cases; N of them, evenly spaced from seed)
//                 [--shard I/N]  (of those, every N-th from the I-th: one test per shard;
//                                 with --cases, cases I, I + N, I + 2N, ... below N's count)
//                 [--work-factor F] [--save DIR] [--record FILE] [--quiet]
//   camopt_mutate --replay DIR      (every *.json in DIR as it is: the corpus of past failures)
//   camopt_mutate --show I --seed S (print case I's study text: a failure is reproducible)
// Exit 0 when every case passed, 1 when any failed, 2 on bad arguments. docs/reliability.md has
// the record of the long runs.
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/time.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "studies/cli.h"
#include "studies/init.h"
#include "studies/study.h"
#include "studies/sweep.h"

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif
#else
constexpr bool kSanitized = false;
#endif

// Markers the serializer leaves in the text, replaced after dump(): a duplicated key and a number
// token JSON values cannot hold (1e400).
const std::string kDupMarker = "\x01" "dup" "\x01";
const std::string kNumMarker = "\x02" "num" "\x02";

struct Example {
  std::string file;  // file name in the examples folder
  json doc;
};

struct Options {
  fs::path examples = fs::path(CAMOPT_SOURCE_DIR) / "studies" / "examples";
  long cases = 1000;
  unsigned long long seed = 1;
  int jobs = 1;
  double timeout_s = 10;
  double memory_mb = 8192;  // address-space limit of a case (0: none)
  double work_factor = 0.01;
  double refusal_cpu_s = 1, refusal_rss_mb = 500;
  double budget_mb = 0;  // any case above this peak memory fails (0: only refusals are held to one)
  fs::path save, record, replay;
  /// Sweep files to mutate instead of studies (`camopt sweep MUTANT --out DIR --jobs 1 ...`); their
  /// bases ("../examples/NAME.json") resolve to the example studies.
  fs::path sweeps;
  /// Every numeric leaf of every kind's `camopt init` study set to each of kFieldValues in turn
  /// (one case each, in order; --cases is ignored).
  bool fields = false;
  /// With --fields: only this kind's cases (empty: every kind), and of them only `sample` evenly
  /// spaced ones, the first at seed % spacing (0: all).
  std::string kind;
  long sample = 0;
  /// Of the cases above, only those whose number is `shard` modulo `shards` (a test per shard).
  long shard = 0, shards = 1;
  long show = -1;
  bool quiet = false;
};

// ------------------------------------------------------------------------------------------------
// Mutations
// ------------------------------------------------------------------------------------------------

class Mutator {
 public:
  Mutator(const std::vector<Example>& examples) : examples_(examples) {
    for (const auto& e : examples) {
      Collect(e.doc);
      kinds_.push_back(e.doc.value("study", std::string("?")));
    }
  }

  /// The text of case `index` of the run with `seed`, and the example it came from.
  std::string Case(unsigned long long seed, long index, std::string* from) const {
    std::mt19937_64 rng(seed * 0x9E3779B97F4A7C15ULL + static_cast<unsigned long long>(index));
    const Example& ex = examples_[Pick(rng, examples_.size())];
    *from = ex.file;
    json doc = ex.doc;
    const int count = 1 + static_cast<int>(std::geometric_distribution<int>(0.45)(rng) % 5);
    for (int m = 0; m < count; ++m) Mutate(doc, rng);
    std::string text = Finish(doc.dump(2));
    // Text-level damage, rarely: cut the file, or put a stray byte in.
    const double u = Uniform(rng);
    if (u < 0.03 && !text.empty()) {
      text.resize(Pick(rng, text.size()));
    } else if (u < 0.05 && !text.empty()) {
      static const char kBytes[] = {'\0', '{', '}', '[', ']', ',', ':', '"', '\\', '\xff', '\xc3', '\n'};
      text.insert(text.begin() + static_cast<long>(Pick(rng, text.size())), kBytes[Pick(rng, sizeof kBytes)]);
    }
    return text;
  }

 private:
  static size_t Pick(std::mt19937_64& rng, size_t n) {
    return n == 0 ? 0 : static_cast<size_t>(rng() % n);
  }
  static double Uniform(std::mt19937_64& rng) { return std::uniform_real_distribution<double>(0, 1)(rng); }

  void Collect(const json& j) {
    if (j.is_object()) {
      for (auto it = j.begin(); it != j.end(); ++it) {
        pool_[it.key()].push_back(it.value());
        Collect(it.value());
      }
    } else if (j.is_array()) {
      for (const auto& v : j) Collect(v);
    }
  }

  static void Nodes(const json& j, const json::json_pointer& at, std::vector<json::json_pointer>& out) {
    if (j.is_object()) {
      for (auto it = j.begin(); it != j.end(); ++it) {
        out.push_back(at / it.key());
        Nodes(it.value(), at / it.key(), out);
      }
    } else if (j.is_array()) {
      for (size_t i = 0; i < j.size(); ++i) {
        out.push_back(at / i);
        Nodes(j[i], at / i, out);
      }
    }
  }

  json Extreme(std::mt19937_64& rng) const {
    static const std::vector<std::string> kTokens = {
        "0", "-0.0", "-1", "1", "0.5", "1e-300", "5e-324", "1e300", "1.7976931348623157e308",
        "-1e308", "2147483648", "-2147483649", "9223372036854775807", "18446744073709551615",
        "1e400", "-1e400", "1e-400", "3", "2", "1e9", "-1e9", "1e6", "100000", "1e-9", "0.999999999999"};
    const std::string& t = kTokens[Pick(rng, kTokens.size())];
    if (t == "1e400" || t == "-1e400" || t == "1e-400") return json(kNumMarker + t);
    return json::parse(t);
  }

  json OddString(std::mt19937_64& rng) const {
    static const std::vector<std::string> kStrings = {
        "", "x", "line\nbreak", "quote\"and'apostrophe", "back\\slash", "/dev/zero", "/proc/self/mem",
        "../../../../etc/passwd", "missing_file.json", ".", "/", "needle_rollers.json",
        "\xc3\xa9\xe2\x82\xac unicode", "none", "NaN", "inf", "-1", "1e400", "ENDSEC\n0\nEOF",
        std::string(3000, 'a')};
    if (Uniform(rng) < 0.3 && !kinds_.empty()) return json(kinds_[Pick(rng, kinds_.size())]);
    return json(kStrings[Pick(rng, kStrings.size())]);
  }

  json OtherType(const json& v, std::mt19937_64& rng) const {
    for (;;) {
      json r;
      switch (Pick(rng, 8)) {
        case 0: r = OddString(rng); break;
        case 1: r = Extreme(rng); break;
        case 2: r = Uniform(rng) < 0.5; break;
        case 3: r = nullptr; break;
        case 4: r = json::array(); break;
        case 5: r = json::object(); break;
        case 6: r = json::array({v}); break;
        default: r = json::object({{"value", v}}); break;
      }
      if (r.type() != v.type() || v.is_null()) return r;
    }
  }

  json Scaled(const json& v, std::mt19937_64& rng) const {
    if (!v.is_number()) return Extreme(rng);
    const double x = v.get<double>();
    switch (Pick(rng, 6)) {
      case 0: return -x;
      case 1: return x + 1;
      case 2: return std::round(x * 1.5 + 0.5);
      case 3: return x * 1e-3;
      default: {
        const int k = static_cast<int>(Pick(rng, 25)) - 12;
        return x * std::pow(10.0, k);
      }
    }
  }

  json Grown(const json& v, std::mt19937_64& rng) const {
    if (!v.is_array()) return json::array({v});
    static const size_t kLengths[] = {0, 1, 2, 3, 50, 400};
    const size_t n = kLengths[Pick(rng, 6)];
    json r = json::array();
    for (size_t i = 0; i < n; ++i) r.push_back(v.empty() ? json(i) : v[i % v.size()]);
    return r;
  }

  void Mutate(json& doc, std::mt19937_64& rng) const {
    std::vector<json::json_pointer> nodes;
    Nodes(doc, json::json_pointer(), nodes);
    if (nodes.empty() || !doc.is_object()) return;
    const json::json_pointer at = nodes[Pick(rng, nodes.size())];
    json& v = doc[at];
    json& parent = doc[at.parent_pointer()];
    const std::string key = at.back();
    switch (Pick(rng, 12)) {
      case 0:  // drop
        if (parent.is_object()) parent.erase(key);
        else parent.erase(static_cast<size_t>(std::stoul(key)));
        return;
      case 1:  // duplicate (an object key twice in the text; an array element twice)
        if (parent.is_object()) {
          parent[kDupMarker + key] = Uniform(rng) < 0.5 ? v : Scaled(v, rng);
        } else {
          const json copy = v;
          parent.insert(parent.begin() + static_cast<long>(std::stoul(key)), copy);
        }
        return;
      case 2: v = OtherType(v, rng); return;
      case 3: case 4: v = Scaled(v, rng); return;
      case 5: v = Extreme(rng); return;
      case 6: v = OddString(rng); return;
      case 7: {  // breed: the value of a same-named field in any example
        const auto it = pool_.find(key);
        if (it != pool_.end()) v = it->second[Pick(rng, it->second.size())];
        else v = Grown(v, rng);
        return;
      }
      case 8: {  // add a field of another example to an object
        json& obj = v.is_object() ? v : (parent.is_object() ? parent : doc);
        auto it = pool_.begin();
        std::advance(it, static_cast<long>(Pick(rng, pool_.size())));
        obj[it->first] = it->second[Pick(rng, it->second.size())];
        return;
      }
      case 9: v = Grown(v, rng); return;
      case 10: doc["study"] = Uniform(rng) < 0.8 ? json(kinds_[Pick(rng, kinds_.size())]) : OtherType(doc["study"], rng); return;
      default:  // an unknown field
        (v.is_object() ? v : doc)["unknown_field_" + std::to_string(Pick(rng, 3))] = 1;
        return;
    }
  }

  // Replaces the markers in the dumped text.
  static std::string Finish(std::string text) {
    // nlohmann escapes the control characters of the markers as \u0001 / \u0002.
    const std::string dup = "\"\\u0001dup\\u0001", num = "\"\\u0002num\\u0002";
    for (size_t p; (p = text.find(dup)) != std::string::npos;) text.replace(p, dup.size(), "\"");
    for (size_t p; (p = text.find(num)) != std::string::npos;) {
      const size_t end = text.find('"', p + num.size());
      text.replace(p, end + 1 - p, text.substr(p + num.size(), end - p - num.size()));
    }
    return text;
  }

  const std::vector<Example>& examples_;
  std::map<std::string, std::vector<json>> pool_;
  std::vector<std::string> kinds_;
};

// ------------------------------------------------------------------------------------------------
// Running and judging a case
// ------------------------------------------------------------------------------------------------

const std::vector<std::string> kOutcomes = {
    "ran", "refused", "incomplete",  // the three good answers
    "defect (exit 1)", "signal", "timeout", "no message", "slow refusal", "big refusal",
    "refusal left files", "no result.json", "other exit code", "over the memory budget"};
bool Failure(const std::string& outcome) {
  return outcome != "ran" && outcome != "refused" && outcome != "incomplete";
}

struct Finished {
  std::string outcome;
  int code = -1;
  double wall_s = 0, cpu_s = 0, rss_mb = 0;
  std::string message;  // first line of stderr
};

std::string ReadFile(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

Finished Judge(int status, const rusage& ru, double wall_s, const fs::path& err_file, const fs::path& out,
               const Options& o) {
  Finished f;
  f.wall_s = wall_s;
  f.cpu_s = static_cast<double>(ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) +
            1e-6 * static_cast<double>(ru.ru_utime.tv_usec + ru.ru_stime.tv_usec);
  f.rss_mb = static_cast<double>(ru.ru_maxrss) / 1024.0;  // KiB on Linux
  const std::string err = ReadFile(err_file);
  f.message = err.substr(0, std::min(err.find('\n'), size_t{300}));
  const bool has_result = fs::exists(out / "result.json");
  // A sweep's case that failed (out of memory or a camopt defect) is a defect of the sweep's answer.
  if (!o.sweeps.empty() && has_result && WIFEXITED(status) && (WEXITSTATUS(status) == 0 || WEXITSTATUS(status) == 3)) {
    const json summary = json::parse(ReadFile(out / "result.json"), nullptr, false);
    const json failed = summary.is_object() ? summary.value("/status_counts/failed"_json_pointer, json(0)) : json(0);
    if (!failed.is_number() || failed.get<long>() != 0) {
      f.code = WEXITSTATUS(status);
      f.outcome = "defect (exit 1)";
      f.message = "a case failed: " + summary.value("/cases_not_ok"_json_pointer, json()).dump().substr(0, 300);
      return f;
    }
  }
  const double scale = kSanitized ? 5.0 : 1.0;
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    f.outcome = sig == SIGALRM || sig == SIGXCPU || (sig == SIGKILL && f.cpu_s >= o.timeout_s) ? "timeout" : "signal";
    f.code = -WTERMSIG(status);
    if (f.outcome == "signal") f.message = std::string("signal ") + strsignal(WTERMSIG(status));
    return f;
  }
  f.code = WEXITSTATUS(status);
  switch (f.code) {
    case 0: f.outcome = has_result ? "ran" : "no result.json"; break;
    case 2:
      if (err.find("camopt: error: ") == std::string::npos || err.size() < 30) f.outcome = "no message";
      else if (fs::exists(out) || fs::exists(out.string() + ".camopt-sweep")) f.outcome = "refusal left files";
      else if (f.cpu_s > o.refusal_cpu_s * scale) f.outcome = "slow refusal";
      else if (f.rss_mb > o.refusal_rss_mb * scale) f.outcome = "big refusal";
      else f.outcome = "refused";
      break;
    case 3:
      // (a sweep with --quiet says nothing more: its cases' statuses are in its result.json)
      if (o.sweeps.empty() && err.find("camopt: finished, but") == std::string::npos) f.outcome = "no message";
      else f.outcome = has_result ? "incomplete" : "no result.json";
      break;
    case 1: f.outcome = "defect (exit 1)"; break;
    default: f.outcome = "other exit code"; break;
  }
  if (o.budget_mb > 0 && !Failure(f.outcome) && f.rss_mb > o.budget_mb * scale) f.outcome = "over the memory budget";
  return f;
}

struct Running {
  pid_t pid = 0;
  long index = 0;
  std::string text, from;
  std::chrono::steady_clock::time_point start;
};

[[noreturn]] void RunChild(const fs::path& study, const fs::path& out, const fs::path& err, const Options& o,
                           double runs = 1) {
  const int efd = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  const int nfd = ::open("/dev/null", O_RDWR);
  if (efd < 0 || nfd < 0) _exit(97);
  dup2(efd, 2);
  dup2(nfd, 1);
  dup2(nfd, 0);
  rlimit core{0, 0};
  setrlimit(RLIMIT_CORE, &core);
  if (o.memory_mb > 0 && !kSanitized) {  // ASan reserves terabytes of address space
    const rlim_t bytes = static_cast<rlim_t>(o.memory_mb * 1024 * 1024);
    rlimit as{bytes, bytes};
    setrlimit(RLIMIT_AS, &as);
  }
  // The time limit is on CPU time (SIGXCPU), so that a loaded machine does not turn a case into a
  // timeout; the wall-clock alarm at four times it catches a case that waits without computing.
  // A sweep of N cases is N runs, each within the caps: it has the time of N/10 runs (the example
  // sweeps' cases take a tenth of a run's limit or less), at least one run's.
  const rlim_t cpu = static_cast<rlim_t>(std::ceil(o.timeout_s * std::max(1.0, runs / 10) * (kSanitized ? 5 : 1)));
  rlimit cpu_limit{cpu, cpu + 2};
  setrlimit(RLIMIT_CPU, &cpu_limit);
  alarm(static_cast<unsigned>(4 * cpu));
  char factor[64];
  std::snprintf(factor, sizeof factor, "%.17g", o.work_factor);
  std::vector<std::string> args = {"camopt", "run", study.string(), "--out", out.string(), "--quiet",
                                   "--max-work-factor", factor};
  if (!o.sweeps.empty()) {
    args[1] = "sweep";
    args.insert(args.end(), {"--jobs", "1"});
  }
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const int code = camopt::studies::CliMain(static_cast<int>(args.size()), argv.data());
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  _exit(code);
}

// --fields: (name, text) of every kind's init study with one numeric leaf set to one value; the
// name is "KIND /pointer = value".
std::vector<std::pair<std::string, std::string>> FieldCases() {
  json deep = 1;
  for (int i = 0; i < 64; ++i) deep = json::array({deep});
  const std::vector<std::pair<std::string, json>> values = {
      {"0", 0},          {"-1", -1},     {"1e-300", 1e-300},       {"-1e-300", -1e-300}, {"1e308", 1e308},
      {"-0", -0.0},      {"5e-324", 5e-324}, {"\"x\"", "x"},     {"a 64-deep array", deep}};
  std::vector<std::pair<std::string, std::string>> out;
  for (const std::string& kind : camopt::studies::StudyKinds()) {
    const json doc = json::parse(camopt::studies::InitTemplate(kind).text);
    const json flat = doc.flatten();
    for (const auto& [pointer, leaf] : flat.items()) {
      if (!leaf.is_number()) continue;
      for (const auto& [label, value] : values) {
        json m = doc;
        m[json::json_pointer(pointer)] = value;
        out.emplace_back(kind + " " + pointer + " = " + label, m.dump(2));
      }
    }
  }
  return out;
}

std::vector<Example> LoadExamples(const fs::path& dir) {
  std::vector<Example> out;
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file() && e.path().extension() == ".json") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  for (const auto& f : files) {
    json j = json::parse(ReadFile(f), nullptr, false);
    if (j.is_object() && ((j.contains("study") && j["study"].is_string()) || (j.contains("sweep") && j["sweep"].is_string())))
      out.push_back({f.filename().string(), std::move(j)});
  }
  return out;
}

std::string Clock(double s) {
  char b[32];
  std::snprintf(b, sizeof b, "%d:%02d", static_cast<int>(s) / 60, static_cast<int>(s) % 60);
  return b;
}

int Usage(const std::string& why) {
  std::cerr << "camopt_mutate: " << why << "\n"
            << "usage: camopt_mutate [--cases N] [--seed S] [--jobs J] [--timeout-s T] [--memory-mb M] [--budget-mb B]\n"
               "                     [--work-factor F] [--examples DIR] [--sweeps DIR] [--save DIR] [--record FILE] [--quiet]\n"
               "       camopt_mutate --replay DIR | --fields [--kind K] [--sample N] [--shard I/N] | --show I [--seed S]\n";
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
      else if (a == "--jobs") o.jobs = std::max(1, std::stoi(next()));
      else if (a == "--timeout-s") o.timeout_s = std::stod(next());
      else if (a == "--memory-mb") o.memory_mb = std::stod(next());
      else if (a == "--budget-mb") o.budget_mb = std::stod(next());
      else if (a == "--work-factor") o.work_factor = std::stod(next());
      else if (a == "--examples") o.examples = next();
      else if (a == "--sweeps") o.sweeps = next();
      else if (a == "--fields") o.fields = true;
      else if (a == "--kind") o.kind = next();
      else if (a == "--sample") o.sample = std::max(0L, std::stol(next()));
      else if (a == "--shard") {
        const std::string v = next();
        const size_t slash = v.find('/');
        if (slash == std::string::npos) return Usage("--shard I/N");
        o.shard = std::stol(v.substr(0, slash));
        o.shards = std::stol(v.substr(slash + 1));
        if (o.shards < 1 || o.shard < 0 || o.shard >= o.shards) return Usage("--shard I/N with 0 <= I < N");
      }
      else if (a == "--save") o.save = next();
      else if (a == "--record") o.record = next();
      else if (a == "--replay") o.replay = next();
      else if (a == "--show") o.show = std::stol(next());
      else if (a == "--quiet") o.quiet = true;
      else return Usage("unknown argument " + a);
    } catch (const std::exception& e) {
      return Usage(a + ": " + e.what());
    }
  }
  const std::vector<Example> examples = LoadExamples(o.sweeps.empty() ? o.examples : o.sweeps);
  if (examples.empty()) return Usage("no example studies or sweeps in " + (o.sweeps.empty() ? o.examples : o.sweeps).string());
  const Mutator mutator(examples);
  if (o.show >= 0) {
    std::string from;
    std::cout << mutator.Case(o.seed, o.show, &from) << "\n";
    std::cerr << "camopt_mutate: case " << o.show << " of seed " << o.seed << ", from " << from << "\n";
    return 0;
  }

  // The replayed corpus, or the mutants, each with its name.
  std::vector<std::pair<std::string, std::string>> replay;  // (name, text)
  if (!o.replay.empty()) {
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(o.replay))
      if (e.is_regular_file() && e.path().extension() == ".json") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    for (const auto& f : files) replay.emplace_back(f.filename().string(), ReadFile(f));
    if (replay.empty()) return Usage("no *.json in " + o.replay.string());
    o.cases = static_cast<long>(replay.size());
  } else if (o.fields) {
    for (auto& c : FieldCases())
      if (o.kind.empty() || c.first.rfind(o.kind + " ", 0) == 0) replay.push_back(std::move(c));
    if (replay.empty()) return Usage("--kind " + o.kind + ": no such study kind");
    if (o.sample > 0 && o.sample < static_cast<long>(replay.size())) {
      // Evenly spaced over the kind's fields and values in order, so a sample meets every part.
      const double spacing = double(replay.size()) / double(o.sample);
      const double first = double(o.seed % static_cast<unsigned long long>(std::max(1.0, std::floor(spacing))));
      std::vector<std::pair<std::string, std::string>> picked;
      for (long k = 0; k < o.sample; ++k) picked.push_back(std::move(replay[static_cast<size_t>(first + spacing * double(k))]));
      replay = std::move(picked);
    }
    if (o.shards > 1) {
      std::vector<std::pair<std::string, std::string>> mine;
      for (size_t k = 0; k < replay.size(); ++k)
        if (static_cast<long>(k % static_cast<size_t>(o.shards)) == o.shard) mine.push_back(std::move(replay[k]));
      replay = std::move(mine);
    }
    o.cases = static_cast<long>(replay.size());
  }
  // Random mutants of one shard: cases shard, shard + shards, ... (each keeps its number, so that
  // `--show I` prints the case a shard reported).
  const long first_case = replay.empty() ? o.shard : 0, case_step = replay.empty() ? o.shards : 1;
  if (replay.empty() && o.shards > 1) o.cases = o.cases > o.shard ? (o.cases - o.shard + o.shards - 1) / o.shards : 0;

  // A scratch folder that looks like the examples folder (relative catalogue paths resolve).
  std::string pattern = (fs::temp_directory_path() / "camopt-mutate-XXXXXX").string();
  if (!mkdtemp(pattern.data())) return Usage("cannot create a scratch folder in " + fs::temp_directory_path().string());
  const fs::path scratch = pattern, ex = scratch / (o.sweeps.empty() ? "examples" : "sweeps");
  fs::create_directories(ex);
  fs::create_directories(scratch / "examples");
  for (const auto& e : fs::directory_iterator(o.examples))
    if (e.is_regular_file()) fs::create_symlink(fs::absolute(e.path()), scratch / "examples" / e.path().filename());
  if (!o.save.empty()) fs::create_directories(o.save);

  std::map<std::string, long> counts;
  std::map<std::string, std::map<std::string, long>> by_kind;  // example → outcome → count
  std::vector<std::string> failures;
  long refused_by_caps = 0;  // refusals that name the work or memory caps
  double max_refusal_cpu = 0, max_refusal_rss = 0, max_rss = 0, slowest = 0;
  std::string slowest_case, biggest_case;
  std::vector<std::pair<double, std::string>> biggest;  // (peak MB, case), largest first
  std::vector<Running> slots(static_cast<size_t>(o.jobs));
  const auto t0 = std::chrono::steady_clock::now();
  auto last_progress = t0;
  long next = 0, done = 0;
  int running = 0;
  const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };

  while (done < o.cases) {
    // Fill the free slots.
    for (size_t s = 0; s < slots.size() && next < o.cases; ++s) {
      if (slots[s].pid != 0) continue;
      Running& r = slots[s];
      r.index = first_case + case_step * next++;
      if (!replay.empty()) {
        r.from = replay[static_cast<size_t>(r.index)].first;
        r.text = replay[static_cast<size_t>(r.index)].second;
      } else {
        r.text = mutator.Case(o.seed, r.index, &r.from);
      }
      const fs::path study = ex / ("mutant_" + std::to_string(s) + ".json");
      const fs::path out = scratch / ("out_" + std::to_string(s));
      fs::remove_all(out);
      {
        std::ofstream f(study, std::ios::binary | std::ios::trunc);
        f << r.text;
      }
      // A sweep's case count (1 when the sweep file is refused: the refusal is the case).
      double runs = 1;
      if (!o.sweeps.empty()) {
        try {
          runs = double(camopt::studies::sweep::CheckSweep(json::parse(r.text), study.string()));
        } catch (const std::exception&) {
        }
      }
      r.start = std::chrono::steady_clock::now();
      const pid_t pid = fork();
      if (pid < 0) {
        std::perror("camopt_mutate: fork");
        return 2;
      }
      if (pid == 0) RunChild(study, out, scratch / ("err_" + std::to_string(s)), o, runs);
      r.pid = pid;
      ++running;
    }
    int status = 0;
    rusage ru{};
    const pid_t pid = wait4(-1, &status, 0, &ru);
    if (pid < 0) {
      std::perror("camopt_mutate: wait4");
      return 2;
    }
    const auto it = std::find_if(slots.begin(), slots.end(), [&](const Running& r) { return r.pid == pid; });
    if (it == slots.end()) continue;
    const size_t s = static_cast<size_t>(it - slots.begin());
    Running& r = *it;
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - r.start).count();
    const fs::path out = scratch / ("out_" + std::to_string(s));
    const Finished f = Judge(status, ru, wall, scratch / ("err_" + std::to_string(s)), out, o);
    ++counts[f.outcome];
    ++by_kind[o.fields ? r.from.substr(0, r.from.find(' ')) : r.from][f.outcome];
    if (f.outcome == "refused") {
      if (f.message.find("--max-work-factor") != std::string::npos) ++refused_by_caps;
      max_refusal_cpu = std::max(max_refusal_cpu, f.cpu_s);
      max_refusal_rss = std::max(max_refusal_rss, f.rss_mb);
    }
    const std::string name = replay.empty() ? "case " + std::to_string(r.index) + " (" + r.from + ")" : r.from;
    if (f.wall_s > slowest) slowest = f.wall_s, slowest_case = name + ", " + f.outcome;
    if (f.rss_mb > max_rss) max_rss = f.rss_mb, biggest_case = name + ", " + f.outcome;
    // The five largest cases by peak memory (candidates for the corpus run under a memory limit).
    biggest.push_back({f.rss_mb, name + ", " + f.outcome});
    std::sort(biggest.begin(), biggest.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    if (biggest.size() > 5) biggest.pop_back();
    if (Failure(f.outcome)) {
      std::ostringstream line;
      line << name << ": " << f.outcome << " (exit " << f.code << ", " << f.wall_s << " s, " << f.rss_mb
           << " MB): " << f.message;
      failures.push_back(line.str());
      if (!o.quiet) std::cerr << "camopt_mutate: FAILURE " << line.str() << "\n";
      if (!o.save.empty()) {
        std::string tag = f.outcome.substr(0, f.outcome.find(' '));
        const std::string stem = tag + "-seed" + std::to_string(o.seed) + "-case" + std::to_string(r.index);
        std::ofstream(o.save / (stem + ".json"), std::ios::binary) << r.text;
        std::ofstream(o.save / (stem + ".txt")) << line.str() << "\nfrom " << r.from << "\n"
                                               << ReadFile(scratch / ("err_" + std::to_string(s)));
      }
    }
    fs::remove_all(out);
    fs::remove_all(out.string() + ".camopt-sweep");
    r.pid = 0;
    --running;
    ++done;
    const auto now = std::chrono::steady_clock::now();
    if (!o.quiet && (std::chrono::duration<double>(now - last_progress).count() > 10 || done == o.cases)) {
      last_progress = now;
      const double t = elapsed();
      std::cerr << "camopt_mutate: " << done << "/" << o.cases << " cases, " << failures.size()
                << " failures, elapsed " << Clock(t) << ", ETA " << Clock(t / static_cast<double>(done) *
                                                                         static_cast<double>(o.cases - done))
                << "\n";
    }
  }
  fs::remove_all(scratch);

  json rec;
  rec["mode"] = std::string(o.fields           ? "fields"
                           : replay.empty()     ? "mutate"
                                                : "replay " + o.replay.string()) +
                (o.sweeps.empty() ? "" : " sweeps");
  rec["seed"] = o.seed;
  rec["cases"] = done;
  rec["jobs"] = o.jobs;
  rec["work_factor"] = o.work_factor;
  rec["timeout_s"] = o.timeout_s;
  rec["memory_limit_mb"] = kSanitized ? 0.0 : o.memory_mb;
  rec["sanitized"] = kSanitized;
  rec["wall_s"] = std::round(elapsed() * 10) / 10;
  json c = json::object();
  for (const auto& k : kOutcomes)
    if (counts.count(k)) c[k] = counts[k];
  rec["outcomes"] = c;
  rec["refused_by_the_caps"] = refused_by_caps;
  rec["failures"] = static_cast<long>(failures.size());
  rec["refusals_max_cpu_s"] = max_refusal_cpu;
  rec["refusals_max_rss_mb"] = max_refusal_rss;
  rec["max_rss_mb"] = max_rss;
  rec["biggest_case"] = biggest_case;
  json big = json::array();
  for (const auto& [mb, name] : biggest) big.push_back(json::object({{"peak_mb", mb}, {"case", name}}));
  rec["biggest_cases"] = big;
  rec["slowest_s"] = slowest;
  rec["slowest_case"] = slowest_case;
  json k = json::object();
  for (const auto& [from, oc] : by_kind) k[from] = oc;
  rec["by_example"] = k;
  json fl = json::array();
  for (size_t i = 0; i < failures.size() && i < 50; ++i) fl.push_back(failures[i]);
  rec["first_failures"] = fl;
  if (!o.record.empty()) std::ofstream(o.record) << rec.dump(2) << "\n";
  json brief = rec;
  brief.erase("by_example");
  std::cout << brief.dump(2) << "\n";
  return failures.empty() ? 0 : 1;
}

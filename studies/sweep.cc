#include "studies/sweep.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <mutex>
#include <new>
#include <set>
#include <sstream>
#include <thread>

#include <sys/stat.h>

#include "studies/study.h"
#include "studies/sweep_checkpoint.h"
#include "studies/sweep_design.h"
#include "studies/sweep_pareto.h"
#include "studies/sweep_report.h"
#include "studies/sweep_world.h"
#include "studies/work_limits.h"
#include "studies/writers.h"

namespace camopt::studies::sweep {

namespace fs = std::filesystem;
using nlohmann::json;
using Pointer = json::json_pointer;

namespace {

const std::set<std::string> kDesigns = {"factorial", "zip", "latin_hypercube", "sobol"};

std::string Fmt(double v, const char* format = "%.10g") {
  char buf[40];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

// A JSON pointer from a string node ("/target/speed_ratio").
Pointer ReadPointer(const Node& n) {
  const std::string s = n.String();
  if (s.empty() || s[0] != '/') n.Fail("a JSON pointer such as \"/load/torque_Nm\"");
  try {
    return Pointer(s);
  } catch (const json::exception&) {
    n.Fail("a JSON pointer such as \"/load/torque_Nm\"");
  }
}

// The study must already hold the object (or array element) that the pointer writes into: a
// misspelt path is refused here, not silently added as a new field.
void CheckSettable(const json& study, const Pointer& p, const Node& n) {
  const Pointer parent = p.parent_pointer();
  if (!study.contains(parent))
    n.FailWith("the base study has no " + (parent.empty() ? std::string("/") : parent.to_string()) +
               " to set \"" + p.back() + "\" in");
  const json& holder = study.at(parent);
  if (holder.is_object()) return;
  if (holder.is_array()) {
    const std::string& key = p.back();
    const bool digits = !key.empty() && std::all_of(key.begin(), key.end(), ::isdigit);
    if (digits && key.size() < 10 && std::stoul(key) < holder.size()) return;
    n.FailWith("the base study's " + parent.to_string() + " has " + std::to_string(holder.size()) +
               " elements; \"" + key + "\" is not one of them");
  }
  n.FailWith("the base study's " + parent.to_string() + " is " + Describe(holder) +
             ", not an object to set \"" + p.back() + "\" in");
}

std::string CsvText(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::string CsvCell(const json& v) {
  if (v.is_null()) return "";
  if (v.is_number_float()) return Fmt(v.get<double>());
  if (v.is_number()) return v.dump();
  if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
  if (v.is_string()) return CsvText(v.get<std::string>());
  return CsvText(v.dump());
}

}  // namespace

Sweep Parse(const std::string& file, double max_cases) { return ParseJson(LoadStudyFile(file), file, max_cases); }

size_t CheckSweep(const json& doc, const std::string& file) { return Cases(ParseJson(doc, file)).size(); }

Sweep ParseJson(const json& doc, const std::string& file, double max_cases) {
  const Node root(&doc, file, "");
  if (!doc.is_object()) root.Fail("a sweep object");
  root.CheckKnownFields({"sweep", "description", "base", "set", "vary", "design", "samples", "seed",
                         "outputs", "pareto", "case_outputs"});
  Sweep s;
  s.file = file;
  s.name = root["sweep"].String();

  const Node base = root["base"];
  if (base.json().is_string()) {
    fs::path p(base.String());
    if (p.is_relative()) p = fs::path(file).parent_path() / p;
    s.study_file = p.string();
    try {
      s.base = LoadStudyFile(s.study_file);
    } catch (const StudyError& e) {
      throw StudyError(file + ": /base: " + e.what());
    }
  } else if (base.json().is_object()) {
    s.base = base.json();
    s.study_file = file;
  } else {
    base.Fail("a study file name or an inline study object");
  }
  if (!s.base.is_object() || !s.base.contains("study"))
    base.FailWith("the base is not a study (it has no \"study\" kind)");

  if (root.Has("set")) {
    const Node set = root["set"];
    if (!set.json().is_object()) set.Fail("an object of JSON pointer: value");
    for (auto it = set.json().begin(); it != set.json().end(); ++it) {
      const std::string key_path = "/set/" + it.key();
      const json key = it.key();
      const Node key_node(&key, file, key_path);
      const Pointer p = ReadPointer(key_node);
      CheckSettable(s.base, p, key_node);
      s.base[p] = it.value();
    }
  }

  s.design = root.StringOr("design", "factorial");
  if (!kDesigns.count(s.design))
    root["design"].Fail("one of factorial, zip, latin_hypercube, sobol");
  const bool sampled = s.design == "latin_hypercube" || s.design == "sobol";
  if (sampled) {
    s.samples = root["samples"].Integer(1);
    if (s.samples > max_cases)
      root["samples"].FailWith("more than the cap of " + Fmt(max_cases, "%.3g") +
                               " cases; raise it with --max-work-factor");
  } else if (root.Has("samples")) {
    root["samples"].FailWith("samples are for the latin_hypercube and sobol designs");
  }
  if (root.Has("seed")) {
    if (s.design != "latin_hypercube") root["seed"].FailWith("a seed is for the latin_hypercube design");
    s.seed = static_cast<uint64_t>(root["seed"].Integer(0));
  }

  const Node vary = root["vary"];
  const std::vector<Node> entries = vary.Elements();
  if (entries.empty()) vary.Fail("at least one field to vary");
  double cases = 1;
  for (const Node& e : entries) {
    e.CheckKnownFields({"path", "values", "range", "count", "log", "integer"});
    Variation v;
    const Pointer p = ReadPointer(e["path"]);
    CheckSettable(s.base, p, e["path"]);
    v.path = p.to_string();
    for (const Variation& other : s.vary)
      if (other.path == v.path) e["path"].FailWith("varied twice");
    v.log = e.BoolOr("log", false);
    v.integer = e.BoolOr("integer", false);
    if (e.Has("values") == e.Has("range")) e.FailWith("expected either \"values\" or \"range\"");
    if (e.Has("values")) {
      for (const Node& x : e["values"].Elements()) {
        if (v.integer && !x.json().is_number_integer()) x.Fail("a whole number (\"integer\": true)");
        v.values.push_back(x.json());
      }
      if (v.values.empty()) e["values"].Fail("at least one value");
      if (e.Has("count")) e["count"].FailWith("a count is for a range");
      if (v.log) e["log"].FailWith("log spacing is for a range");
    } else {
      std::tie(v.lo, v.hi) = e["range"].Range();
      if (v.log && !(v.lo > 0)) e["range"].Fail("a range of positive numbers (\"log\": true)");
      v.has_range = true;
      if (sampled) {
        if (e.Has("count"))
          e["count"].FailWith("a count is for the factorial and zip designs; the " + s.design +
                              " design takes \"samples\"");
      } else {
        const int count = e["count"].Integer(1);
        if (count > max_cases) e["count"].FailWith("more than the cap of " + Fmt(max_cases, "%.3g") + " cases");
        v.values = RangeLevels(v, count);
      }
    }
    if (s.design == "factorial") cases *= static_cast<double>(v.values.size());
    if (s.design == "zip") {
      if (!s.vary.empty() && v.values.size() != s.vary.front().values.size())
        e.FailWith("the zip design needs as many levels in every field (" +
                   std::to_string(s.vary.front().values.size()) + " in the first, " +
                   std::to_string(v.values.size()) + " here)");
      cases = static_cast<double>(v.values.size());
    }
    s.vary.push_back(std::move(v));
  }
  if (s.design == "factorial" && cases > max_cases)
    vary.FailWith("the factorial design has " + Fmt(cases, "%.3g") + " cases, more than the cap of " +
                  Fmt(max_cases, "%.3g") + "; raise it with --max-work-factor");
  if (s.design == "sobol" && s.vary.size() > 3667)  // Boost's table of direction numbers
    vary.FailWith("the sobol design takes at most 3667 fields");
  // The expansion itself, before it is built: one JSON value per case and field (a Sobol design of
  // 1e6 samples over 50 fields took 14 s and 1.5 GB in --dry-run, over 3 667 fields it asked for
  // 29 GB). Ten values per case of the cap, at the same --max-work-factor.
  {
    const double n_cases = sampled ? static_cast<double>(s.samples) : cases;
    const double values = n_cases * static_cast<double>(s.vary.size());
    if (values > 10 * max_cases)
      vary.FailWith("the design has " + Fmt(n_cases, "%.3g") + " cases of " + std::to_string(s.vary.size()) +
                    " fields, " + Fmt(values, "%.3g") + " values, more than the cap of " + Fmt(10 * max_cases, "%.3g") +
                    " (expanded before any case runs); fewer samples or fields, or raise it with --max-work-factor");
  }

  const Node outputs = root["outputs"];
  auto add_output = [&](const Node& n) {
    const std::string path = ReadPointer(n).to_string();
    for (size_t i = 0; i < s.outputs.size(); ++i)
      if (s.outputs[i].path == path) return i;
    s.outputs.push_back({path});
    return s.outputs.size() - 1;
  };
  for (const Node& o : outputs.Elements()) add_output(o);
  if (s.outputs.empty()) outputs.Fail("at least one JSON pointer into result.json");
  if (root.Has("pareto")) {
    const Node pareto = root["pareto"];
    pareto.CheckKnownFields({"minimize", "maximize"});
    std::set<size_t> seen;
    auto objectives = [&](const char* key, std::vector<size_t>& into) {
      if (!pareto.Has(key)) return;
      for (const Node& o : pareto[key].Elements()) {
        const size_t i = add_output(o);  // an objective is an output column too
        if (!seen.insert(i).second) o.FailWith("this output is already an objective");
        into.push_back(i);
      }
    };
    objectives("minimize", s.minimize);
    objectives("maximize", s.maximize);
    if (s.minimize.empty() && s.maximize.empty())
      pareto.Fail("at least one output to minimize or maximize");
  }
  s.case_outputs = root.BoolOr("case_outputs", false);
  return s;
}

json CaseStudy(const Sweep& s, const std::vector<json>& inputs) {
  json study = s.base;
  for (size_t d = 0; d < s.vary.size(); ++d) study[Pointer(s.vary[d].path)] = inputs[d];
  return study;
}

json CaseRecord::ToJson() const {
  return {{"case", index}, {"status", status}, {"message", message}, {"outputs", outputs}};
}

CaseRecord CaseRecord::FromJson(const json& j) {
  CaseRecord r;
  r.index = j.at("case").get<size_t>();
  r.status = j.at("status").get<std::string>();
  r.message = j.at("message").get<std::string>();
  r.outputs = j.at("outputs").get<std::vector<json>>();
  return r;
}

CaseRecord RunCase(const Sweep& s, size_t index, const std::vector<json>& inputs,
                   const RunContext& ctx, Outputs* files) {
  CaseRecord r;
  r.index = index;
  r.outputs.assign(s.outputs.size(), json());
  RunContext c = ctx;
  c.study_file = s.study_file;
  c.quiet = true;  // the sweep shows its own progress; the cases' lines would interleave
  try {
    Outputs out = RunStudy(CaseStudy(s, inputs), c);
    r.status = out.incomplete().empty() ? "ok" : "incomplete";
    r.message = out.incomplete();
    const json result = out.result() ? *out.result() : json();
    for (size_t k = 0; k < s.outputs.size(); ++k) {
      const Pointer p(s.outputs[k].path);
      if (!result.contains(p)) continue;
      const json& v = result.at(p);
      r.outputs[k] = v.is_structured() ? json(v.dump()) : v;
    }
    if (files) *files = std::move(out);
  } catch (const StudyError& e) {
    r.status = "error";
    r.message = e.what();
  } catch (const std::bad_alloc&) {
    r.status = "failed";
    r.message = "out of memory";
  } catch (const std::exception& e) {
    r.status = "failed";
    r.message = std::string("internal error (a camopt defect; please report it): ") + e.what();
  }
  return r;
}

std::string CasesCsv(const Sweep& s, const std::vector<std::vector<json>>& cases,
                     const std::vector<CaseRecord>& records) {
  std::ostringstream os;
  os << "case";
  for (const Variation& v : s.vary) os << "," << CsvText(v.path);
  os << ",status";
  for (const OutputColumn& o : s.outputs) os << "," << CsvText(o.path);
  os << ",message\n";
  std::vector<const CaseRecord*> sorted;
  for (const CaseRecord& r : records) sorted.push_back(&r);
  std::sort(sorted.begin(), sorted.end(), [](auto* a, auto* b) { return a->index < b->index; });
  for (const CaseRecord* r : sorted) {
    os << r->index;
    for (const json& x : cases[r->index]) os << "," << CsvCell(x);
    os << "," << r->status;
    for (const json& x : r->outputs) os << "," << CsvCell(x);
    os << "," << CsvText(r->message) << "\n";
  }
  return os.str();
}

namespace {

std::mutex& HintMutex() {
  static std::mutex m;
  return m;
}
std::string& Hint() {
  static std::string hint;
  return hint;
}
void SetInterruptHint(std::string hint) {
  const std::lock_guard<std::mutex> lock(HintMutex());
  Hint() = std::move(hint);
}

// Runs `pending` cases on `jobs` threads; each finished record goes to the checkpoint (and its
// files to cases/NNNN) before it counts as done.
std::vector<CaseRecord> RunPool(const Sweep& s, const std::vector<std::vector<json>>& cases,
                                const std::vector<size_t>& pending, int jobs, const RunContext& ctx,
                                Checkpoint& checkpoint, const fs::path& partial,
                                const std::string& label, bool quiet) {
  std::vector<CaseRecord> records(pending.size());
  std::atomic<size_t> next{0};
  std::mutex m;
  std::condition_variable cv;
  size_t finished = 0, not_ok = 0;
  std::exception_ptr fatal;
  auto worker = [&] {
    while (true) {
      const size_t k = next.fetch_add(1);
      if (k >= pending.size()) return;
      const size_t i = pending[k];
      try {
        Outputs files;
        CaseRecord r = RunCase(s, i, cases[i], ctx, s.case_outputs ? &files : nullptr);
        if (s.case_outputs && !files.files().empty()) {
          OutputFolder folder((partial / "cases" / CaseFolderName(i, cases.size())).string());
          folder.Commit(files);
        }
        checkpoint.Append(r);
        const std::lock_guard<std::mutex> lock(m);
        not_ok += r.status != "ok";
        records[k] = std::move(r);
        ++finished;
      } catch (...) {  // the checkpoint or a case folder cannot be written, or a cancellation
                       // (StudyCancelled passes RunCase's handlers): stop the sweep
        const std::lock_guard<std::mutex> lock(m);
        if (!fatal) fatal = std::current_exception();
        next = pending.size();
      }
      cv.notify_one();
    }
  };
  std::vector<std::thread> threads;
  const int n = std::max(1, std::min<int>(jobs, static_cast<int>(pending.size())));
  for (int t = 0; t < n && !pending.empty(); ++t) threads.emplace_back(worker);
  try {
    Progress progress(label, quiet);
    std::unique_lock<std::mutex> lock(m);
    while (finished < pending.size() && !fatal) {
      cv.wait_for(lock, std::chrono::milliseconds(200));
      const size_t f = finished, bad = not_ok;
      lock.unlock();
      progress.Update(double(f) / double(pending.size()),
                      std::to_string(f) + "/" + std::to_string(pending.size()) + " cases" +
                          (bad ? ", " + std::to_string(bad) + " not ok" : ""));
      lock.lock();
    }
  } catch (...) {  // a cancellation (Progress::Update): no new case starts, the running ones stop
    const std::lock_guard<std::mutex> lock(m);
    if (!fatal) fatal = std::current_exception();
    next = pending.size();
  }
  for (auto& t : threads) t.join();  // never left joinable: the pool's threads end before it does
  if (fatal) std::rethrow_exception(fatal);
  return records;
}

int DefaultJobs(int local_ranks) {
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  return std::max(1, static_cast<int>(cores) / std::max(1, local_ranks));
}

// The merged folder: written into the partial folder, which then replaces --out in one rename.
void WriteMerged(const Sweep& s, const std::vector<std::vector<json>>& cases,
                 std::vector<CaseRecord> records, const fs::path& partial, const fs::path& out,
                 size_t& not_ok_count, std::string& not_ok_text, std::string& summary_text) {
  std::sort(records.begin(), records.end(), [](const auto& a, const auto& b) { return a.index < b.index; });
  Outputs outputs;
  outputs.Add("cases.csv", CasesCsv(s, cases, records));
  json summary = {{"sweep", s.name}, {"design", s.design}, {"cases", cases.size()}};
  std::map<std::string, size_t> counts = {{"ok", 0}, {"incomplete", 0}, {"error", 0}, {"failed", 0}};
  json not_ok = json::array();
  for (const CaseRecord& r : records) {
    ++counts[r.status];
    if (r.status == "ok") continue;
    not_ok.push_back({{"case", r.index}, {"status", r.status}, {"message", r.message}});
    if (not_ok_count < 10)
      not_ok_text += "  case " + std::to_string(r.index) + " (" + r.status + "): " + r.message + "\n";
    ++not_ok_count;
  }
  summary["status_counts"] = counts;
  summary["verdict"] = SweepVerdict(records);
  summary["cases_not_ok"] = not_ok;
  json vary = json::array(), outs = json::array();
  for (const Variation& v : s.vary) vary.push_back(v.path);
  for (const OutputColumn& o : s.outputs) outs.push_back(o.path);
  summary["vary"] = vary;
  summary["outputs"] = outs;
  const std::vector<size_t> front = ParetoFront(s, records);
  if (!s.minimize.empty() || !s.maximize.empty()) {
    std::vector<CaseRecord> front_records;
    json front_cases = json::array();
    for (size_t i : front) {
      front_records.push_back(records[i]);
      front_cases.push_back(records[i].index);
    }
    outputs.Add("pareto.csv", CasesCsv(s, cases, front_records));
    summary["pareto_front_cases"] = front_cases;
  }
  const auto plots = ParetoPlots(s, records, front);
  for (const auto& [file, svg] : plots) outputs.Add(file, svg);
  const auto output_plots = OutputPlots(s, cases, records);
  for (const auto& [file, svg] : output_plots) outputs.Add(file, svg);
  outputs.Add("report.html", SweepHtml(s, cases, records, front, plots, output_plots));
  summary_text = SweepSummary(s, records, front, out.string());
  outputs.AddJson("result.json", summary);
  // The merged files first: when they cannot be written (a full disk) the checkpoints stay and
  // --resume finds every case done. Removing the checkpoints and the rename need no space.
  WriteFilesInto(partial.string(), outputs);
  // The lists that make this folder the next sweep's to replace (studies/study.h, NotReplaceable):
  // the merged files and cases/, whose list names the case folders (each with its run's own list).
  std::vector<std::string> manifest = ManifestEntries(outputs);
  std::error_code ec;
  if (fs::is_directory(partial / "cases", ec)) {
    std::vector<std::string> case_folders;
    for (const auto& e : fs::directory_iterator(partial / "cases", ec))
      if (e.is_directory(ec)) case_folders.push_back(e.path().filename().string() + "/");
    std::sort(case_folders.begin(), case_folders.end());
    WriteManifest((partial / "cases").string(), case_folders);
    manifest.push_back("cases/");
  }
  WriteManifest(partial.string(), manifest);
  // Checked again at the swap: a file added to --out while the sweep ran is the user's.
  struct stat st {};
  if (lstat(out.c_str(), &st) == 0) {
    const std::string why = S_ISDIR(st.st_mode) ? NotReplaceable(out) : "it is no longer a folder";
    if (!why.empty())
      throw StudyError("--out " + out.string() + ": the folder changed while the sweep ran (" + why +
                       "); nothing was replaced: the sweep's results are in " + partial.string());
  }
  RemoveCheckpoints(partial);
  MoveFolderIn(partial.string(), out.string());
}

int Run(const Options& o, World& world) {
  const double factor = std::min(o.max_work_factor, 1e3);
  // The file cap of this sweep's factor while it runs, the previous one after.
  struct FileCap {
    size_t saved = CurrentInputLimits().max_file_bytes;
    explicit FileCap(double f) { CurrentInputLimits().max_file_bytes = FileBytesForWorkFactor(f); }
    ~FileCap() { CurrentInputLimits().max_file_bytes = saved; }
  } file_cap(factor);
  Sweep s;
  std::vector<std::vector<json>> cases;
  fs::path out, partial;
  try {
    CheckWorkFactor(o.max_work_factor);
    s = o.doc ? ParseJson(*o.doc, o.file, 1e6 * factor) : Parse(o.file, 1e6 * factor);
    if (o.case_outputs) s.case_outputs = true;
    cases = Cases(s);
    if (o.dry_run) {
      std::cout << cases.size() << " cases\n";
      return 0;
    }
    out = OutFolderPath(o.out);
    partial = PartialFolder(out);
    CheckReplaceable(out, o.out);
    if (!o.doc) CheckNotInside(o.file, out.string(), "sweep file");
    if (s.study_file != o.file) CheckNotInside(s.study_file, out.string(), "base study");
  } catch (const StudyError& e) {
    std::cerr << "camopt: error: " << e.what() << "\n";
    return 2;
  }

  std::string why;
  if (!world.Start(why)) {
    std::cerr << "camopt: error: " << why << "\n";
    return 2;
  }
  const std::string header = CheckpointHeader(s, cases);
  const std::string label =
      "sweep " + s.name + (world.size() > 1 ? " (rank " + std::to_string(world.rank()) + " of " +
                                                  std::to_string(world.size()) + ")"
                                            : "");

  // Rank 0 prepares the partial folder and reads what an earlier run finished, holding a lock
  // beside --out for the whole sweep: a second sweep into the same folder would delete the
  // first one's partial folder.
  std::map<size_t, CaseRecord> done;
  int status = 0;
  std::string message;
  SweepLock lock;
  if (world.rank() == 0) {
    try {
      lock.Take(out, o.out);
      done = OpenPartialFolder(partial, o.out, s, header, cases.size(), o.resume, o.quiet);
      if (o.resume && !done.empty() && !o.quiet)
        std::cerr << "camopt: resuming: " << done.size() << " of " << cases.size()
                  << " cases already done\n";
    } catch (const StudyError& e) {
      status = 2;
      message = e.what();
    }
  }
  status = world.BroadcastInt(status);
  if (status != 0) {
    if (world.rank() == 0) std::cerr << "camopt: error: " << message << "\n";
    world.Finish();
    return status;
  }
  std::vector<uint64_t> done_list;
  for (const auto& [i, r] : done) done_list.push_back(i);
  done_list = world.BroadcastIndices(done_list);

  // This rank's cases: round-robin by case number, skipping the finished ones.
  std::vector<size_t> pending;
  {
    size_t d = 0;
    std::sort(done_list.begin(), done_list.end());
    for (size_t i = 0; i < cases.size(); ++i) {
      while (d < done_list.size() && done_list[d] < i) ++d;
      if (d < done_list.size() && done_list[d] == i) continue;
      if (static_cast<int>(i % static_cast<size_t>(world.size())) == world.rank()) pending.push_back(i);
    }
  }

  if (world.rank() == 0) {
    std::string command = "camopt sweep " + o.file + " --out " + o.out;
    if (o.case_outputs) command += " --case-outputs";
    SetInterruptHint("the finished cases are kept in " + partial.string() + "; `" + command +
                     " --resume` runs only the others");
  }
  RunContext ctx;
  ctx.quiet = true;
  ctx.max_work_factor = o.max_work_factor;
  const int jobs = o.jobs > 0 ? o.jobs : DefaultJobs(world.local_size());
  std::vector<CaseRecord> mine;
  try {
    std::error_code ec;
    fs::create_directories(partial / (s.case_outputs ? "cases" : ""), ec);
    Checkpoint checkpoint(partial / CheckpointName(world.rank()), header);
    const auto t0 = std::chrono::steady_clock::now();
    mine = RunPool(s, cases, pending, jobs, ctx, checkpoint, partial, label, o.quiet);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!o.quiet && world.rank() == 0)
      std::cerr << "camopt: " << label << ": " << pending.size() << " cases in " << Fmt(seconds, "%.3g")
                << " s on " << jobs << " thread" << (jobs == 1 ? "" : "s") << "\n";
  } catch (const StudyError& e) {
    std::cerr << "camopt: error: " << e.what() << "\n";
    world.Abort(2);
    return 2;
  }

  // Gather to rank 0 (in rank order), merge with the checkpointed cases, write.
  std::string text;
  for (const CaseRecord& r : mine) text += r.ToJson().dump() + "\n";
  const std::string all = world.GatherToRoot(text);
  int code = 0;
  if (world.rank() == 0) {
    // Keyed by case number: every case exactly once, whatever ran where.
    std::istringstream gathered(all);
    std::string line;
    while (std::getline(gathered, line))
      if (!line.empty()) {
        CaseRecord r = CaseRecord::FromJson(json::parse(line));
        done.emplace(r.index, std::move(r));
      }
    std::vector<CaseRecord> records;
    for (auto& [i, r] : done) records.push_back(std::move(r));
    size_t not_ok = 0;
    std::string not_ok_text, summary_text;
    try {
      if (records.size() != cases.size())
        throw std::runtime_error("the ranks returned " + std::to_string(records.size()) + " of " +
                                 std::to_string(cases.size()) + " cases");
      WriteMerged(s, cases, std::move(records), partial, out, not_ok, not_ok_text, summary_text);
      if (o.summary) std::cout << summary_text << std::flush;
      if (not_ok > 0) {
        if (o.summary)
          std::cerr << "camopt: sweep finished; " << not_ok << " of " << cases.size()
                    << " cases are not ok (see cases.csv):\n"
                    << not_ok_text << (not_ok > 10 ? "  ...\n" : "");
        code = 3;
      }
      if (!o.quiet) std::cerr << "camopt: results written to " << out.string() << "\n";
    } catch (const StudyError& e) {
      std::cerr << "camopt: error: " << e.what() << "\n";
      code = 2;
    }
  }
  code = world.BroadcastInt(code);
  world.Finish();
  return code;
}

}  // namespace

std::string InterruptHint() {
  const std::lock_guard<std::mutex> lock(HintMutex());
  return Hint();
}

int RunCommand(const Options& options) {
  World world;
  int code = 1;
  try {
    return Run(options, world);
  } catch (const StudyError& e) {
    std::cerr << "camopt: error: " << e.what() << "\n";
    code = 2;
  } catch (const std::bad_alloc&) {
    std::cerr << "camopt: error: " << options.file << ": out of memory\n";
  } catch (const std::exception& e) {
    std::cerr << "camopt: internal error while running the sweep " << options.file << ": " << e.what()
              << " (a camopt defect; please report it with the sweep file)\n";
  }
  if (world.size() > 1) world.Abort(code);  // the other ranks may be waiting for this one
  return code;
}

}  // namespace camopt::studies::sweep

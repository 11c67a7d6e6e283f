// `camopt run STUDY --convergence` (studies/convergence.h).
#include "studies/convergence.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>

#include "studies/format.h"
#include "studies/kind.h"
#include "studies/report.h"
#include "studies/writers.h"
#include "studies/archive.h"

namespace camopt::studies {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
using json = nlohmann::json;

// value × factor, element by element for an array of numbers; whole numbers rounded.
json Scale(const json& value, double factor, bool integer) {
  if (value.is_array()) {
    json out = json::array();
    for (const json& e : value) out.push_back(Scale(e, factor, integer));
    return out;
  }
  const double v = value.get<double>() * factor;
  if (integer) return json(static_cast<long long>(std::llround(v)));
  return json(v);
}

std::string Show(const json& value) {
  if (value.is_array()) {
    std::string s;
    for (const json& e : value) s += (s.empty() ? "" : "×") + Show(e);
    return s;
  }
  if (value.is_number_integer()) return std::to_string(value.get<long long>());
  if (value.is_number()) return Format(value.get<double>(), 4);
  return value.dump();
}

// A JSON pointer as a file-name part: "/input_cam/max_force" → "input_cam.max_force".
std::string FileNamePart(const std::string& pointer) {
  std::string s;
  for (char c : pointer.substr(pointer.empty() ? 0 : 1)) s += c == '/' ? '.' : c;
  return s;
}

struct Ran {
  bool ok = false;
  std::string skipped;     // why not run
  std::string incomplete;  // ran, result not what was asked (exit 3 of a normal run)
  double seconds = 0;
  std::vector<double> values;  // per headline, NaN when absent
  Outputs outputs;
};

std::vector<double> HeadlineValues(const Outputs& outputs, const std::vector<std::string>& headlines) {
  static const json kNone;
  const json& result = outputs.result() ? *outputs.result() : kNone;
  std::vector<double> values;
  for (const std::string& h : headlines) {
    double v = kNaN;
    const json::json_pointer p(h);
    if (result.is_object() && result.contains(p) && result[p].is_number()) v = result[p].get<double>();
    values.push_back(v);
  }
  return values;
}

Ran RunOne(const json& study, const RunContext& ctx, const std::vector<std::string>& headlines,
           bool rethrow) {
  Ran r;
  const auto t0 = std::chrono::steady_clock::now();
  try {
    r.outputs = RunStudy(study, ctx);
  } catch (const StudyError& e) {
    if (rethrow) throw;
    r.skipped = e.what();
    return r;
  } catch (const std::exception& e) {
    if (rethrow) throw;
    r.skipped = std::string("failed: ") + e.what();
    return r;
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.ok = true;
  r.incomplete = r.outputs.incomplete();
  r.values = HeadlineValues(r.outputs, headlines);
  return r;
}

json ValueAt(const json& study, const FidelityKnob& k, const std::string& path) {
  const json::json_pointer p(path);
  return study.contains(p) ? study[p] : k.default_value;
}

}  // namespace

ErrorEstimate EstimateKnobError(const std::vector<double>& values, size_t base, double ratio, double order) {
  ErrorEstimate e;
  e.method = "none";
  const double f0 = values[base];
  e.extrapolated = f0;
  if (!std::isfinite(f0)) return e;
  const bool finer = base + 1 < values.size() && std::isfinite(values[base + 1]);
  const bool coarser = base > 0 && std::isfinite(values[base - 1]);
  if (finer && order > 0) {
    const double rp = std::pow(ratio, order);
    const double signed_error = (f0 - values[base + 1]) * rp / (rp - 1);
    e.error = std::abs(signed_error);
    e.extrapolated = f0 - signed_error;
    e.method = "richardson";
  } else if (finer) {
    double finest = values[base + 1];
    for (size_t i = base + 1; i < values.size(); ++i)
      if (std::isfinite(values[i])) finest = values[i];
    e.error = std::abs(f0 - finest);
    e.extrapolated = finest;
    e.method = "difference_to_finest";
  } else if (coarser) {
    e.error = std::abs(values[base - 1] - f0);
    e.method = "difference_to_coarser";
  }
  if (finer && coarser) {
    const double d1 = values[base - 1] - f0, d2 = f0 - values[base + 1];
    if (d1 * d2 > 0 && std::abs(d1) > std::abs(d2))
      e.observed_order = std::log(std::abs(d1) / std::abs(d2)) / std::log(ratio);
  }
  return e;
}

ConvergenceRun RunConvergence(const json& study, const RunContext& ctx) {
  ConvergenceRun out;
  const std::string kind = study.is_object() && study.contains("study") && study["study"].is_string()
                               ? study["study"].get<std::string>()
                               : "";
  const bool talk = !ctx.quiet;
  // The study's own settings first: its errors are the study's (exit 2, 3 as a normal run).
  if (talk) std::cerr << "convergence: the study at its own settings\n";
  Fidelity fid;
  Ran own;
  own = RunOne(study, ctx, {}, /*rethrow=*/true);  // validates the file
  if (const FidelityOf* f = FindFidelity(kind)) fid = (*f)(study);
  else fid.no_knob = "the kind declares no fidelity knobs";
  own.values = HeadlineValues(own.outputs, fid.headlines);
  out.own = std::move(own.outputs);

  json report;
  report["study"] = kind;
  report["name"] = study.value("name", "");
  report["study_file"] = ctx.study_file;
  report["note"] = "each knob refined and coarsened one at a time, the others at the study's "
                   "settings; wall times are of this machine and this run (they vary); the "
                   "knobs' runs, the study's included, apply study_run.variant_overrides when "
                   "given (work that does not change the headlines)";
  report["headlines"] = fid.headlines;
  json own_values = json::object();
  for (size_t h = 0; h < fid.headlines.size(); ++h) own_values[fid.headlines[h]] = NumberOrNull(own.values[h]);
  report["study_run"] = {{"wall_time_s", own.seconds}, {"values", own_values}};
  if (fid.knobs.empty()) report["no_knob"] = fid.no_knob;

  RunContext quiet_ctx = ctx;
  quiet_ctx.quiet = true;
  const bool overrides = !fid.knobs.empty() && !fid.variant_overrides.empty();
  const size_t total_runs = 1 + 2 * fid.knobs.size() + (overrides ? 1 : 0);
  size_t run_no = 1;
  // The variants skip work that does not change the headlines (variant_overrides): the study's
  // settings are run once more that way, so that the times of one knob compare like with like.
  double study_seconds = own.seconds;
  if (overrides) {
    json variant = study;
    for (auto it = fid.variant_overrides.begin(); it != fid.variant_overrides.end(); ++it)
      variant[json::json_pointer(it.key())] = it.value();
    ++run_no;
    if (talk)
      std::cerr << "convergence: run " << run_no << "/" << total_runs << ": the study's settings without "
                << fid.variant_overrides.dump() << "\n";
    const Ran bare = RunOne(variant, quiet_ctx, fid.headlines, false);
    if (bare.ok) study_seconds = bare.seconds;
    report["study_run"]["variant_overrides"] = fid.variant_overrides;
    report["study_run"]["wall_time_s_with_overrides"] = bare.ok ? json(bare.seconds) : json(nullptr);
  }
  std::vector<double> total_error(fid.headlines.size(), 0.0);
  std::vector<bool> has_error(fid.headlines.size(), false);
  // For the plots: per headline, per knob, the (time, error) points.
  std::vector<std::vector<Series>> plot(fid.headlines.size());
  char line[512];
  std::string& table = out.table;
  table += "convergence of " + kind + (ctx.study_file.empty() ? "" : " (" + ctx.study_file + ")") + "\n";
  if (fid.knobs.empty()) table += "  no fidelity knob: " + fid.no_knob + "\n";

  json knobs = json::array();
  for (const FidelityKnob& k : fid.knobs) {
    const double ratio = k.refine > 1 ? k.refine : 1.0 / k.refine;
    // coarse, study, refined (coarse → fine).
    const double factors[3] = {1.0 / k.refine, 1.0, k.refine};
    const char* names[3] = {"coarsened", "study", "refined"};
    std::vector<Ran> runs(3);
    std::vector<json> settings(3);
    for (int s = 0; s < 3; ++s) {
      try {
        settings[s] = Scale(ValueAt(study, k, k.paths.front()), factors[s], k.integer);
      } catch (const json::exception&) {
        settings[s] = nullptr;
      }
      if (s == 1) {
        settings[s] = ValueAt(study, k, k.paths.front());
        runs[s].ok = true;
        runs[s].seconds = study_seconds;
        runs[s].values = own.values;
        runs[s].incomplete = out.own.incomplete();
        continue;
      }
      ++run_no;
      if (talk)
        std::cerr << "convergence: run " << run_no << "/" << total_runs << ": " << k.name << " = "
                  << Show(settings[s]) << " (" << names[s] << ")\n";
      json variant = study;
      try {
        for (auto it = fid.variant_overrides.begin(); it != fid.variant_overrides.end(); ++it)
          variant[json::json_pointer(it.key())] = it.value();
        for (const std::string& p : k.paths)
          variant[json::json_pointer(p)] = Scale(ValueAt(study, k, p), factors[s], k.integer);
      } catch (const json::exception&) {  // the file has something else at the knob's path
        runs[s].skipped = "the study file has no number at " + k.paths.front();
        if (talk) std::cerr << "convergence: skipped: " << runs[s].skipped << "\n";
        continue;
      }
      runs[s] = RunOne(variant, quiet_ctx, fid.headlines, false);
      if (talk && !runs[s].ok) std::cerr << "convergence: skipped: " << runs[s].skipped << "\n";
    }
    json kj;
    kj["name"] = k.name;
    kj["paths"] = k.paths;
    kj["note"] = k.note;
    kj["refine_factor"] = k.refine;
    kj["order"] = k.order > 0 ? json(k.order) : json(nullptr);
    kj["study_value"] = settings[1];
    json runs_j = json::array();
    for (int s = 0; s < 3; ++s) {
      json rj = {{"setting", names[s]}, {"value", settings[s]}};
      if (runs[s].ok) {
        rj["wall_time_s"] = runs[s].seconds;
        if (!runs[s].incomplete.empty()) rj["incomplete"] = runs[s].incomplete;
      } else {
        rj["skipped"] = runs[s].skipped;
      }
      runs_j.push_back(rj);
    }
    kj["runs"] = runs_j;

    std::snprintf(line, sizeof line, "\nknob %s (%s; refine ×%s%s)\n", k.name.c_str(), k.paths.front().c_str(),
                  Format(k.refine, 3).c_str(), k.order > 0 ? (", order " + Format(k.order, 3)).c_str() : "");
    table += line;
    std::snprintf(line, sizeof line, "  %-52s", "setting");
    table += line;
    for (int s = 0; s < 3; ++s) {
      std::snprintf(line, sizeof line, " %16s", (Show(settings[s]) + (s == 1 ? "*" : "")).c_str());
      table += line;
    }
    table += "  est. error of *\n";
    std::snprintf(line, sizeof line, "  %-52s", "wall time [s]");
    table += line;
    for (int s = 0; s < 3; ++s) {
      std::snprintf(line, sizeof line, " %16s", runs[s].ok ? Format(runs[s].seconds, 3).c_str() : "skipped");
      table += line;
    }
    table += "\n";

    json outputs = json::object();
    for (size_t h = 0; h < fid.headlines.size(); ++h) {
      std::vector<double> v(3, kNaN);
      for (int s = 0; s < 3; ++s)
        if (runs[s].ok) v[s] = runs[s].values[h];
      const ErrorEstimate e = EstimateKnobError(v, 1, ratio, k.order);
      json oj;
      oj["values"] = {NumberOrNull(v[0]), NumberOrNull(v[1]), NumberOrNull(v[2])};
      oj["method"] = e.method;
      if (e.method != "none") {
        oj["estimated_error"] = e.error;
        oj["relative_error"] = v[1] != 0 ? json(e.error / std::abs(v[1])) : json(nullptr);
        oj["extrapolated"] = e.extrapolated;
        total_error[h] += e.error;
        has_error[h] = true;
      }
      oj["observed_order"] = e.observed_order > 0 ? json(e.observed_order) : json(nullptr);
      outputs[fid.headlines[h]] = oj;
      if (!std::isfinite(v[1])) continue;
      std::snprintf(line, sizeof line, "  %-52s", fid.headlines[h].c_str());
      table += line;
      for (int s = 0; s < 3; ++s) {
        std::snprintf(line, sizeof line, " %16s", std::isfinite(v[s]) ? Format(v[s], 7).c_str() : "-");
        table += line;
      }
      table += "  " + (e.method == "none" ? std::string("-")
                                          : Format(e.error, 3) + " (" + e.method + ")") + "\n";
      // Error of each run against the best value this knob gives (its finest run, or Richardson's
      // limit): points of error against time.
      Series series{k.name, {}, {}};
      for (int s = 0; s < 3; ++s) {
        if (!std::isfinite(v[s]) || !runs[s].ok) continue;
        const double err = std::abs(v[s] - e.extrapolated);
        if (err <= 0) continue;
        series.x.push_back(runs[s].seconds);
        series.y.push_back(std::log10(err));
      }
      if (!series.x.empty()) plot[h].push_back(series);
    }
    kj["outputs"] = outputs;
    knobs.push_back(kj);
  }
  report["knobs"] = knobs;
  json totals = json::object();
  if (!fid.knobs.empty()) table += "\nestimated error of the study's settings (sum over the knobs)\n";
  for (size_t h = 0; h < fid.headlines.size(); ++h) {
    if (!has_error[h]) continue;
    const double v = own.values[h];
    totals[fid.headlines[h]] = {{"value", NumberOrNull(v)},
                                {"estimated_error", total_error[h]},
                                {"relative_error", std::isfinite(v) && v != 0 ? json(total_error[h] / std::abs(v))
                                                                              : json(nullptr)}};
    std::snprintf(line, sizeof line, "  %-52s %16s ± %s\n", fid.headlines[h].c_str(), Format(v, 7).c_str(),
                  Format(total_error[h], 3).c_str());
    table += line;
  }
  report["estimated_error"] = totals;
  json plots = json::array();
  for (size_t h = 0; h < fid.headlines.size(); ++h) {
    if (plot[h].empty()) continue;
    const std::string file = "convergence_" + FileNamePart(fid.headlines[h]) + ".svg";
    PlotOptions po;
    po.title = "Error against time: " + fid.headlines[h];
    po.x_label = "wall time of the run [s]";
    po.y_label = "log10 |value - best estimate of its knob|";
    out.own.Add(file, SvgLinePlot(plot[h], po));
    plots.push_back(file);
  }
  report["plots"] = plots;
  out.report = report;
  return out;
}

void RunConvergenceFile(const std::string& file, const std::string& out_dir, const RunContext& ctx) {
  RunContext c = ctx;
  c.study_file = file;
  const json study = LoadStudyFile(file);
  CheckNotInside(file, out_dir, "study file");
  OutputFolder folder(out_dir);  // a bad --out is reported before the work
  ConvergenceRun run = RunConvergence(study, c);
  run.own.AddJson("convergence.json", run.report);
  // report.html again, now with the convergence plots in it.
  if (study.contains("study") && study["study"].is_string()) AddReport(study["study"].get<std::string>(), study, run.own);
  folder.Commit(run.own);
  std::cout << run.table << std::flush;
  RunAnswer answer;
  answer.status = run.own.status().value_or(Status::kLimitsMet);
  answer.reason = run.own.status_reason();
  if (ExitCode(answer.status, ctx.strict) != 0) throw StudyIncomplete(answer);
}

}  // namespace camopt::studies

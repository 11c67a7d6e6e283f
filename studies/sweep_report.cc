#include "studies/sweep_report.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "studies/provenance.h"
#include "studies/report.h"
#include "studies/sweep_pareto.h"
#include "studies/writers.h"

namespace camopt::studies::sweep {

using nlohmann::json;

namespace {

std::string Kind(const Sweep& s) {
  return s.base.is_object() && s.base.contains("study") && s.base["study"].is_string()
             ? s.base["study"].get<std::string>()
             : "";
}

std::string ColumnName(const Sweep& s, size_t column) { return PlainName(Kind(s), s.outputs[column].path); }

std::string InputName(const Sweep& s, const Variation& v) { return PlainName(Kind(s), v.path); }

// A cell of the case table: numbers as the report shows them, other values as JSON.
std::string CellText(const json& v) {
  if (v.is_number()) return ReportNumber(v.get<double>());
  if (v.is_null()) return "";
  if (v.is_string()) return v.get<std::string>();
  return v.dump();
}

}  // namespace

std::vector<std::pair<std::string, std::string>> ParetoPlots(const Sweep& s, const std::vector<CaseRecord>& records,
                                                             const std::vector<size_t>& front) {
  const std::vector<size_t> objectives = ObjectiveColumns(s);
  if (objectives.empty()) return {};
  const size_t k = objectives.size();
  std::vector<double> f;
  std::vector<const CaseRecord*> ok;
  for (const CaseRecord& r : records)
    if (r.status == "ok" && Objectives(s, r, f)) ok.push_back(&r);
  auto label = [&](size_t column) {
    return ColumnName(s, column) + (Maximized(s, column) ? " (maximize)" : " (minimize)");
  };
  const bool labelled = front.size() <= 20;
  // One panel: objective a (or the case number when a is k) against objective b.
  auto panel = [&](size_t a, size_t b) {
    auto x_of = [&](const CaseRecord& r) {
      return a == k ? static_cast<double>(r.index) : r.outputs[objectives[a]].get<double>();
    };
    auto y_of = [&](const CaseRecord& r) { return r.outputs[objectives[b]].get<double>(); };
    Series all{"ok cases", {}, {}}, dots{labelled ? "Pareto front (case numbers beside)" : "Pareto front", {}, {}};
    all.markers = dots.markers = true;
    for (const CaseRecord* r : ok) {
      all.x.push_back(x_of(*r));
      all.y.push_back(y_of(*r));
    }
    std::vector<std::tuple<double, double, size_t>> points;
    for (size_t i : front) points.push_back({x_of(records[i]), y_of(records[i]), records[i].index});
    std::sort(points.begin(), points.end());
    for (const auto& [x, y, index] : points) {
      dots.x.push_back(x);
      dots.y.push_back(y);
      if (labelled) dots.point_labels.push_back(std::to_string(index));
    }
    std::vector<Series> series = {all, dots};
    if (k == 2) series.push_back({"front in order", dots.x, dots.y});
    PlotOptions o;
    o.title = s.name + ": Pareto front, " + std::to_string(front.size()) + " of " + std::to_string(ok.size()) +
              " ok cases";
    if (k > 2)
      o.title += "; objectives " + std::to_string(a + 1) + " and " + std::to_string(b + 1) + " of " +
                 std::to_string(k) + " (a front case that looks dominated here is better in another)";
    o.x_label = a == k ? "case" : label(objectives[a]);
    o.y_label = label(objectives[b]);
    return SvgLinePlot(series, o);
  };
  std::vector<std::pair<std::string, std::string>> plots;
  if (k == 1) {
    plots.push_back({"pareto.svg", panel(k, 0)});
    return plots;
  }
  // Every pair of the first six objectives (15 panels at most).
  const size_t shown = std::min<size_t>(k, 6);
  for (size_t a = 0; a < shown; ++a)
    for (size_t b = a + 1; b < shown; ++b)
      plots.push_back({a == 0 && b == 1 ? "pareto.svg"
                                        : "pareto_" + std::to_string(a + 1) + "_" + std::to_string(b + 1) + ".svg",
                       panel(a, b)});
  return plots;
}

std::vector<std::pair<std::string, std::string>> OutputPlots(const Sweep& s, const std::vector<std::vector<json>>& cases,
                                                             const std::vector<CaseRecord>& records) {
  std::vector<std::pair<std::string, std::string>> plots;
  const size_t n_in = std::min<size_t>(s.vary.size(), 4), n_out = std::min<size_t>(s.outputs.size(), 6);
  auto number = [](const json& v, double& x) {
    if (!v.is_number()) return false;
    x = v.get<double>();
    return std::isfinite(x);
  };
  for (size_t o = 0; o < n_out; ++o)
    for (size_t i = 0; i < n_in; ++i) {
      // The ok cases with a number for the input and the output; with two inputs, by the other's level.
      const bool by_level = s.vary.size() == 2;
      const size_t other = 1 - i;
      std::map<double, Series> lines;  // the other input's level → its line
      Series points{"ok cases", {}, {}};
      points.markers = true;
      for (const CaseRecord& r : records) {
        double x = 0, y = 0, level = 0;
        if (r.status != "ok" || r.index >= cases.size() || o >= r.outputs.size()) continue;
        if (!number(cases[r.index][i], x) || !number(r.outputs[o], y)) continue;
        if (by_level && number(cases[r.index][other], level)) {
          Series& line = lines[level];
          if (line.label.empty()) line.label = InputName(s, s.vary[other]) + " = " + ReportNumber(level);
          line.style = SeriesStyle::kLineAndMarkers;
          line.x.push_back(x);
          line.y.push_back(y);
        } else {
          points.x.push_back(x);
          points.y.push_back(y);
        }
      }
      std::vector<Series> series;
      for (auto& [level, line] : lines) {
        // Along x, so that the line joins neighbouring levels of this input.
        std::vector<size_t> order(line.x.size());
        for (size_t k = 0; k < order.size(); ++k) order[k] = k;
        std::sort(order.begin(), order.end(), [&x = line.x](size_t a, size_t b) { return x[a] < x[b]; });
        Series sorted{line.label, {}, {}};
        sorted.style = line.style;
        for (size_t k : order) sorted.x.push_back(line.x[k]), sorted.y.push_back(line.y[k]);
        series.push_back(sorted);
      }
      if (!points.x.empty()) series.push_back(points);
      if (series.empty()) continue;
      PlotOptions po;
      po.title = s.name + ": " + ColumnName(s, o) + " against " + InputName(s, s.vary[i]);
      po.x_label = InputName(s, s.vary[i]);
      po.y_label = ColumnName(s, o);
      plots.push_back({"outputs_" + std::to_string(o + 1) + "_vs_" + std::to_string(i + 1) + ".svg",
                       SvgLinePlot(series, po)});
    }
  return plots;
}

std::string SweepVerdict(const std::vector<CaseRecord>& records) {
  std::map<std::string, size_t> counts;
  for (const CaseRecord& r : records) ++counts[r.status];
  const size_t ok = counts["ok"];
  std::string verdict = ok == records.size()
                            ? "All " + std::to_string(records.size()) + " cases ok"
                            : std::to_string(ok) + " of " + std::to_string(records.size()) + " cases ok";
  for (const char* status : {"incomplete", "error", "failed"})
    if (counts[status] > 0) verdict += ", " + std::to_string(counts[status]) + " " + status;
  return verdict;
}

std::string SweepHtml(const Sweep& s, const std::vector<std::vector<json>>& cases,
                      const std::vector<CaseRecord>& records, const std::vector<size_t>& front,
                      const std::vector<std::pair<std::string, std::string>>& plots,
                      const std::vector<std::pair<std::string, std::string>>& output_plots) {
  std::map<std::string, size_t> counts;
  for (const CaseRecord& r : records) ++counts[r.status];
  const size_t ok = counts["ok"];
  const std::vector<size_t> objectives = ObjectiveColumns(s);
  std::ostringstream os;
  os << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
     << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
     << "<link rel=\"icon\" href=\"data:,\">\n"
     << "<title>camopt sweep: " << HtmlEscape(s.name) << "</title>\n<style>\n" << ReportStyle()
     << "\n</style>\n</head>\n<body>\n";
  os << "<h1>" << HtmlEscape(s.name) << "</h1>\n<p class=\"meta\">camopt sweep of <code>"
     << HtmlEscape(Kind(s)) << "</code> studies · camopt " << HtmlEscape(CamoptVersion()) << "</p>\n";
  const std::string verdict = SweepVerdict(records);
  os << "<div class=\"verdict " << (ok == records.size() ? "ok" : "bad") << "\">" << HtmlEscape(verdict)
     << "</div>\n";

  os << "<h2>Design</h2>\n<p>" << HtmlEscape(s.design) << ", " << cases.size() << " cases</p>\n";
  os << "<table>\n<tr><th>input</th><th>pointer</th><th>levels</th></tr>\n";
  for (const Variation& v : s.vary) {
    std::string levels;
    if (v.has_range) {
      levels = "[" + ReportNumber(v.lo) + ", " + ReportNumber(v.hi) + "]" + (v.log ? " (log)" : "") +
               (v.integer ? " (whole numbers)" : "");
    } else {
      for (const json& x : v.values) levels += (levels.empty() ? "" : ", ") + CellText(x);
    }
    os << "<tr><td>" << HtmlEscape(InputName(s, v)) << "</td><td><code>" << HtmlEscape(v.path) << "</code></td><td>"
       << HtmlEscape(levels) << "</td></tr>\n";
  }
  os << "</table>\n";

  // The table of a set of records: case, inputs, status, outputs (and message when asked).
  auto table = [&](const std::vector<const CaseRecord*>& rows, bool message) {
    os << "<table>\n<tr><th>case</th>";
    for (const Variation& v : s.vary) os << "<th>" << HtmlEscape(InputName(s, v)) << "</th>";
    os << "<th>status</th>";
    for (size_t c = 0; c < s.outputs.size(); ++c) os << "<th>" << HtmlEscape(ColumnName(s, c)) << "</th>";
    if (message) os << "<th>why</th>";
    os << "</tr>\n";
    for (const CaseRecord* r : rows) {
      os << "<tr><td class=\"n\">" << r->index << "</td>";
      for (const json& x : cases[r->index]) os << "<td class=\"n\">" << HtmlEscape(CellText(x)) << "</td>";
      os << "<td class=\"" << (r->status == "ok" ? "pass" : "fail") << "\">" << HtmlEscape(r->status) << "</td>";
      for (const json& x : r->outputs) os << "<td class=\"n\">" << HtmlEscape(CellText(x)) << "</td>";
      if (message) os << "<td>" << HtmlEscape(r->message) << "</td>";
      os << "</tr>\n";
    }
    os << "</table>\n";
  };

  if (!objectives.empty()) {
    os << "<h2>Pareto front</h2>\n<p>" << front.size() << " of " << ok
       << " ok cases are not dominated (no other ok case is at least as good in every objective and "
          "better in one) over: ";
    for (size_t i = 0; i < objectives.size(); ++i)
      os << (i ? "; " : "") << (Maximized(s, objectives[i]) ? "maximize " : "minimize ")
         << HtmlEscape(ColumnName(s, objectives[i]));
    os << ".</p>\n";
    std::vector<const CaseRecord*> rows;
    for (size_t i : front) rows.push_back(&records[i]);
    table(rows, false);
    os << "<div class=\"plots\">\n";
    for (const auto& [file, svg] : plots)
      os << "<figure>\n" << svg << "<figcaption>" << HtmlEscape(file) << "</figcaption>\n</figure>\n";
    os << "</div>\n";
  }

  if (!output_plots.empty()) {
    os << "<h2>Outputs against the inputs</h2>\n<p>Each output over the ok cases as each varied input "
          "changes"
       << (s.vary.size() == 2 ? ", one line per level of the other input" : "") << ".</p>\n<div class=\"plots\">\n";
    for (const auto& [file, svg] : output_plots)
      os << "<figure>\n" << svg << "<figcaption>" << HtmlEscape(file) << "</figcaption>\n</figure>\n";
    os << "</div>\n";
  }

  std::vector<const CaseRecord*> not_ok;
  for (const CaseRecord& r : records)
    if (r.status != "ok") not_ok.push_back(&r);
  os << "<h2>Cases not ok</h2>\n";
  if (not_ok.empty()) os << "<p>None.</p>\n";
  else table(not_ok, true);

  constexpr size_t kMaxRows = 2000;
  os << "<h2>Every case</h2>\n";
  std::vector<const CaseRecord*> all;
  for (size_t i = 0; i < std::min(records.size(), kMaxRows); ++i) all.push_back(&records[i]);
  table(all, false);
  if (records.size() > kMaxRows)
    os << "<p>The first " << kMaxRows << " of " << records.size() << " cases; every case is in cases.csv.</p>\n";

  os << "<h2>Files of this sweep</h2>\n<ul>\n<li><code>cases.csv</code> (every case)</li>\n";
  if (!objectives.empty()) {
    os << "<li><code>pareto.csv</code> (the front's cases)</li>\n";
    for (const auto& [file, svg] : plots) os << "<li><code>" << HtmlEscape(file) << "</code></li>\n";
  }
  for (const auto& [file, svg] : output_plots) os << "<li><code>" << HtmlEscape(file) << "</code></li>\n";
  os << "<li><code>result.json</code> (counts, cases not ok, the front's case numbers)</li>\n"
     << "<li><code>report.html</code> (this page)</li>\n</ul>\n</body>\n</html>\n";
  return os.str();
}

std::string SweepSummary(const Sweep& s, const std::vector<CaseRecord>& records, const std::vector<size_t>& front,
                         const std::string& out_dir) {
  std::map<std::string, size_t> counts;
  for (const CaseRecord& r : records) ++counts[r.status];
  std::ostringstream os;
  os << "camopt: sweep \"" << s.name << "\": " << records.size() << " cases, " << counts["ok"] << " ok";
  for (const char* status : {"incomplete", "error", "failed"})
    if (counts[status] > 0) os << ", " << counts[status] << " " << status;
  os << "\n";
  const std::vector<size_t> objectives = ObjectiveColumns(s);
  if (!objectives.empty()) {
    os << "  Pareto front: " << front.size() << " of " << counts["ok"] << " ok cases";
    if (!front.empty()) {
      os << ": ";
      for (size_t i = 0; i < std::min<size_t>(front.size(), 20); ++i)
        os << (i ? ", " : "") << records[front[i]].index;
      if (front.size() > 20) os << ", …";
    }
    os << "\n";
  }
  // The best case of each objective, or each output's range over the ok cases.
  const std::vector<size_t> columns = [&] {
    if (!objectives.empty()) return objectives;
    std::vector<size_t> c;
    for (size_t i = 0; i < std::min<size_t>(s.outputs.size(), 8); ++i) c.push_back(i);
    return c;
  }();
  for (size_t c : columns) {
    const CaseRecord *low = nullptr, *high = nullptr;
    for (const CaseRecord& r : records) {
      if (r.status != "ok" || !r.outputs[c].is_number()) continue;
      const double v = r.outputs[c].get<double>();
      if (!low || v < low->outputs[c].get<double>()) low = &r;
      if (!high || v > high->outputs[c].get<double>()) high = &r;
    }
    if (!low) continue;
    auto at = [](const CaseRecord* r, size_t col) {
      return ReportNumber(r->outputs[col].get<double>()) + " (case " + std::to_string(r->index) + ")";
    };
    if (!objectives.empty())
      os << "  " << (Maximized(s, c) ? "maximize " : "minimize ") << ColumnName(s, c) << ": best "
         << at(Maximized(s, c) ? high : low, c) << "\n";
    else
      os << "  " << ColumnName(s, c) << ": " << at(low, c) << " to " << at(high, c) << "\n";
  }
  os << "  details: " << out_dir << "/report.html\n";
  return os.str();
}

}  // namespace camopt::studies::sweep

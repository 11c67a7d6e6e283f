#include "studies/report.h"
#include "studies/kind.h"
#include "studies/writers.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>
#include <utility>

namespace camopt::studies {

namespace {

std::string Html(const std::string& s) { return XmlText(s); }

// A number as a designer reads it: integers exactly, others to 6 significant digits.
std::string Number(double v) {
  char buf[40];
  if (std::abs(v) < 1e12 && v == std::round(v)) std::snprintf(buf, sizeof buf, "%.0f", v);
  else std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

std::string Value(const nlohmann::json& v) {
  if (v.is_number()) return Number(v.get<double>());
  if (v.is_string()) return v.get<std::string>();
  if (v.is_array() && std::all_of(v.begin(), v.end(), [](const nlohmann::json& e) { return e.is_string(); })) {
    std::string joined;
    for (const auto& e : v) joined += (joined.empty() ? "" : "; ") + e.get<std::string>();
    return joined.empty() ? "none" : joined;
  }
  return v.dump();
}

// An error estimate: two significant digits are all it carries.
std::string Error(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.2g", v);
  return buf;
}

// The SVG with a viewBox (so that the page can scale it without cropping) and its width in px.
std::pair<std::string, double> Scalable(const std::string& svg) {
  const size_t open = svg.find("<svg");
  const size_t close = svg.find('>', open);
  if (open == std::string::npos || close == std::string::npos) return {svg, 0.0};
  const std::string tag = svg.substr(open, close - open);
  auto attribute = [&](const std::string& name) {
    const size_t at = tag.find(" " + name + "=\"");
    return at == std::string::npos ? std::string() : tag.substr(at + name.size() + 3,
                                                                 tag.find('"', at + name.size() + 3) - (at + name.size() + 3));
  };
  const std::string w = attribute("width"), h = attribute("height");
  const double width = std::atof(w.c_str());
  if (!attribute("viewBox").empty() || w.empty() || h.empty()) return {svg, width};
  std::string out = svg;
  out.insert(open + 4, " viewBox=\"0 0 " + w + " " + h + "\"");
  return {out, width};
}

const nlohmann::json* At(const nlohmann::json& j, const std::string& pointer) {
  if (pointer.empty()) return nullptr;
  try {
    const nlohmann::json::json_pointer p(pointer);
    if (!j.contains(p)) return nullptr;
    const nlohmann::json& v = j.at(p);
    return v.is_null() ? nullptr : &v;
  } catch (const nlohmann::json::exception&) {
    return nullptr;
  }
}

// Leaves of a JSON value as (path, value) rows; arrays of plain values stay on one row.
void Flatten(const nlohmann::json& j, const std::string& path,
             std::vector<std::pair<std::string, std::string>>& rows) {
  const bool plain_array = j.is_array() && std::none_of(j.begin(), j.end(), [](const nlohmann::json& e) {
                             return e.is_structured();
                           });
  if (j.is_object() && !j.empty()) {
    for (const auto& [k, v] : j.items()) Flatten(v, path + "/" + k, rows);
  } else if (j.is_array() && !plain_array) {
    for (size_t i = 0; i < j.size(); ++i) Flatten(j[i], path + "/" + std::to_string(i), rows);
  } else {
    rows.emplace_back(path.empty() ? "/" : path, j.is_string() ? j.get<std::string>() : j.dump());
  }
}

const char* kStyle = R"(body{font-family:sans-serif;margin:24px auto;max-width:1200px;color:#222;padding:0 16px}
h1{font-size:22px;margin-bottom:4px}h2{font-size:17px;border-bottom:1px solid #ccc;padding-bottom:3px;margin-top:28px}
.meta{color:#555;font-size:13px}.verdict{padding:8px 12px;margin:12px 0;font-weight:bold;border-radius:4px}
.ok{background:#e3f4e3;color:#185c18}.partial{background:#fdf1d6;color:#6b4a00}.bad{background:#fbe3e3;color:#8c1a1a}.info{background:#eef2f8;color:#234}
table{border-collapse:collapse;font-size:14px}td,th{border:1px solid #ccc;padding:3px 8px;text-align:left}
th{background:#f3f3f3}td.n{text-align:right;font-variant-numeric:tabular-nums}
td.pass{color:#185c18;font-weight:bold}td.fail{color:#8c1a1a;font-weight:bold;background:#fbe3e3}
.plots{display:grid;grid-template-columns:repeat(auto-fill,minmax(500px,1fr));gap:12px}
figure{margin:0;border:1px solid #ddd;padding:6px;overflow-x:auto}figure.wide{grid-column:1/-1}figcaption{font-size:12px;color:#555}
figure svg{max-width:100%;height:auto}pre{font-size:12px;background:#f7f7f7;padding:8px;overflow-x:auto}
code{font-size:13px}ul.w li{color:#8a5300})";

// A number of a row, or NaN.
double RowNumber(const nlohmann::json& row, const char* key) {
  return row.contains(key) && row[key].is_number() ? row[key].get<double>() : NAN;
}

std::string Cell(double v, const std::string& unit = "") {
  return std::isfinite(v) ? Number(v) + (unit.empty() ? "" : " " + unit) : "";
}

// The life table as HTML: element, kind, equivalent load, C, C0, s0, L10h, pass/fail.
void LifeTableHtml(std::ostringstream& os, const std::string& pointer, const nlohmann::json& life) {
  const nlohmann::json& table = life["table"];
  const double limit = life.contains("life_h") && life["life_h"].is_number() ? life["life_h"].get<double>() : NAN;
  os << "<p class=\"meta\"><code>" << Html(pointer) << "/table</code>"
     << (std::isfinite(limit) ? " · limit <code>life_h</code> = " + Number(limit) + " h" : std::string(" · no life limit"))
     << "</p>\n<table>\n<tr><th>element</th><th>kind</th><th>equivalent load</th><th>C</th><th>C0</th><th>s0</th>"
     << "<th>L10h</th><th>status</th></tr>\n";
  for (const nlohmann::json& row : table) {
    if (!row.is_object()) continue;
    const std::string element = row.contains("element") ? Value(row["element"]) : "";
    const std::string kind = row.contains("kind") ? Value(row["kind"]) : "";
    // A cam track's contact life is rated by a pressure (material.contact_fatigue), a bearing's by a load.
    std::string load = Cell(RowNumber(row, "equivalent_load_N"), "N");
    if (load.empty() && std::isfinite(RowNumber(row, "equivalent_pressure_MPa")))
      load = "p_eq " + Cell(RowNumber(row, "equivalent_pressure_MPa"), "MPa");
    std::string c = Cell(RowNumber(row, "dynamic_rating_N"), "N");
    if (c.empty() && std::isfinite(RowNumber(row, "reference_pressure_MPa")))
      c = "p_ref " + Cell(RowNumber(row, "reference_pressure_MPa"), "MPa");
    const bool has_life = row.contains("L10h") && row["L10h"].is_number();
    const std::string l10 = has_life ? Cell(row["L10h"].get<double>(), "h") : "no load";
    std::string status, cls;
    if (row.contains("pass") && row["pass"].is_boolean()) {
      const bool ok = row["pass"].get<bool>();
      status = ok ? "pass" : "FAIL";
      cls = ok ? "pass" : "fail";
    }
    os << "<tr><td>" << Html(element) << "</td><td>" << Html(kind) << "</td><td class=\"n\">" << Html(load)
       << "</td><td class=\"n\">" << Html(c) << "</td><td class=\"n\">"
       << Html(Cell(RowNumber(row, "static_rating_N"), "N")) << "</td><td class=\"n\">"
       << Html(Cell(RowNumber(row, "s0"))) << "</td><td class=\"n\">" << Html(l10) << "</td><td class=\"" << cls
       << "\">" << status << "</td></tr>\n";
  }
  os << "</table>\n";
}

}  // namespace

std::vector<std::pair<std::string, const nlohmann::json*>> LifeTables(const nlohmann::json& result) {
  std::vector<std::pair<std::string, const nlohmann::json*>> out;
  const auto is_life = [](const nlohmann::json& v) {
    return v.is_object() && v.contains("table") && v["table"].is_array() && !v["table"].empty();
  };
  if (!result.is_object()) return out;
  if (result.contains("life") && is_life(result["life"])) out.emplace_back("/life", &result["life"]);
  for (const auto& [key, v] : result.items())
    if (v.is_object() && v.contains("life") && is_life(v["life"])) out.emplace_back("/" + key + "/life", &v["life"]);
  return out;
}

std::string SvgLifeBars(const nlohmann::json& table, double limit_h, const std::string& title) {
  struct LifeBar {
    std::string label;
    double hours;  // NaN: no load (infinite life)
    bool fails;
  };
  std::vector<LifeBar> bars;
  double lo = INFINITY, hi = -INFINITY;
  for (const nlohmann::json& row : table) {
    if (!row.is_object()) continue;
    const double h = row.contains("L10h") && row["L10h"].is_number() ? row["L10h"].get<double>() : NAN;
    const bool fails = row.contains("pass") && row["pass"].is_boolean() && !row["pass"].get<bool>();
    bars.push_back({row.contains("element") ? Value(row["element"]) : "", h > 0 ? h : NAN, fails});
    if (h > 0 && std::isfinite(h)) lo = std::min(lo, h), hi = std::max(hi, h);
  }
  if (limit_h > 0 && std::isfinite(limit_h)) lo = std::min(lo, limit_h), hi = std::max(hi, limit_h);
  if (!std::isfinite(lo)) lo = 1, hi = 10;
  // Whole decades around the data, at least one.
  double d0 = std::floor(std::log10(lo)), d1 = std::ceil(std::log10(hi));
  if (d1 <= d0) d1 = d0 + 1;
  const double left = 190, right = 30, top = 52, row_h = 26, width = 720;
  const double plot_w = width - left - right, height = top + row_h * bars.size() + 50;
  const auto x_of = [&](double h) { return left + plot_w * (std::log10(h) - d0) / (d1 - d0); };
  std::ostringstream os;
  char buf[400];
  os << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << Number(width) << "\" height=\"" << Number(height)
     << "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  os << "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
  os << "<text x=\"" << Number(width / 2) << "\" y=\"18\" text-anchor=\"middle\" font-size=\"14\">" << Html(title)
     << "</text>\n";
  const double bottom = top + row_h * bars.size();
  for (int d = int(d0); d <= int(d1); ++d) {
    const double x = x_of(std::pow(10.0, d));
    std::snprintf(buf, sizeof buf,
                  "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke=\"#dddddd\"/>\n"
                  "<text x=\"%.2f\" y=\"%.2f\" text-anchor=\"middle\">1e%d</text>\n",
                  x, top - 4, x, bottom, x, bottom + 16, d);
    os << buf;
  }
  std::snprintf(buf, sizeof buf, "<text x=\"%.2f\" y=\"%.2f\" text-anchor=\"middle\">L10h [h] (log scale)</text>\n",
                left + plot_w / 2, bottom + 36);
  os << buf;
  for (size_t i = 0; i < bars.size(); ++i) {
    const LifeBar& b = bars[i];
    const double y = top + row_h * i;
    std::snprintf(buf, sizeof buf, "<text x=\"%.2f\" y=\"%.2f\" text-anchor=\"end\">", left - 6, y + row_h * 0.65);
    os << buf << Html(b.label) << "</text>\n";
    if (std::isnan(b.hours)) {
      std::snprintf(buf, sizeof buf, "<text x=\"%.2f\" y=\"%.2f\">no load</text>\n", left + 4, y + row_h * 0.65);
      os << buf;
      continue;
    }
    const double x = std::max(left, std::min(left + plot_w, x_of(b.hours)));
    std::snprintf(buf, sizeof buf,
                  "<rect x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\" fill=\"%s\"/>\n"
                  "<text x=\"%.2f\" y=\"%.2f\">",
                  left, y + 4, std::max(x - left, 0.5), row_h - 8, b.fails ? "#d62728" : "#1f77b4",
                  std::min(x + 4, left + plot_w - 60), y + row_h * 0.65);
    os << buf << Html(Number(b.hours)) << " h</text>\n";
  }
  if (limit_h > 0 && std::isfinite(limit_h)) {
    const double x = x_of(limit_h);
    std::snprintf(buf, sizeof buf,
                  "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke=\"#000000\" stroke-width=\"1.5\" "
                  "stroke-dasharray=\"6,4\"/>\n<text x=\"%.2f\" y=\"%.2f\" text-anchor=\"middle\">",
                  x, top - 4, x, bottom, x, top - 8);
    os << buf << "limit life_h = " << Html(Number(limit_h)) << " h</text>\n";
  }
  std::snprintf(buf, sizeof buf, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke=\"#000000\"/>\n", left,
                top - 4, left, bottom);
  os << buf << "</svg>\n";
  return os.str();
}

const std::vector<Headline>* FindHeadlines(const std::string& kind) {
  const KindDescriptor* k = FindKind(kind);
  return k && k->report ? &*k->report : nullptr;
}

HeadlineTable EvaluateHeadlines(const std::string& kind, const nlohmann::json& study, const nlohmann::json& result) {
  return EvaluateHeadlines(FindHeadlines(kind), study, result);
}

HeadlineTable EvaluateHeadlines(const std::vector<Headline>* headlines, const nlohmann::json& study,
                                const nlohmann::json& result) {
  HeadlineTable table;
  if (result.is_object() && result.contains("best") && result["best"].is_null()) {
    table.no_design = true;
    if (result.contains("notes") && result["notes"].is_array() && !result["notes"].empty() &&
        result["notes"][0].is_string())
      table.no_design_reason = result["notes"][0].get<std::string>();
  }
  if (!headlines) {
    for (const auto& [k, v] : result.items())
      if (v.is_number()) table.rows.push_back({k, Value(v), "", "", ""});
    return table;
  }
  table.registered = true;
  for (const Headline& h : *headlines) {
    const nlohmann::json* v = At(result, h.pointer);
    if (!v) continue;
    if (!h.only_with.empty() && !At(result, h.only_with)) continue;
    if (!h.not_with.empty() && At(result, h.not_with)) continue;
    const std::string unit = h.unit.empty() ? "" : " " + h.unit;
    std::string value = Value(*v);
    double error = 0;  // the value's error estimate, when the kind gives one
    const nlohmann::json* e = At(result, h.error_pointer);
    if (e && e->is_number() && v->is_number()) error = std::abs(e->get<double>());
    if (v->is_number() && std::abs(v->get<double>()) < std::max(h.resolution, error)) value = "0";
    if (e && e->is_number() && v->is_number()) value += " ± " + Error(error);
    HeadlineRow row{h.label, value + (v->is_number() ? unit : ""), "", "", ""};
    double limit = h.limit_value;
    const bool in_study = h.limit_pointer.rfind("study:", 0) == 0;
    if (const nlohmann::json* l = At(in_study ? study : result, h.limit_pointer.substr(in_study ? 6 : 0));
        l && l->is_number())
      limit = l->get<double>();
    if (v->is_number() && std::isfinite(limit)) {
      const double margin = h.upper_limit ? limit - v->get<double>() : v->get<double>() - limit;
      row.limit = (h.upper_limit ? "≤ " : "≥ ") + Number(limit) + unit;
      row.margin = Number(margin) + unit;
      // A limit holds when the value is within it plus its estimated error (the verified-optimum
      // contract, objectives/verification.h), as result.json's verification says.
      const bool holds = margin >= -error;
      row.status = holds ? "pass" : "fail";
      ++table.limits;
      if (!holds) table.exceeded.push_back(h.label);
    } else if (v->is_number() && !h.limit_pointer.empty()) {
      table.unset.push_back(h.label);  // a limit the kind considers, not set in this study
    }
    table.rows.push_back(row);
  }
  return table;
}

namespace {
std::string VerdictCore(const HeadlineTable& table, Status status, const std::string& reason) {
  if (IsVerified(status) && table.limits == 0)
    return std::string("Every limit verified by the accurate model") +
           (status == Status::kFeasibleVerified ? "; not proven optimal" + (reason.empty() ? "" : ": " + reason) : "");
  const std::string met = table.limits == 0 ? std::string("No limits to check in this study")
                          : table.limits == 1 ? std::string("The limit is met")
                                              : "All " + std::to_string(table.limits) + " limits met";
  switch (status) {
    case Status::kOptimalVerified: return met + ", verified by the accurate model";
    case Status::kFeasibleVerified:
      return met + ", verified by the accurate model; not proven optimal" + (reason.empty() ? "" : ": " + reason);
    case Status::kInfeasible: {
      std::string why = !reason.empty() ? reason : table.no_design_reason;
      // A reason that says it already ("no design meets the limits (...): ...") is not repeated.
      const std::string head = "no design meets the limits";
      if (why.size() >= head.size() && std::equal(head.begin(), head.end(), why.begin(),
                                                  [](char a, char b) { return a == std::tolower(static_cast<unsigned char>(b)); })) {
        why = why.substr(head.size());
        return "No design meets the limits" + (why.rfind(": ", 0) == 0 || why.rfind(" (", 0) == 0 ? why : why.empty() ? "" : ": " + why);
      }
      return "No design meets the limits" + (why.empty() ? std::string(" (result.json: best is null)") : ": " + why);
    }
    case Status::kNotVerifiable: return "Not verifiable" + (reason.empty() ? "" : ": " + reason);
    case Status::kNotConverged: return "Not converged" + (reason.empty() ? "" : ": " + reason);
    case Status::kLimitsMet:
    case Status::kLimitsExceeded: break;
  }
  if (table.exceeded.empty()) return met;
  std::string s = std::to_string(table.exceeded.size()) + " of " + std::to_string(table.limits) + " limits exceeded: ";
  for (size_t i = 0; i < table.exceeded.size(); ++i) s += (i ? "; " : "") + table.exceeded[i];
  return s;
}
}  // namespace

std::string VerdictLine(const HeadlineTable& table, Status status, const std::string& reason) {
  std::string line = VerdictCore(table, status, reason);
  if (!table.unset.empty() && status != Status::kInfeasible && status != Status::kNotConverged &&
      status != Status::kNotVerifiable) {
    line += "; not checked, no limit set: ";
    for (size_t i = 0; i < table.unset.size(); ++i) line += (i ? "; " : "") + table.unset[i];
  }
  return line;
}

Status StatusOfTable(const HeadlineTable& table) {
  return table.no_design ? Status::kInfeasible : table.exceeded.empty() ? Status::kLimitsMet : Status::kLimitsExceeded;
}

std::string VerdictOf(const HeadlineTable& table, const nlohmann::json& result) {
  std::optional<Status> status;
  std::string reason;
  if (result.is_object() && result.contains("status") && result["status"].is_string())
    status = StatusFromName(result["status"].get<std::string>());
  if (result.is_object() && result.contains("status_reason") && result["status_reason"].is_string())
    reason = result["status_reason"].get<std::string>();
  return VerdictLine(table, status.value_or(StatusOfTable(table)), reason);
}

std::string HtmlReport(const std::string& kind, const nlohmann::json& study, const Outputs& outputs) {
  return HtmlReport(kind, FindHeadlines(kind), study, outputs);
}

std::string HtmlReport(const std::string& kind, const std::vector<Headline>* headlines, const nlohmann::json& study,
                       const Outputs& outputs) {
  const auto& files = outputs.files();
  static const nlohmann::json kNone = nlohmann::json::object();
  const nlohmann::json& result = outputs.result() && outputs.result()->is_object() ? *outputs.result() : kNone;
  std::string name = study.is_object() && study.contains("name") && study["name"].is_string()
                         ? study["name"].get<std::string>()
                         : "";
  if (name.empty()) name = kind;

  const HeadlineTable table = EvaluateHeadlines(headlines, study, result);
  const std::vector<HeadlineRow>& rows = table.rows;
  const int limits = table.limits;

  std::vector<std::string> warnings;
  if (result.contains("warnings") && result["warnings"].is_array())
    for (const auto& w : result["warnings"]) warnings.push_back(w.is_string() ? w.get<std::string>() : w.dump());
  if (result.contains("warning") && result["warning"].is_string() && !result["warning"].get<std::string>().empty())
    warnings.push_back(result["warning"].get<std::string>());
  std::vector<std::string> notes;
  if (result.contains("notes") && result["notes"].is_array())
    for (const auto& n : result["notes"]) notes.push_back(n.is_string() ? n.get<std::string>() : n.dump());

  std::ostringstream os;
  os << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
     << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
     << "<link rel=\"icon\" href=\"data:,\">\n"
     << "<title>camopt report: " << Html(name) << "</title>\n<style>\n" << kStyle << "\n</style>\n</head>\n<body>\n";
  os << "<h1>" << Html(name) << "</h1>\n<p class=\"meta\">camopt study kind <code>" << Html(kind) << "</code>";
  if (result.contains("camopt_version")) os << " · camopt " << Html(Value(result["camopt_version"]));
  if (result.contains("study_sha256")) os << " · study SHA-256 <code>" << Html(Value(result["study_sha256"])) << "</code>";
  os << "</p>\n";
  if (study.is_object() && study.contains("description") && study["description"].is_string())
    os << "<p>" << Html(study["description"].get<std::string>()) << "</p>\n";

  // The verdict first, one line from the answer's status (studies/status.h).
  const Status status = outputs.status().value_or(StatusOfTable(table));
  // Green only when every limit the kind considers was checked: limits met with some not set is
  // amber ("partial"), so that a verdict over the limits a study happened to set is not read as
  // "this design is fine".
  const char* badge = ExitCode(status, false) != 0 || status == Status::kLimitsExceeded ? "bad"
                      : limits == 0 && !IsVerified(status) && table.unset.empty()        ? "info"
                      : !table.unset.empty()                                             ? "partial"
                                                                                         : "ok";
  os << "<div class=\"verdict " << badge << "\">" << Html(VerdictLine(table, status, outputs.status_reason()))
     << " <code>" << StatusName(status) << "</code></div>\n";

  os << "<h2>Headline numbers</h2>\n";
  if (rows.empty()) {
    os << "<p>None.</p>\n";
  } else {
    os << "<table>\n<tr><th>quantity</th><th>value</th><th>limit</th><th>margin</th><th>status</th></tr>\n";
    for (const HeadlineRow& r : rows)
      os << "<tr><td>" << Html(r.label) << "</td><td class=\"n\">" << Html(r.value) << "</td><td class=\"n\">"
         << Html(r.limit) << "</td><td class=\"n\">" << Html(r.margin) << "</td><td class=\""
         << r.status << "\">" << (r.status.empty() ? "" : r.status == "pass" ? "pass" : "FAIL") << "</td></tr>\n";
    os << "</table>\n";
  }

  os << "<h2>Warnings</h2>\n";
  if (warnings.empty()) {
    os << "<p>None.</p>\n";
  } else {
    os << "<ul class=\"w\">\n";
    for (const auto& w : warnings) os << "<li>" << Html(w) << "</li>\n";
    os << "</ul>\n";
  }
  if (!notes.empty()) {
    os << "<h2>Notes</h2>\n<ul>\n";
    for (const auto& n : notes) os << "<li>" << Html(n) << "</li>\n";
    os << "</ul>\n";
  }

  const auto lives = LifeTables(result);
  if (!lives.empty()) {
    os << "<h2>Lives</h2>\n";
    for (const auto& [pointer, life] : lives) LifeTableHtml(os, pointer, *life);
  }

  os << "<h2>Plots</h2>\n<div class=\"plots\">\n";
  int plots = 0;
  for (const auto& [file, content] : files) {
    if (file.size() < 4 || file.compare(file.size() - 4, 4, ".svg") != 0) continue;
    const auto [svg, width] = Scalable(content);
    os << "<figure" << (width > 900 ? " class=\"wide\"" : "") << ">\n" << svg << "<figcaption>" << Html(file)
       << "</figcaption>\n</figure>\n";
    ++plots;
  }
  os << "</div>\n";
  if (plots == 0) os << "<p>This run has no plots.</p>\n";

  os << "<h2>Inputs</h2>\n<table>\n<tr><th>field</th><th>value</th></tr>\n";
  std::vector<std::pair<std::string, std::string>> inputs;
  Flatten(study, "", inputs);
  for (const auto& [path, value] : inputs)
    os << "<tr><td><code>" << Html(path) << "</code></td><td>" << Html(value) << "</td></tr>\n";
  os << "</table>\n";

  os << "<h2>Files of this run</h2>\n<ul>\n";
  // Each file with its size (kB = 1000 bytes), so a part too large for its reader shows here.
  const auto size = [](size_t bytes) {
    char buf[32];
    if (bytes < 1000)
      std::snprintf(buf, sizeof buf, "%zu bytes", bytes);
    else if (bytes < 1000000)
      std::snprintf(buf, sizeof buf, bytes < 10000 ? "%.1f kB" : "%.0f kB", double(bytes) / 1e3);
    else
      std::snprintf(buf, sizeof buf, "%.1f MB", double(bytes) / 1e6);
    return std::string(buf);
  };
  for (const auto& [file, content] : files)
    os << "<li><code>" << Html(file) << "</code> " << size(content.size()) << "</li>\n";
  os << "<li><code>report.html</code> (this page)</li>\n</ul>\n";
  os << "<details><summary>result.json</summary>\n<pre>" << Html(result.dump(2)) << "</pre>\n</details>\n";
  os << "</body>\n</html>\n";
  return os.str();
}

const char* ReportStyle() { return kStyle; }
std::vector<Headline> JoinHeadlines(std::initializer_list<std::vector<Headline>> parts) {
  std::vector<Headline> rows;
  for (const auto& part : parts) rows.insert(rows.end(), part.begin(), part.end());
  return rows;
}

std::string HtmlEscape(const std::string& text) { return Html(text); }
std::string ReportNumber(double value) { return Number(value); }

std::string PlainName(const std::string& kind, const std::string& pointer) {
  if (const std::vector<Headline>* headlines = FindHeadlines(kind))
    for (const Headline& h : *headlines)
      if (h.pointer == pointer) return h.label + (h.unit.empty() ? "" : " [" + h.unit + "]");
  // Unit suffixes of result keys (docs/studies.md, "Units"), longest first.
  static const std::vector<std::pair<std::string, std::string>> kUnits = {
      {"_Nm_per_arcmin", "N·m/arcmin"}, {"_Nm_per_rad", "N·m/rad"}, {"_N_per_mm", "N/mm"},
      {"_arcmin", "arcmin"}, {"_arcsec", "arcsec"}, {"_percent", "%"}, {"_MPa", "MPa"},
      {"_GPa", "GPa"}, {"_rpm", "rpm"}, {"_deg", "deg"}, {"_rad", "rad"}, {"_mm", "mm"},
      {"_um", "µm"}, {"_Nm", "N·m"}, {"_kg", "kg"}, {"_N", "N"}, {"_W", "W"}, {"_h", "h"},
      {"_s", "s"}};
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(pointer);
  while (std::getline(in, part, '/'))
    if (!part.empty()) parts.push_back(part);
  if (parts.empty()) return pointer;
  std::string unit;
  std::string& last = parts.back();
  for (const auto& [suffix, name] : kUnits)
    if (last.size() > suffix.size() && last.compare(last.size() - suffix.size(), suffix.size(), suffix) == 0) {
      last.resize(last.size() - suffix.size());
      unit = name;
      break;
    }
  std::string words;
  for (const std::string& p : parts) {
    std::string w = p;
    std::replace(w.begin(), w.end(), '_', ' ');
    words += (words.empty() ? "" : ", ") + w;
  }
  return words + (unit.empty() ? "" : " [" + unit + "]");
}

void AddReport(const std::string& kind, const nlohmann::json& study, Outputs& outputs) {
  if (const nlohmann::json* r = outputs.result()) {
    const nlohmann::json& result = *r;
    const auto lives = LifeTables(result);
    for (size_t i = 0; i < lives.size(); ++i) {
      const nlohmann::json& life = *lives[i].second;
      const double limit = life.contains("life_h") && life["life_h"].is_number() ? life["life_h"].get<double>() : 0.0;
      outputs.Add(i == 0 ? "life.svg" : "life_" + std::to_string(i + 1) + ".svg",
                  SvgLifeBars(life["table"], limit, "Lives L10h (" + lives[i].first + "/table)"));
    }
  }
  outputs.Add("report.html", HtmlReport(kind, study, outputs));
}

}  // namespace camopt::studies

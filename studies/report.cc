#include "studies/report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>
#include <utility>

namespace camopt::studies {

namespace {

std::map<std::string, std::vector<Headline>>& Reports() {
  static std::map<std::string, std::vector<Headline>> reports;
  return reports;
}

std::string Html(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '&') out += "&amp;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}

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
    for (const auto& e : v) joined += (joined.empty() ? "" : ", ") + e.get<std::string>();
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
.ok{background:#e3f4e3;color:#185c18}.bad{background:#fbe3e3;color:#8c1a1a}.info{background:#eef2f8;color:#234}
table{border-collapse:collapse;font-size:14px}td,th{border:1px solid #ccc;padding:3px 8px;text-align:left}
th{background:#f3f3f3}td.n{text-align:right;font-variant-numeric:tabular-nums}
td.pass{color:#185c18;font-weight:bold}td.fail{color:#8c1a1a;font-weight:bold;background:#fbe3e3}
.plots{display:grid;grid-template-columns:repeat(auto-fill,minmax(500px,1fr));gap:12px}
figure{margin:0;border:1px solid #ddd;padding:6px;overflow-x:auto}figure.wide{grid-column:1/-1}figcaption{font-size:12px;color:#555}
figure svg{max-width:100%;height:auto}pre{font-size:12px;background:#f7f7f7;padding:8px;overflow-x:auto}
code{font-size:13px}ul.w li{color:#8a5300})";

}  // namespace

bool RegisterReport(const std::string& kind, std::vector<Headline> headlines) {
  Reports()[kind] = std::move(headlines);
  return true;
}

HeadlineTable EvaluateHeadlines(const std::string& kind, const nlohmann::json& study, const nlohmann::json& result) {
  HeadlineTable table;
  const auto reg = Reports().find(kind);
  if (reg == Reports().end()) {
    for (const auto& [k, v] : result.items())
      if (v.is_number()) table.rows.push_back({k, Value(v), "", "", ""});
    return table;
  }
  table.registered = true;
  for (const Headline& h : reg->second) {
    const nlohmann::json* v = At(result, h.pointer);
    if (!v) continue;
    const std::string unit = h.unit.empty() ? "" : " " + h.unit;
    std::string value = Value(*v);
    double error = 0;  // the value's error estimate, when the kind gives one
    if (const nlohmann::json* e = At(result, h.error_pointer); e && e->is_number() && v->is_number()) {
      value += " ± " + Error(e->get<double>());
      error = std::abs(e->get<double>());
    }
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
    }
    table.rows.push_back(row);
  }
  return table;
}

std::string VerdictLine(const HeadlineTable& table) {
  if (table.limits == 0) return "No limits to check in this study";
  if (table.exceeded.empty()) return "All " + std::to_string(table.limits) + " limits met";
  std::string s = std::to_string(table.exceeded.size()) + " of " + std::to_string(table.limits) + " limits exceeded: ";
  for (size_t i = 0; i < table.exceeded.size(); ++i) s += (i ? ", " : "") + table.exceeded[i];
  return s;
}

std::string HtmlReport(const std::string& kind, const nlohmann::json& study, const Outputs& outputs) {
  const auto& files = outputs.files();
  nlohmann::json result = nlohmann::json::object();
  if (const auto it = files.find("result.json"); it != files.end()) {
    result = nlohmann::json::parse(it->second, nullptr, false);
    if (result.is_discarded()) result = nlohmann::json::object();
  }
  std::string name = study.is_object() && study.contains("name") && study["name"].is_string()
                         ? study["name"].get<std::string>()
                         : "";
  if (name.empty()) name = kind;

  const HeadlineTable table = EvaluateHeadlines(kind, study, result);
  const std::vector<HeadlineRow>& rows = table.rows;
  const int limits = table.limits, exceeded = int(table.exceeded.size());

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

  // The verdict first: incomplete, limits exceeded, or all met.
  if (!outputs.incomplete().empty())
    os << "<div class=\"verdict bad\">Incomplete: " << Html(outputs.incomplete()) << "</div>\n";
  if (limits > 0)
    os << "<div class=\"verdict " << (exceeded ? "bad" : "ok") << "\">" << Html(VerdictLine(table)) << "</div>\n";
  else if (outputs.incomplete().empty())
    os << "<div class=\"verdict info\">" << Html(VerdictLine(table)) << "</div>\n";

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
  for (const auto& [file, content] : files) os << "<li><code>" << Html(file) << "</code></li>\n";
  os << "<li><code>report.html</code> (this page)</li>\n</ul>\n";
  os << "<details><summary>result.json</summary>\n<pre>" << Html(result.dump(2)) << "</pre>\n</details>\n";
  os << "</body>\n</html>\n";
  return os.str();
}

void AddReport(const std::string& kind, const nlohmann::json& study, Outputs& outputs) {
  outputs.Add("report.html", HtmlReport(kind, study, outputs));
}

}  // namespace camopt::studies

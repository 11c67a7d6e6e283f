// datasheet.html (studies/datasheet.h).
#include "studies/datasheet.h"

#include <cmath>
#include <map>

#include "studies/kind.h"
#include "studies/report.h"

namespace camopt::studies {

namespace {

const nlohmann::json* At(const nlohmann::json& j, const std::string& pointer) {
  if (pointer.empty()) return nullptr;
  const nlohmann::json::json_pointer p(pointer);
  return j.contains(p) ? &j.at(p) : nullptr;
}

const char* kSheetStyle =
    "table.sheet{min-width:640px}table.sheet td.src{color:#777;font-size:11px;font-family:monospace}"
    "table.sheet td.why{color:#8a5300}";

}  // namespace

std::string DatasheetHtml(const DatasheetSpec& spec, const nlohmann::json& result,
                          const std::vector<std::pair<std::string, std::string>>& figures) {
  auto text = [&](const char* key) {
    return result.contains(key) && result[key].is_string() ? result[key].get<std::string>() : std::string();
  };
  std::string h = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>Datasheet: " +
                  HtmlEscape(text("name")) + "</title><style>" + ReportStyle() + kSheetStyle +
                  "</style></head><body>\n<h1>Datasheet: " + HtmlEscape(text("name")) + "</h1>\n" +
                  "<p class=\"meta\">" + HtmlEscape(text("study")) + " · computed by camopt " +
                  HtmlEscape(text("camopt_version")) + " from the study of SHA-256 <code>" +
                  HtmlEscape(text("study_sha256")) +
                  "</code>. Every number is read from result.json; its source is the JSON pointer beside it.</p>\n";
  for (const DatasheetSection& section : spec.sections) {
    std::string rows;
    for (const DatasheetRow& row : section.rows) {
      const nlohmann::json* v = At(result, row.pointer);
      std::string value, cls = "n", source = row.pointer;
      if (v && v->is_number()) {
        value = ReportNumber(v->get<double>() * row.scale) + (row.unit.empty() ? "" : " " + row.unit);
      } else if (v && v->is_string()) {
        value = v->get<std::string>();
        cls = "";
      } else {
        const nlohmann::json* why = At(result, row.why_pointer);
        if (!v && !why) continue;  // neither asked nor explained: the study did not give the block
        value = why && why->is_string() ? why->get<std::string>() : "not computed";
        if (why && why->is_string()) source = row.why_pointer;  // the text shown is the why's
        cls = "why";
      }
      rows += "<tr><td>" + HtmlEscape(row.label) + "</td><td class=\"" + cls + "\" data-source=\"" +
              HtmlEscape(source) + "\">" + HtmlEscape(value) + "</td><td class=\"src\">" + HtmlEscape(source) +
              "</td></tr>\n";
    }
    if (rows.empty()) continue;
    h += "<h2>" + HtmlEscape(section.title) + "</h2>\n<table class=\"sheet\"><tr><th>item</th><th>value</th>"
         "<th>result.json</th></tr>\n" + rows + "</table>\n";
  }
  // The bearing lives as the life table has them.
  if (const nlohmann::json* table = At(result, "/life/table"); table && table->is_array() && !table->empty()) {
    h += "<h2>Bearing lives at the duty cycle</h2>\n<table class=\"sheet\"><tr><th>element</th><th>L10 [h]</th>"
         "<th>result.json</th></tr>\n";
    for (size_t k = 0; k < table->size(); ++k) {
      const nlohmann::json& row = (*table)[k];
      const std::string name = row.contains("element") && row["element"].is_string() ? row["element"].get<std::string>()
                               : row.contains("name") && row["name"].is_string()    ? row["name"].get<std::string>()
                                                                                    : std::to_string(k + 1);
      const std::string pointer = "/life/table/" + std::to_string(k) + "/L10h";
      const nlohmann::json* v = At(result, pointer);
      const std::string value = v && v->is_number() ? ReportNumber(v->get<double>()) + " h" : "no load";
      h += "<tr><td>" + HtmlEscape(name) + "</td><td class=\"n\" data-source=\"" + pointer + "\">" +
           HtmlEscape(value) + "</td><td class=\"src\">" + pointer + "</td></tr>\n";
    }
    h += "</table>\n";
  }
  if (!figures.empty()) {
    h += "<h2>Curves</h2>\n<div class=\"plots\">\n";
    for (const auto& [name, svg] : figures)
      h += "<figure>" + svg + "<figcaption>" + HtmlEscape(name) + "</figcaption></figure>\n";
    h += "</div>\n";
  }
  h += "</body></html>\n";
  return h;
}

void AddDatasheet(const std::string& kind, Outputs& outputs) {
  const KindDescriptor* k = FindKind(kind);
  if (!k || !k->datasheet || !outputs.result()) return;
  const DatasheetSpec& spec = *k->datasheet;
  const auto& files = outputs.files();
  const nlohmann::json& result = *outputs.result();
  if (!At(result, spec.when_pointer)) return;
  std::vector<std::pair<std::string, std::string>> figures;
  for (const std::string& f : spec.figures)
    if (const auto svg = files.find(f); svg != files.end()) figures.emplace_back(f, svg->second);
  outputs.Add("datasheet.html", DatasheetHtml(spec, result, figures));
}

}  // namespace camopt::studies

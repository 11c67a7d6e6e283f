// report.html: one self-contained page per run, written for every study kind.
//
// It shows the study's inputs, the headline numbers with their limits and pass/fail, the
// warnings, every SVG plot of the run inline, and the full result.json; it loads nothing from
// anywhere else (no script, no style sheet, no font, no image file), so it can be mailed as is.
// The page is built from the run's own outputs (result.json and the *.svg files), so a kind only
// declares which result.json numbers are its headlines and where their limits are
// (KindDescriptor::report, studies/kind.h). Same outputs → byte-identical page.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "studies/study.h"

namespace camopt::studies {

/// One headline number of a kind's report: a number in result.json and, optionally, its limit.
/// A headline whose pointer is not in result.json (an optional stage not run) is left out.
struct Headline {
  std::string label;    // "largest contact stress, input cam"
  std::string pointer;  // JSON pointer into result.json: "/input_cam/max_contact_stress_MPa"
  std::string unit;     // "MPa" ("" for a pure number)
  /// The limit: a JSON pointer into result.json, or into the study when it starts with "study:"
  /// ("study:/limits/contact_stress_MPa"); where it points at no number, limit_value (NaN: no
  /// limit, e.g. a default of 0 for a margin).
  std::string limit_pointer = "";
  double limit_value = NAN;
  /// true: the value passes when value ≤ limit (a stress); false: when value ≥ limit (a margin).
  bool upper_limit = true;
  /// The value's error estimate (a JSON pointer into result.json), shown as "± error".
  std::string error_pointer = "";
  /// Shown only when this JSON pointer is in result.json ("": always): a label that holds for one
  /// variant of a kind only (a formula of one follower type).
  std::string only_with = "";
  /// Left out when this JSON pointer is in result.json ("": never): the label of the other variant.
  std::string not_with = "";
  /// The smallest magnitude the value resolves (a design variable at the optimizer's tolerance):
  /// a value below it, or below its own error estimate, is shown as 0, not as the solver's noise.
  double resolution = 0;
};

/// The rows of several lists, in order: a kind's own rows and the shared blocks' (RatingsHeadlines,
/// TorsionalDynamicsHeadlines).
std::vector<Headline> JoinHeadlines(std::initializer_list<std::vector<Headline>> parts);

/// The headlines of a kind's report (KindDescriptor::report), or nullptr: a kind without them gets
/// every top-level number of result.json instead (the Python module's Result.headlines reads their
/// numbers from result.json by their pointers).
const std::vector<Headline>* FindHeadlines(const std::string& kind);

/// One headline evaluated on a run, as report.html and the stdout summary show it.
struct HeadlineRow {
  std::string label;
  std::string value;   ///< with its error estimate ("± …") and unit
  std::string limit;   ///< "≤ 1500 MPa", "" without a limit
  std::string margin;  ///< limit − value (upper) or value − limit (lower), with unit
  std::string status;  ///< "pass", "fail" or "" without a limit
};

/// A kind's headlines evaluated on a result: a limit holds when the value is within it plus the
/// value's estimated error (the verified-optimum contract, objectives/verification.h). A kind
/// without registered headlines gets every top-level number of result.json (registered false).
struct HeadlineTable {
  std::vector<HeadlineRow> rows;
  int limits = 0;                      ///< rows with a limit
  std::vector<std::string> exceeded;   ///< labels of the rows that fail
  /// Labels of the rows whose limit the kind considers but the study did not set: a verdict over
  /// the limits set says so, so that "met" is never read as "this design is fine".
  std::vector<std::string> unset;
  bool registered = false;
  /// A sizing result without a design ("best": null): why, from result.json's first note ("" when
  /// it has none); no_design true. Its limits cannot be checked: there is nothing to check them on.
  bool no_design = false;
  std::string no_design_reason;
};
HeadlineTable EvaluateHeadlines(const std::string& kind, const nlohmann::json& study, const nlohmann::json& result);
/// The same with the headlines given (nullptr: none).
HeadlineTable EvaluateHeadlines(const std::vector<Headline>* headlines, const nlohmann::json& study,
                                const nlohmann::json& result);

/// The verdict line of an answer, a function of its status (studies/status.h) and the reason
/// that goes with it: "All 7 limits met, verified by the accurate model", "All 7 limits met,
/// verified; not proven optimal: <why>", "No design meets the limits: <why>", "Not verifiable:
/// <why>", "Not converged: <why>", "All 7 limits met", "2 of 7 limits exceeded: a, b", or "No
/// limits to check in this study".
std::string VerdictLine(const HeadlineTable& table, Status status, const std::string& reason);

/// The status a table alone gives (no run status known): infeasible without a design, else its
/// limits met or exceeded.
Status StatusOfTable(const HeadlineTable& table);

/// The verdict line of a written result.json (its "status" and "status_reason"; for a result
/// without them, the limits of `table`): for readers of a finished run (the studio, Python).
std::string VerdictOf(const HeadlineTable& table, const nlohmann::json& result);

/// The page for a run of `kind` on `study` whose files are `outputs` (result.json, *.svg, …).
std::string HtmlReport(const std::string& kind, const nlohmann::json& study, const Outputs& outputs);
/// The same with the headlines given (nullptr: every top-level number).
std::string HtmlReport(const std::string& kind, const std::vector<Headline>* headlines, const nlohmann::json& study,
                       const Outputs& outputs);

/// The life tables of a result: every object named "life" with a "table" array, at the top level
/// or one level down (lcr_analysis's /life, the sizing kinds' /best/life), with its JSON pointer.
std::vector<std::pair<std::string, const nlohmann::json*>> LifeTables(const nlohmann::json& result);

/// A horizontal bar plot of the lives L10h [h] of a life table's rows on a logarithmic axis, the
/// limit life_h (when > 0) drawn as a vertical dashed line; bars that fail it red. Rows without a
/// finite L10h (no load) are listed as "no load" at the axis end.
std::string SvgLifeBars(const nlohmann::json& table, double limit_h, const std::string& title);

/// A result number's plain name for tables and axis titles: the kind's headline label and unit
/// when `pointer` is one of its headlines, else the pointer's words with the unit of its key's
/// suffix ("/input_cam/max_contact_stress_MPa" → "input cam, max contact stress [MPa]").
std::string PlainName(const std::string& kind, const std::string& pointer);

/// For pages built like report.html (the sweep's): its style sheet, HTML escaping, and a number
/// as it shows one (integers exactly, others to 6 significant digits).
const char* ReportStyle();
std::string HtmlEscape(const std::string& text);
std::string ReportNumber(double value);

/// Adds report.html (HtmlReport) to outputs, and before it life.svg (SvgLifeBars) when result.json
/// has a life table (LifeTables; `life_N.svg` for a second one), so that the plot is a file of the
/// run like every other.
void AddReport(const std::string& kind, const nlohmann::json& study, Outputs& outputs);

}  // namespace camopt::studies

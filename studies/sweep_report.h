// What shows a sweep's Pareto front (studies/sweep_pareto.h): the front's plots (pareto.svg and,
// with more than two objectives, one panel per pair), the sweep's report.html and its stdout
// summary. The cases are run in studies/sweep.cc.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "studies/sweep.h"

namespace camopt::studies::sweep {

/// The front's plots as {file name, SVG}: one objective, the objective over the case number; two,
/// pareto.svg; k > 2, pareto.svg for objectives 1 and 2 and pareto_I_J.svg for each other pair
/// (a front case can look dominated in two of k objectives: it is better in another, and the
/// titles say so). Front cases are labelled with their numbers (up to 20 of them), axes with the
/// objectives' plain names (PlainName) and the direction.
std::vector<std::pair<std::string, std::string>> ParetoPlots(const Sweep& sweep,
                                                             const std::vector<CaseRecord>& records,
                                                             const std::vector<size_t>& front);

/// Each output against each varied input over the ok cases (numbers only): outputs_I_vs_J.svg
/// for output I and input J (1-based; the first six outputs and four inputs). With two varied
/// inputs, one line per level of the other input, so that a plot reads as "this output as J
/// changes, at each value of the other"; otherwise the cases as points.
std::vector<std::pair<std::string, std::string>> OutputPlots(const Sweep& sweep,
                                                             const std::vector<std::vector<nlohmann::json>>& cases,
                                                             const std::vector<CaseRecord>& records);

/// The verdict over the cases, one line: "All N cases ok" or "K of N cases ok", then the count of
/// each other status ("…, 2 incomplete"). The report's headline and result.json's "verdict".
std::string SweepVerdict(const std::vector<CaseRecord>& records);

/// The sweep's report.html: the verdict over the cases, the design, the Pareto front (its cases
/// and plots), each output against each input (OutputPlots), the cases not ok and why, and every
/// case's row. `records` sorted by case number; `plots` the front's SVG files to show inline,
/// `output_plots` OutputPlots'.
std::string SweepHtml(const Sweep& sweep, const std::vector<std::vector<nlohmann::json>>& cases,
                      const std::vector<CaseRecord>& records, const std::vector<size_t>& front,
                      const std::vector<std::pair<std::string, std::string>>& plots,
                      const std::vector<std::pair<std::string, std::string>>& output_plots = {});

/// The answer first, for stdout: the counts by status, the front's cases, the best case of each
/// objective (or each output's range without objectives), and where report.html is.
std::string SweepSummary(const Sweep& sweep, const std::vector<CaseRecord>& records,
                         const std::vector<size_t>& front, const std::string& out_dir);

}  // namespace camopt::studies::sweep

// `camopt run STUDY --convergence`: the study at its own settings and with each fidelity knob of
// its kind (FidelityKnob, declared next to the kind's registration) refined and coarsened one at a
// time, in process (RunStudy). Writes convergence.json — per knob its values, the wall time of
// each run, per headline output the value at each setting and the estimated error of the study's
// setting (Richardson where the kind declares the order, else the difference to the finest run) —
// an SVG of error against time per output, and a table for stdout. The study's own result files
// are those of its own settings.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "studies/study.h"

namespace camopt::studies {

/// The estimated error of the study's setting f0 from the runs of one knob, ordered from coarse
/// to fine: values[i] at settings whose step shrinks by `ratio` (> 1) each time; base is the index
/// of f0. Richardson (order > 0 and a finer run): (f0 − f1)·ρ^p/(ρ^p − 1); otherwise |f0 − f_finest|;
/// with no finer run (refinement skipped), |f_coarser − f0| (method says so).
struct ErrorEstimate {
  double error = 0;          ///< >= 0
  double extrapolated = 0;   ///< Richardson's limit (or the finest value)
  std::string method;        ///< "richardson", "difference_to_finest", "difference_to_coarser", "none"
  double observed_order = 0; ///< from three runs when they converge monotonically, else 0
};
ErrorEstimate EstimateKnobError(const std::vector<double>& values, size_t base, double ratio, double order);

struct ConvergenceRun {
  Outputs own;                 ///< the study's own outputs (its settings)
  nlohmann::json report;       ///< convergence.json
  std::string table;           ///< the stdout table
};

/// Runs the study and its knob variants. Throws as RunStudy for the study's own settings; a
/// variant that cannot run (over the work limits, outside a setting's range) is skipped and
/// recorded in the report.
ConvergenceRun RunConvergence(const nlohmann::json& study, const RunContext& ctx);

/// The CLI: loads `file`, runs the convergence study, writes the study's own files plus
/// convergence.json and convergence_*.svg into out_dir, prints the table on stdout. Throws as
/// RunStudyFile (StudyIncomplete when the study's own result is incomplete).
void RunConvergenceFile(const std::string& file, const std::string& out_dir, const RunContext& ctx);

}  // namespace camopt::studies

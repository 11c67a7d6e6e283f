// Study kind "cycloid_crowning_tuning" (studies/cycloid_crowning_tuning_study.h): parse, scan and
// optimise through objectives/cycloid_crowning.h and optimizers/, write.
#include "studies/cycloid_crowning_tuning_study.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>
#include <vector>

#include "optimizers/solver.h"
#include "studies/cycloid_study_common.h"
#include "studies/report.h"
#include "studies/writers.h"

namespace camopt::studies::cycloid_crowning_tuning {

using objectives::CrowningEvaluation;

Study Parse(const Node& root) {
  root.CheckKnownFields({"study", "name", "description", "drive", "modification", "material", "load", "analysis", "tuning", "crowning"});
  Study s;
  s.name = root.json().value("name", "");
  s.drive = cycloid_common::ParseDrive(root);
  s.material = cycloid_common::ParseMaterial(root);
  const Node load = root["load"];
  load.CheckKnownFields({"design_torque_Nm", "max_torque_Nm"});
  s.design_torque_Nm = load["design_torque_Nm"].Positive();
  s.max_torque_Nm = load["max_torque_Nm"].Positive();
  if (s.max_torque_Nm < s.design_torque_Nm) load["max_torque_Nm"].Fail("a torque >= design_torque_Nm");
  const Node tuning = root["tuning"];
  tuning.CheckKnownFields({"coefficient_mm", "effective_length_mm", "reference_coefficient_mm", "curve_points",
                           "max_evaluations", "edge_margin_um"});
  std::tie(s.coefficient_lo_mm, s.coefficient_hi_mm) = tuning["coefficient_mm"].Range();
  if (s.coefficient_lo_mm < 0 || !(s.coefficient_hi_mm > s.coefficient_lo_mm))
    tuning["coefficient_mm"].Fail("a range [lo, hi] with 0 <= lo < hi");
  s.tune_length = tuning.Has("effective_length_mm");
  s.length_lo_mm = s.length_hi_mm = s.drive.face_width_mm;
  if (s.tune_length) {
    std::tie(s.length_lo_mm, s.length_hi_mm) = tuning["effective_length_mm"].Range();
    if (s.length_lo_mm < s.drive.face_width_mm)
      tuning["effective_length_mm"].Fail("a range with lo >= the face width");
    s.tune_length = s.length_hi_mm > s.length_lo_mm;
  }
  // "crowning": the logarithmic form whose coefficient is tuned; its other fields stay fixed.
  if (root.Has("crowning")) {
    const Node c = root["crowning"];
    c.CheckKnownFields({"type", "effective_length_mm", "end_drop_mm", "flat_length_mm"});
    if (c["type"].String() != "logarithmic") c["type"].Fail("\"logarithmic\"");
    s.shape.type = cycloid::CrowningType::kLogarithmic;
    s.shape.end_drop_mm = c.NonNegativeOr("end_drop_mm", 0.0);
    s.shape.flat_length_mm = c.NonNegativeOr("flat_length_mm", 0.0);
    if (c.Has("effective_length_mm")) {
      if (tuning.Has("effective_length_mm"))
        c["effective_length_mm"].Fail("no value here when tuning.effective_length_mm is given");
      s.length_lo_mm = s.length_hi_mm = c["effective_length_mm"].Positive();
      if (s.length_lo_mm < s.drive.face_width_mm) c["effective_length_mm"].Fail("a length >= the face width");
    }
    s.shape.effective_length_mm = s.length_lo_mm;
    if (const std::string why = cycloid::CheckCrowning(s.shape, s.drive.face_width_mm); !why.empty())
      c.FailWith(why);
  }
  s.reference_coefficient_mm = tuning.NonNegativeOr("reference_coefficient_mm", 0.005);
  s.curve_points = tuning.IntegerOr("curve_points", 2, 11);
  s.max_evaluations = tuning.IntegerOr("max_evaluations", 1, 30);
  s.required_edge_margin_um = tuning.NumberOr("edge_margin_um", 0.0);
  if (s.curve_points > 200) tuning["curve_points"].Fail("at most 200 points");
  if (root.Has("analysis")) {
    const Node a = root["analysis"];
    a.CheckKnownFields({"grid", "crank_angles_per_mesh_period"});
    cycloid_common::ParseGrid(a, s.options);
    s.crank_angles_per_mesh_period = a.IntegerOr("crank_angles_per_mesh_period", 1, 6);
    if (s.crank_angles_per_mesh_period > 1000) a["crank_angles_per_mesh_period"].Fail("at most 1000");
  }
  return s;
}

Result Run(const Study& s, const RunContext& ctx) {
  const std::vector<double> angles =
      cycloid::UniformCrankAngles(s.crank_angles_per_mesh_period, 2.0 * kPi / s.drive.rollers);
  objectives::CycloidCrowningModel model(s.drive, s.material, s.options, s.design_torque_Nm * 1000.0,
                                         s.max_torque_Nm * 1000.0, angles, s.shape);
  // The paper's form (eq. 7, L = B) for the reference coefficient.
  objectives::CycloidCrowningModel paper(s.drive, s.material, s.options, s.design_torque_Nm * 1000.0,
                                         s.max_torque_Nm * 1000.0, angles);
  Result r;
  Progress progress("cycloid_crowning_tuning", ctx.quiet);
  // 1. The stress-versus-f curve (at L = the lower length bound).
  for (int k = 0; k < s.curve_points; ++k) {
    const double f = s.coefficient_lo_mm + (s.coefficient_hi_mm - s.coefficient_lo_mm) * k / (s.curve_points - 1);
    r.curve.push_back(model.Evaluate(f, s.length_lo_mm));
    progress.Update(0.5 * (k + 1) / s.curve_points, "scan f = " + Format(f * 1e3, 4) + " um");
  }
  r.reference = paper.Evaluate(s.reference_coefficient_mm, s.drive.face_width_mm);
  // 2. Start from the best feasible scan point (else the one with the largest margin).
  const CrowningEvaluation start = objectives::LowestFeasibleStress(r.curve, s.required_edge_margin_um)
                                       .value_or(objectives::LargestEdgeMargin(r.curve));

  objectives::CycloidCrowningSpec spec;
  spec.coefficient_lo_mm = s.coefficient_lo_mm;
  spec.coefficient_hi_mm = s.coefficient_hi_mm;
  spec.initial_coefficient_mm = start.coefficient_mm;
  spec.tune_length = s.tune_length;
  spec.length_lo_mm = s.length_lo_mm;
  spec.length_hi_mm = s.length_hi_mm;
  spec.required_edge_margin_um = s.required_edge_margin_um;
  spec.stress_scale_MPa = std::max(1.0, start.stress_MPa);
  const objectives::Problem problem = objectives::CycloidCrowningProblem(
      model, spec, [&](const CrowningEvaluation& e) {
        r.history.push_back(e);
        progress.Update(std::min(1.0, 0.5 + 0.5 * double(r.history.size()) / (s.max_evaluations + 1)),
                        "f = " + Format(e.coefficient_mm * 1e3, 4) + " um, " +
                            cycloid_common::Fixed(e.stress_MPa, 0) + " MPa");
      });
  optimizers::SolverOptions options;
  options.backend = "nlopt_cobyla";
  options.tolerance = 1e-3;             // relative, on f (and L) and on the stress
  options.constraint_tolerance = 1e-2;  // µm of edge margin; NLopt aims at a tenth of it
  options.max_evaluations = s.max_evaluations;
  options.max_seconds = 1e9;  // no time limit: the evaluation budget bounds the run
  const optimizers::SolverResult solved = optimizers::Solve(problem, options);
  switch (solved.status) {
    case optimizers::SolverStatus::kIterationLimit: r.status = "max_evaluations reached"; break;
    case optimizers::SolverStatus::kFailed: r.status = "optimizer stopped: " + solved.message; break;
    // COBYLA stopped on its tolerances; whether the point is feasible is judged below over every
    // evaluation.
    default: r.status = "converged"; break;
  }
  progress.Done();
  // The best feasible point seen anywhere (scan, then optimiser).
  std::vector<CrowningEvaluation> seen = r.curve;
  seen.insert(seen.end(), r.history.begin(), r.history.end());
  const auto best = objectives::LowestFeasibleStress(seen, s.required_edge_margin_um - 1e-9);
  r.feasible = best.has_value();
  r.best = best.value_or(start);
  r.evaluations = model.evaluations() + paper.evaluations();
  return r;
}

nlohmann::json ToJson(const Study& s, const Result& r) {
  nlohmann::json jcurve = nlohmann::json::array();
  for (const auto& e : r.curve)
    jcurve.push_back({{"coefficient_mm", e.coefficient_mm},
                      {"max_contact_stress_MPa", Finite(e.stress_MPa, "stress")},
                      {"edge_margin_at_max_torque_um", Finite(e.edge_margin_um, "margin")}});
  return {{"study", "cycloid_crowning_tuning"},
          {"name", s.name},
          {"optimizer", "NLopt LN_COBYLA from the best feasible point of a scan"},
          {"status", r.status},
          {"feasible", r.feasible},
          {"tuned_coefficient_mm", Finite(r.best.coefficient_mm, "f")},
          {"tuned_effective_length_mm", Finite(r.best.length_mm, "L")},
          {"end_drop_mm", s.shape.end_drop_mm},
          {"flat_length_mm", s.shape.flat_length_mm},
          {"tuned_max_contact_stress_MPa", Finite(r.best.stress_MPa, "stress")},
          {"tuned_edge_margin_at_max_torque_um", Finite(r.best.edge_margin_um, "margin")},
          {"reference_coefficient_mm", s.reference_coefficient_mm},
          {"reference_max_contact_stress_MPa", Finite(r.reference.stress_MPa, "stress")},
          {"reference_edge_margin_at_max_torque_um", Finite(r.reference.edge_margin_um, "margin")},
          {"design_torque_Nm", s.design_torque_Nm},
          {"max_torque_Nm", s.max_torque_Nm},
          {"crank_angles_per_mesh_period", s.crank_angles_per_mesh_period},
          {"axial_cell_mm", s.drive.face_width_mm / s.options.axial_cells},
          {"evaluations", r.evaluations},
          {"curve", jcurve}};
}

void Write(const Study& s, const Result& r, Outputs& out) {
  out.AddJson("result.json", ToJson(s, r));
  Table table;
  std::vector<double> cf, cs, cm;
  for (const auto& e : r.curve) {
    cf.push_back(e.coefficient_mm * 1e3);
    cs.push_back(e.stress_MPa);
    cm.push_back(e.edge_margin_um);
  }
  table.Add("coefficient_um", cf);
  table.Add("max_contact_stress_MPa", cs);
  table.Add("edge_margin_at_max_torque_um", cm);
  Table hist;
  std::vector<double> hf, hl, hs, hm;
  for (const auto& e : r.history) {
    hf.push_back(e.coefficient_mm * 1e3);
    hl.push_back(e.length_mm);
    hs.push_back(e.stress_MPa);
    hm.push_back(e.edge_margin_um);
  }
  hist.Add("coefficient_um", hf);
  hist.Add("effective_length_mm", hl);
  hist.Add("max_contact_stress_MPa", hs);
  hist.Add("edge_margin_at_max_torque_um", hm);
  out.Add("stress_vs_coefficient.csv", ToCsv(table));
  out.Add("history.csv", ToCsv(hist));
  PlotOptions po;
  po.title = "Peak contact stress over the mesh at the design torque";
  po.x_label = "LCM coefficient f [um]";
  po.y_label = "peak contact stress [MPa]";
  po.points = {{"tuned", r.best.coefficient_mm * 1e3, r.best.stress_MPa},
               {"paper f", s.reference_coefficient_mm * 1e3, r.reference.stress_MPa}};
  out.Add("stress_vs_coefficient.svg", SvgLinePlot({{"peak contact stress", cf, cs}}, po));
  po.title = "Edge margin at the maximum torque (>= 0: off the face edges)";
  po.y_label = "edge margin [um]";
  po.guides = {{"required edge margin", s.required_edge_margin_um}};
  po.points = {{"tuned", r.best.coefficient_mm * 1e3, r.best.edge_margin_um},
               {"paper f", s.reference_coefficient_mm * 1e3, r.reference.edge_margin_um}};
  out.Add("edge_margin_vs_coefficient.svg", SvgLinePlot({{"edge margin", cf, cm}}, po));
}

namespace {
CAMOPT_REGISTER_STUDY_KIND("cycloid_crowning_tuning");

// Fidelity for `camopt run --convergence` (studies/convergence.h): crank angles, contact grid and
// the optimizer's evaluation budget (its tolerances are fixed).
Fidelity Knobs(const nlohmann::json&) {
  Fidelity f;
  f.knobs.push_back({"crank_angles_per_mesh_period", {"/analysis/crank_angles_per_mesh_period"}, 6, 2,
                     true, 0, "uniform crank angles per mesh period"});
  f.knobs.push_back({"grid", {"/analysis/grid"}, {40, 40}, 2, true, 0,
                     "contact cells across the profile and along the face"});
  f.knobs.push_back({"max_evaluations", {"/tuning/max_evaluations"}, 30, 2, true, 0,
                     "COBYLA evaluations after the scan"});
  f.headlines = {"/tuned_coefficient_mm", "/tuned_max_contact_stress_MPa",
                 "/reference_max_contact_stress_MPa"};
  return f;
}
CAMOPT_REGISTER_FIDELITY("cycloid_crowning_tuning", Knobs);
}  // namespace

namespace {
// report.html: the headline numbers and their limits.
CAMOPT_REGISTER_REPORT("cycloid_crowning_tuning", {
    {"tuned LCM coefficient", "/tuned_coefficient_mm", "mm"},
    {"peak contact stress, tuned", "/tuned_max_contact_stress_MPa", "MPa"},
    {"peak contact stress, paper's coefficient", "/reference_max_contact_stress_MPa", "MPa"},
    {"edge margin at the maximum torque, tuned", "/tuned_edge_margin_at_max_torque_um", "um",
     "study:/tuning/edge_margin_um", 0.0, false},
    {"edge margin at the maximum torque, paper's coefficient", "/reference_edge_margin_at_max_torque_um", "um",
     "study:/tuning/edge_margin_um", 0.0, false},
    {"status", "/status", ""},
});
}  // namespace

}  // namespace camopt::studies::cycloid_crowning_tuning

// Study kind "cycloid_crowning_tuning": the logarithmic crowning coefficient f (and, as an
// option, its effective length L) that minimises the peak contact stress over the mesh cycle at a
// design torque, subject to the contact pattern staying off the face edges at a maximum torque.
//
// Method. The mesh repeats every 2π/n1 of crank angle (up to a relabelling of the rollers), so
// one mesh period sampled uniformly stands for the cycle. A scan of f over its bounds gives the
// stress-versus-f curve; NLopt's COBYLA (LN_COBYLA: bounded, derivative-free, with inequality
// constraints handled directly) then refines from the best feasible point of the scan. Derivative
// free because each evaluation solves a complementarity problem per pair and takes a maximum over
// cells and angles: the objective is non-smooth in f (and slightly grid-quantised), so gradients
// would mislead a quasi-Newton method. The constraint is the edge margin of model/cycloid
// (clearance left at the outermost axial cells, negative in proportion to the edge pressure when
// the contact reaches an edge), continuous in f, required >= edge_margin_um.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <nlopt.hpp>

#include "model/cycloid/loaded_tca.h"
#include "studies/cycloid_study_common.h"
#include "studies/study.h"
#include "studies/writers.h"

namespace camopt::studies {
namespace {

using namespace camopt::cycloid;

struct Evaluation {
  double coefficient_mm = 0, length_mm = 0;
  double stress_MPa = 0;      // max over the design-torque cycle
  double edge_margin_um = 0;  // min over the max-torque cycle
  int pairs = 0;
};

class Tuner {
 public:
  Tuner(const Drive& drive, const Material& material, const LoadedOptions& options,
        double design_torque, double max_torque, std::vector<double> angles)
      : drive_(drive),
        design_(drive, Crowning{}, material, Design(options)),
        maximum_(drive, Crowning{}, material, Maximum(options)),
        design_torque_Nmm_(design_torque * 1000.0),
        max_torque_Nmm_(max_torque * 1000.0),
        angles_(std::move(angles)) {}

  Evaluation Evaluate(double f, double length) {
    Crowning c;
    c.type = CrowningType::kLogarithmic;
    c.coefficient_mm = std::max(0.0, f);
    c.effective_length_mm = length;
    design_.SetCrowning(c);
    maximum_.SetCrowning(c);
    Evaluation e;
    e.coefficient_mm = c.coefficient_mm;
    e.length_mm = length;
    const CycleResult d = RunCycle(design_, design_torque_Nmm_, angles_);
    const CycleResult m = RunCycle(maximum_, max_torque_Nmm_, angles_);
    e.stress_MPa = d.max_pressure_MPa;
    e.pairs = d.max_pairs_in_contact;
    e.edge_margin_um = m.edge_margin_mm * 1e3;
    ++evaluations_;
    return e;
  }
  int evaluations() const { return evaluations_; }
  const Drive& drive() const { return drive_; }

 private:
  static LoadedOptions Design(LoadedOptions o) {
    o.keep_pressure = false;
    o.edge_margin = false;
    return o;
  }
  static LoadedOptions Maximum(LoadedOptions o) {
    o.keep_pressure = false;
    o.edge_margin = true;
    return o;
  }
  Drive drive_;
  LoadedTca design_, maximum_;
  double design_torque_Nmm_, max_torque_Nmm_;
  std::vector<double> angles_;
  int evaluations_ = 0;
};

struct NloptData {
  Tuner* tuner;
  bool tune_length;
  double fixed_length;
  double stress_scale;
  double required_margin_um;
  std::vector<Evaluation>* history;
  Progress* progress;
  int max_evaluations;
  // The last evaluation is cached: COBYLA asks for the objective and the constraint at the
  // same point one after the other.
  std::vector<double> last_x;
  Evaluation last;
};

const Evaluation& EvaluateAt(NloptData& d, const std::vector<double>& x) {
  if (x != d.last_x) {
    d.last = d.tuner->Evaluate(x[0], d.tune_length ? x[1] : d.fixed_length);
    d.last_x = x;
    d.history->push_back(d.last);
    d.progress->Update(std::min(1.0, 0.5 + 0.5 * double(d.history->size()) / (d.max_evaluations + 1)),
                       "f = " + cycloid_common::Fmt(x[0] * 1e3) + " um, " +
                           cycloid_common::Fmt(d.last.stress_MPa, "%.0f") + " MPa");
  }
  return d.last;
}

double Objective(const std::vector<double>& x, std::vector<double>& grad, void* data) {
  if (!grad.empty()) std::fill(grad.begin(), grad.end(), 0.0);  // derivative-free: never asked
  auto& d = *static_cast<NloptData*>(data);
  return EvaluateAt(d, x).stress_MPa / d.stress_scale;
}

double EdgeConstraint(const std::vector<double>& x, std::vector<double>& grad, void* data) {
  if (!grad.empty()) std::fill(grad.begin(), grad.end(), 0.0);
  auto& d = *static_cast<NloptData*>(data);
  return d.required_margin_um - EvaluateAt(d, x).edge_margin_um;  // <= 0
}

void RunCycloidCrowningTuning(const Node& root, const RunContext& ctx, Outputs& out) {
  root.CheckKnownFields({"study", "name", "description", "drive", "modification", "material", "load", "analysis", "tuning"});
  const Drive drive = cycloid_common::ParseDrive(root);
  const Material material = cycloid_common::ParseMaterial(root);
  const Node load = root["load"];
  load.CheckKnownFields({"design_torque_Nm", "max_torque_Nm"});
  const double design_torque = load["design_torque_Nm"].Positive();
  const double max_torque = load["max_torque_Nm"].Positive();
  if (max_torque < design_torque) load["max_torque_Nm"].Fail("a torque >= design_torque_Nm");
  const Node tuning = root["tuning"];
  tuning.CheckKnownFields({"coefficient_mm", "effective_length_mm", "reference_coefficient_mm", "curve_points",
                           "max_evaluations", "edge_margin_um"});
  const auto [f_lo, f_hi] = tuning["coefficient_mm"].Range();
  if (f_lo < 0 || !(f_hi > f_lo)) tuning["coefficient_mm"].Fail("a range [lo, hi] with 0 <= lo < hi");
  bool tune_length = tuning.Has("effective_length_mm");
  double l_lo = drive.face_width_mm, l_hi = drive.face_width_mm;
  if (tune_length) {
    std::tie(l_lo, l_hi) = tuning["effective_length_mm"].Range();
    if (l_lo < drive.face_width_mm)
      tuning["effective_length_mm"].Fail("a range with lo >= the face width");
    tune_length = l_hi > l_lo;
  }
  const double f_ref = tuning.NonNegativeOr("reference_coefficient_mm", 0.005);
  const int curve_points = tuning.IntegerOr("curve_points", 2, 11);
  const int max_evaluations = tuning.IntegerOr("max_evaluations", 1, 30);
  const double required_margin_um = tuning.NumberOr("edge_margin_um", 0.0);
  if (curve_points > 200) tuning["curve_points"].Fail("at most 200 points");

  LoadedOptions options;
  int per_period = 6;
  if (root.Has("analysis")) {
    const Node a = root["analysis"];
    a.CheckKnownFields({"grid", "crank_angles_per_mesh_period"});
    cycloid_common::ParseGrid(a, options);
    per_period = a.IntegerOr("crank_angles_per_mesh_period", 1, 6);
    if (per_period > 1000) a["crank_angles_per_mesh_period"].Fail("at most 1000");
  }
  const std::vector<double> angles = UniformCrankAngles(per_period, 2.0 * kPi / drive.rollers);
  Tuner tuner(drive, material, options, design_torque, max_torque, angles);

  Progress progress("cycloid_crowning_tuning", ctx.quiet);
  // 1. The stress-versus-f curve (at L = the lower length bound).
  std::vector<Evaluation> curve;
  for (int k = 0; k < curve_points; ++k) {
    const double f = f_lo + (f_hi - f_lo) * k / (curve_points - 1);
    curve.push_back(tuner.Evaluate(f, l_lo));
    progress.Update(0.5 * (k + 1) / curve_points, "scan f = " + cycloid_common::Fmt(f * 1e3) + " um");
  }
  const Evaluation reference = tuner.Evaluate(f_ref, drive.face_width_mm);
  // 2. Start from the best feasible scan point (else the one with the largest margin).
  const Evaluation* start = nullptr;
  for (const auto& e : curve)
    if (e.edge_margin_um >= required_margin_um && (!start || e.stress_MPa < start->stress_MPa)) start = &e;
  if (!start)
    for (const auto& e : curve)
      if (!start || e.edge_margin_um > start->edge_margin_um) start = &e;

  std::vector<Evaluation> history;
  NloptData data{&tuner, tune_length, l_lo, std::max(1.0, start->stress_MPa), required_margin_um,
                 &history, &progress, max_evaluations, {}, {}};
  const int nvar = tune_length ? 2 : 1;
  nlopt::opt opt(nlopt::LN_COBYLA, nvar);
  std::vector<double> lb{f_lo}, ub{f_hi}, x{start->coefficient_mm};
  if (tune_length) {
    lb.push_back(l_lo);
    ub.push_back(l_hi);
    x.push_back(l_lo);
  }
  opt.set_lower_bounds(lb);
  opt.set_upper_bounds(ub);
  opt.set_min_objective(Objective, &data);
  opt.add_inequality_constraint(EdgeConstraint, &data, 1e-3);
  opt.set_maxeval(max_evaluations);
  opt.set_xtol_rel(1e-3);
  std::vector<double> step{0.1 * (f_hi - f_lo)};
  if (tune_length) step.push_back(0.1 * (l_hi - l_lo));
  opt.set_initial_step(step);
  std::string status;
  try {
    double minf = 0;
    const nlopt::result r = opt.optimize(x, minf);
    status = r == nlopt::MAXEVAL_REACHED ? "max_evaluations reached" : "converged";
  } catch (const std::exception& e) {
    status = std::string("NLopt stopped: ") + e.what();
  }
  progress.Done();
  // The best feasible point seen anywhere (scan or optimiser).
  const Evaluation* best = nullptr;
  auto consider = [&](const Evaluation& e) {
    if (e.edge_margin_um >= required_margin_um - 1e-9 && (!best || e.stress_MPa < best->stress_MPa)) best = &e;
  };
  for (const auto& e : curve) consider(e);
  for (const auto& e : history) consider(e);
  const bool feasible = best != nullptr;
  if (!best) best = start;

  nlohmann::json jcurve = nlohmann::json::array();
  Table table;
  std::vector<double> cf, cs, cm;
  for (const auto& e : curve) {
    jcurve.push_back({{"coefficient_mm", e.coefficient_mm},
                      {"max_contact_stress_MPa", Finite(e.stress_MPa, "stress")},
                      {"edge_margin_at_max_torque_um", Finite(e.edge_margin_um, "margin")}});
    cf.push_back(e.coefficient_mm * 1e3);
    cs.push_back(e.stress_MPa);
    cm.push_back(e.edge_margin_um);
  }
  table.Add("coefficient_um", cf);
  table.Add("max_contact_stress_MPa", cs);
  table.Add("edge_margin_at_max_torque_um", cm);
  Table hist;
  std::vector<double> hf, hl, hs, hm;
  for (const auto& e : history) {
    hf.push_back(e.coefficient_mm * 1e3);
    hl.push_back(e.length_mm);
    hs.push_back(e.stress_MPa);
    hm.push_back(e.edge_margin_um);
  }
  hist.Add("coefficient_um", hf);
  hist.Add("effective_length_mm", hl);
  hist.Add("max_contact_stress_MPa", hs);
  hist.Add("edge_margin_at_max_torque_um", hm);

  nlohmann::json result = {
      {"study", "cycloid_crowning_tuning"},
      {"name", root.json().value("name", "")},
      {"optimizer", "NLopt LN_COBYLA from the best feasible point of a scan"},
      {"status", status},
      {"feasible", feasible},
      {"tuned_coefficient_mm", Finite(best->coefficient_mm, "f")},
      {"tuned_effective_length_mm", Finite(best->length_mm, "L")},
      {"tuned_max_contact_stress_MPa", Finite(best->stress_MPa, "stress")},
      {"tuned_edge_margin_at_max_torque_um", Finite(best->edge_margin_um, "margin")},
      {"reference_coefficient_mm", f_ref},
      {"reference_max_contact_stress_MPa", Finite(reference.stress_MPa, "stress")},
      {"reference_edge_margin_at_max_torque_um", Finite(reference.edge_margin_um, "margin")},
      {"design_torque_Nm", design_torque},
      {"max_torque_Nm", max_torque},
      {"crank_angles_per_mesh_period", per_period},
      {"axial_cell_mm", drive.face_width_mm / options.axial_cells},
      {"evaluations", tuner.evaluations()},
      {"curve", jcurve}};
  out.AddJson("result.json", result);
  out.Add("stress_vs_coefficient.csv", ToCsv(table));
  out.Add("history.csv", ToCsv(hist));
  PlotOptions po;
  po.title = "Peak contact stress over the mesh at the design torque";
  po.x_label = "LCM coefficient f [um]";
  po.y_label = "stress [MPa]";
  out.Add("stress_vs_coefficient.svg",
          SvgLinePlot({{"max stress", cf, cs},
                       {"tuned", {best->coefficient_mm * 1e3}, {best->stress_MPa}},
                       {"paper f", {f_ref * 1e3}, {reference.stress_MPa}}},
                      po));
  po.title = "Edge margin at the maximum torque (>= 0: off the face edges)";
  po.y_label = "margin [um]";
  out.Add("edge_margin_vs_coefficient.svg", SvgLinePlot({{"margin", cf, cm}}, po));
}

CAMOPT_REGISTER_STUDY("cycloid_crowning_tuning", RunCycloidCrowningTuning);

}  // namespace
}  // namespace camopt::studies

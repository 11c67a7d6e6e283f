#include "objectives/cycloid_crowning.h"

#include "objectives/cycloid_fields.h"
#include "objectives/evaluation_memo.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace camopt::objectives {
namespace {

cycloid::LoadedOptions WithoutMaps(cycloid::LoadedOptions o, bool edge_margin) {
  o.keep_pressure = false;
  o.crank_slope = false;  // no gear ratio in the tuning
  o.edge_margin = edge_margin;
  return o;
}

/// Value-only evaluator with a memory of every point it ran.
class CrowningEvaluator final : public Evaluator {
 public:
  CrowningEvaluator(CycloidCrowningModel& model, const CycloidCrowningSpec& spec,
                    std::function<void(const CrowningEvaluation&)> on_evaluation)
      : Evaluator(spec.tune_length ? 2 : 1, {{kCrowningStress, 0, 1}, {kCrowningEdgeMargin, 1, 1}}),
        model_(model),
        tune_length_(spec.tune_length),
        fixed_length_mm_(spec.length_lo_mm),
        memory_(0, std::move(on_evaluation)) {}

 protected:
  void DoEval(std::span<const double> x, std::span<double> y) const override {
    const CrowningEvaluation& e =
        memory_.Get(std::vector<double>(x.begin(), x.end()), [](const CrowningEvaluation&) { return true; },
                    [&] { return model_.Evaluate(x[0], tune_length_ ? x[1] : fixed_length_mm_); });
    y[0] = e.stress_MPa;
    y[1] = e.edge_margin_um;
  }
  void DoEvalWithJacobian(std::span<const double>, std::span<double>, std::span<double>) const override {
    throw std::logic_error("the cycloid crowning problem is value-only (use a derivative-free solver)");
  }
  bool has_jacobian() const override { return false; }

 private:
  CycloidCrowningModel& model_;
  bool tune_length_;
  double fixed_length_mm_;
  mutable EvaluationMemo<CrowningEvaluation> memory_;
};

}  // namespace

CycloidCrowningModel::CycloidCrowningModel(const cycloid::Drive& drive,
                                           const cycloid::Material& material,
                                           const cycloid::LoadedOptions& options,
                                           double design_torque_Nmm, double max_torque_Nmm,
                                           std::vector<double> crank_angles_rad,
                                           const cycloid::Crowning& shape)
    : drive_(drive),
      design_(drive, cycloid::Crowning{}, material, WithoutMaps(options, false)),
      maximum_(drive, cycloid::Crowning{}, material, WithoutMaps(options, true)),
      shape_(shape),
      design_torque_Nmm_(design_torque_Nmm),
      max_torque_Nmm_(max_torque_Nmm),
      angles_(std::move(crank_angles_rad)) {
  shape_.type = cycloid::CrowningType::kLogarithmic;
}

CrowningEvaluation CycloidCrowningModel::Evaluate(double coefficient_mm, double length_mm) {
  cycloid::Crowning c = shape_;
  c.coefficient_mm = std::max(0.0, coefficient_mm);
  c.effective_length_mm = length_mm;
  CrowningEvaluation e;
  e.coefficient_mm = c.coefficient_mm;
  e.length_mm = length_mm;
  const cycloid::CycleResult d = cycloid::RunCycle(design_.WithCrowning(c), design_torque_Nmm_, angles_);
  const cycloid::CycleResult m = cycloid::RunCycle(maximum_.WithCrowning(c), max_torque_Nmm_, angles_);
  e.stress_MPa = d.max_pressure_MPa;
  e.pairs = d.max_pairs_in_contact;
  e.edge_margin_um = m.end_distance_mm * 1e3;
  ++evaluations_;
  return e;
}

std::optional<CrowningEvaluation> LowestFeasibleStress(const std::vector<CrowningEvaluation>& evaluations,
                                                       double required_margin_um) {
  const CrowningEvaluation* best = nullptr;
  for (const auto& e : evaluations)
    if (e.edge_margin_um >= required_margin_um && (!best || e.stress_MPa < best->stress_MPa)) best = &e;
  if (!best) return std::nullopt;
  return *best;
}

CrowningEvaluation LargestEdgeMargin(const std::vector<CrowningEvaluation>& evaluations) {
  if (evaluations.empty()) throw std::invalid_argument("LargestEdgeMargin: no evaluation");
  const CrowningEvaluation* best = &evaluations.front();
  for (const auto& e : evaluations)
    if (e.edge_margin_um > best->edge_margin_um) best = &e;
  return *best;
}

Problem CycloidCrowningProblem(CycloidCrowningModel& model, const CycloidCrowningSpec& spec,
                               std::function<void(const CrowningEvaluation&)> on_evaluation) {
  Problem p;
  p.variables.push_back({"coefficient_mm", spec.coefficient_lo_mm, spec.coefficient_hi_mm,
                         spec.initial_coefficient_mm, 1.0});
  if (spec.tune_length)
    p.variables.push_back({"effective_length_mm", spec.length_lo_mm, spec.length_hi_mm,
                           spec.length_lo_mm, 1.0});
  p.evaluator = std::make_unique<CrowningEvaluator>(model, spec, std::move(on_evaluation));
  p.objective = kCrowningStress;
  p.objective_scale = spec.stress_scale_MPa;
  p.constraints.push_back({kCrowningEdgeMargin, spec.required_edge_margin_um, kInf, 1.0});
  return p;
}

}  // namespace camopt::objectives

namespace camopt::objectives {


std::vector<std::string> TuningVariableNames() {
  return {"coefficient_mm", "effective_length_mm", "end_drop_mm", "flat_length_mm",
          "radius_mm",      "delta_position_um",   "delta_radius_um"};
}

std::string TuningVariableAllowed(const std::string& name, cycloid::CrowningType type) {
  if (name == "delta_position_um" || name == "delta_radius_um") return "";
  return CrowningParameterApplies(name, type).value_or("not a tuning variable");
}

CycloidTuningModel::CycloidTuningModel(const cycloid::Drive& drive, const cycloid::Crowning& crowning,
                                       const cycloid::Material& material,
                                       const cycloid::LoadedOptions& options, double design_torque_Nmm,
                                       double max_torque_Nmm, std::vector<double> crank_angles_rad,
                                       std::vector<std::string> variables, double temperature_MPa)
    : drive_(drive),
      crowning_(crowning),
      design_(drive, crowning, material,
              [&] {
                cycloid::LoadedOptions o = options;
                o.keep_pressure = true;  // the derivatives need the converged pressures
                o.crank_slope = false;
                o.edge_margin = false;
                o.sensitivity_tolerance = CycloidSensitivityTolerance(options);
                return o;
              }()),
      maximum_(drive, crowning, material,
               [&] {
                 cycloid::LoadedOptions o = options;
                 o.keep_pressure = true;
                 o.crank_slope = false;
                 o.edge_margin = true;
                 o.sensitivity_tolerance = CycloidSensitivityTolerance(options);
                 return o;
               }()),
      design_torque_Nmm_(design_torque_Nmm),
      max_torque_Nmm_(max_torque_Nmm),
      angles_(std::move(crank_angles_rad)),
      variables_(std::move(variables)),
      temperature_MPa_(temperature_MPa) {
  for (const std::string& v : variables_)
    if (const std::string why = TuningVariableAllowed(v, crowning.type); !why.empty())
      throw std::invalid_argument("tuning variable " + v + ": " + why);
}

std::pair<cycloid::Drive, cycloid::Crowning> CycloidTuningModel::Design(const std::vector<double>& x) const {
  if (x.size() != variables_.size()) throw std::invalid_argument("CycloidTuningModel: one value per variable");
  cycloid::Drive d = drive_;
  cycloid::Crowning c = crowning_;
  for (size_t j = 0; j < x.size(); ++j) {
    SetCycloidField(variables_[j], x[j], d, c);
    if (variables_[j] == "coefficient_mm") c.coefficient_mm = std::max(0.0, x[j]);  // negative requests are 0
  }
  return {d, c};
}

namespace {
// A joint-tuning evaluation's values (no gradients) from its two cycles: design torque (stress,
// LTE, β0, pair loads) and maximum torque (end distances); n1 rollers.
TuningEvaluation Values(const cycloid::CycleResult& dc, const cycloid::CycleResult& mc, size_t n1,
                        double temperature_MPa) {
  TuningEvaluation e;
  e.smooth_stress_MPa = cycloid::SmoothPeakPressure(dc, temperature_MPa);
  e.stress_MPa = dc.max_pressure_MPa;
  e.edge_margin_um = mc.end_distance_mm * 1e3;
  for (const cycloid::MeshLoad& m : mc.meshes) e.end_distance_um.push_back(m.end_distance_mm * 1e3);
  e.lte_peak_to_peak_arcsec = dc.lte_peak_to_peak_arcsec;
  for (const cycloid::MeshLoad& m : dc.meshes) e.unloaded_te_arcsec.push_back(m.unloaded_rotation_rad * cycloid::kArcsecPerRad);
  e.max_pair_load_N = dc.max_pair_load_N;
  e.pairs = dc.max_pairs_in_contact;
  e.converged = dc.converged && mc.converged;
  e.pair_peak_MPa.assign(dc.meshes.size() * n1, 0.0);
  for (size_t k = 0; k < dc.meshes.size(); ++k)
    for (const cycloid::PairLoad& p : dc.meshes[k].pairs) e.pair_peak_MPa[k * n1 + size_t(p.roller)] = p.max_pressure_MPa;
  return e;
}
}  // namespace

TuningEvaluation CycloidTuningModel::EvaluatedOn(const std::vector<size_t>& angle_indices) const {
  if (!last_design_ || !last_max_) throw std::logic_error("CycloidTuningModel::EvaluatedOn: no evaluation yet");
  std::vector<double> angles;
  std::vector<cycloid::MeshLoad> design, maximum;
  for (size_t k : angle_indices) {
    angles.push_back(angles_.at(k));
    design.push_back(last_design_->meshes.at(k));
    maximum.push_back(last_max_->meshes.at(k));
  }
  const cycloid::Drive drive = Design(last_x_).first;
  TuningEvaluation e = Values(cycloid::SummariseCycle(drive, std::move(design), angles),
                              cycloid::SummariseCycle(drive, std::move(maximum), angles),
                              size_t(drive_.rollers), temperature_MPa_);
  e.x = last_x_;
  return e;
}

TuningEvaluation CycloidTuningModel::Evaluate(const std::vector<double>& x, bool with_gradient) {
  const auto [d, c] = Design(x);
  const cycloid::LoadedTca des = design_.WithModification(d.delta_position_mm, d.delta_radius_mm).WithCrowning(c);
  const cycloid::LoadedTca max = maximum_.WithModification(d.delta_position_mm, d.delta_radius_mm).WithCrowning(c);
  if (!(last_x_ == x && last_design_ && last_max_)) {
    last_x_ = x;
    last_design_ = cycloid::RunCycle(des, design_torque_Nmm_, angles_);
    last_max_ = cycloid::RunCycle(max, max_torque_Nmm_, angles_);
    ++evaluations_;
  }
  const cycloid::CycleResult& dc = *last_design_;
  const cycloid::CycleResult& mc = *last_max_;
  TuningEvaluation e = Values(dc, mc, size_t(drive_.rollers), temperature_MPa_);
  e.x = x;
  if (!with_gradient) return e;
  ++gradient_evaluations_;
  const size_t nv = variables_.size(), na = angles_.size(), n1 = size_t(drive_.rollers);
  std::vector<std::string> params;
  std::vector<double> factor;
  for (const std::string& v : variables_) {
    const auto [p, f] = CycloidModelParameter(v);
    params.push_back(p);
    factor.push_back(f);
  }
  const std::vector<cycloid::CycleDerivative> dd = cycloid::DifferentiateCycle(des, dc, params, temperature_MPa_);
  const std::vector<cycloid::CycleDerivative> dm = cycloid::DifferentiateCycle(max, mc, params, temperature_MPa_);
  e.d_smooth_stress.resize(nv);
  e.d_stress.resize(nv);
  e.d_lte.resize(nv);
  e.d_end_distance.assign(na * nv, 0.0);
  e.d_unloaded_te.assign(na * nv, 0.0);
  e.d_pair_peak.assign(na * n1 * nv, 0.0);
  for (size_t j = 0; j < nv; ++j) {
    for (size_t k = 0; k < na; ++k)
      for (size_t i = 0; i < dc.meshes[k].pairs.size(); ++i)
        e.d_pair_peak[(k * n1 + size_t(dc.meshes[k].pairs[i].roller)) * nv + j] =
            dd[j].pair_max_pressure_MPa[k][i] * factor[j];
    // coefficient_mm is clamped at 0 (Design): its derivative is the one-sided one above 0.
    e.d_smooth_stress[j] = dd[j].smooth_peak_MPa * factor[j];
    e.d_stress[j] = dd[j].max_pressure_MPa * factor[j];
    e.d_lte[j] = dd[j].lte_peak_to_peak_arcsec * factor[j];
    for (size_t k = 0; k < na; ++k) {
      e.d_end_distance[k * nv + j] = dm[j].end_distance_per_angle_mm[k] * 1e3 * factor[j];
      e.d_unloaded_te[k * nv + j] = dd[j].unloaded_rotation_rad[k] * cycloid::kArcsecPerRad * factor[j];
    }
    e.converged = e.converged && dd[j].converged && dm[j].converged;
  }
  return e;
}

namespace {

// Outputs: [objective][end distance per angle][LTE p-p][β0 per angle] and, in the epigraph
// form, [pair peak − t per (angle, roller)] after them; x = [model variables][t (epigraph)].
class TuningEvaluator final : public Evaluator {
 public:
  TuningEvaluator(CycloidTuningModel& model, bool epigraph,
                  std::function<void(const TuningEvaluation&)> on_evaluation)
      : Evaluator(int(model.variables().size()) + (epigraph ? 1 : 0), Blocks(model, epigraph)),
        model_(model),
        epigraph_(epigraph),
        memory_(0, std::move(on_evaluation)) {}

 protected:
  void DoEval(std::span<const double> x, std::span<double> y) const override {
    Fill(Get(x, false), x, y);
  }
  void DoEvalWithJacobian(std::span<const double> x, std::span<double> y,
                          std::span<double> jacobian) const override {
    const TuningEvaluation& e = Get(x, true);
    Fill(e, x, y);
    const size_t n = size_t(num_vars()), nv = model_.variables().size(), na = e.end_distance_um.size();
    std::fill(jacobian.begin(), jacobian.end(), 0.0);
    for (size_t j = 0; j < nv; ++j) {
      jacobian[j] = epigraph_ ? 0.0 : e.d_smooth_stress[j];
      for (size_t k = 0; k < na; ++k) jacobian[(1 + k) * n + j] = e.d_end_distance[k * nv + j];
      jacobian[(1 + na) * n + j] = e.d_lte[j];
      for (size_t k = 0; k < na; ++k) jacobian[(2 + na + k) * n + j] = e.d_unloaded_te[k * nv + j];
    }
    if (!epigraph_) return;
    jacobian[nv] = 1.0;  // d t / d t
    const size_t first = 2 + 2 * na;
    for (size_t s = 0; s < e.pair_peak_MPa.size(); ++s) {
      for (size_t j = 0; j < nv; ++j) jacobian[(first + s) * n + j] = e.d_pair_peak[s * nv + j];
      jacobian[(first + s) * n + nv] = -1.0;
    }
  }

 private:
  static std::vector<OutputBlock> Blocks(const CycloidTuningModel& model, bool epigraph) {
    const int na = int(model.crank_angles().size());
    std::vector<OutputBlock> b = {{epigraph ? kTuningPeakBound : kTuningSmoothStress, 0, 1},
                                  {kTuningEndDistance, 1, na},
                                  {kTuningLte, 1 + na, 1},
                                  {kTuningBacklash, 2 + na, na}};
    if (epigraph) b.push_back({kTuningStressExcess, 2 + 2 * na, na * model.drive().rollers});
    return b;
  }
  void Fill(const TuningEvaluation& e, std::span<const double> x, std::span<double> y) const {
    const size_t nv = model_.variables().size();
    y[0] = epigraph_ ? x[nv] : e.smooth_stress_MPa;
    for (size_t k = 0; k < e.end_distance_um.size(); ++k) y[1 + k] = e.end_distance_um[k];
    const size_t na = e.end_distance_um.size();
    y[1 + na] = e.lte_peak_to_peak_arcsec;
    for (size_t k = 0; k < na; ++k) y[2 + na + k] = e.unloaded_te_arcsec[k];
    if (epigraph_)
      for (size_t s = 0; s < e.pair_peak_MPa.size(); ++s) y[2 + 2 * na + s] = e.pair_peak_MPa[s] - x[nv];
  }
  const TuningEvaluation& Get(std::span<const double> x, bool gradient) const {
    const std::vector<double> key(x.begin(), x.begin() + std::ptrdiff_t(model_.variables().size()));
    return memory_.Get(
        key, [&](const TuningEvaluation& m) { return !gradient || !m.d_smooth_stress.empty(); },
        [&] { return model_.Evaluate(key, gradient); });
  }

  CycloidTuningModel& model_;
  bool epigraph_;
  mutable EvaluationMemo<TuningEvaluation> memory_;
};

}  // namespace

Problem CycloidTuningProblem(CycloidTuningModel& model, const CycloidTuningSpec& spec,
                             std::function<void(const TuningEvaluation&)> on_evaluation) {
  if (spec.variables.size() != model.variables().size())
    throw std::invalid_argument("CycloidTuningProblem: one variable per model variable");
  Problem p;
  p.variables = spec.variables;
  p.evaluator = std::make_unique<TuningEvaluator>(model, spec.epigraph, std::move(on_evaluation));
  p.objective = spec.epigraph ? kTuningPeakBound : kTuningSmoothStress;
  p.objective_scale = spec.stress_scale_MPa;
  if (spec.epigraph) {
    p.variables.push_back({kTuningPeakBound, 0.0, kInf, spec.initial_peak_bound_MPa, spec.stress_scale_MPa});
    p.constraints.push_back({kTuningStressExcess, -kInf, 0.0, spec.stress_scale_MPa});
  }
  p.constraints.push_back({kTuningEndDistance, spec.required_end_distance_um, kInf, 10.0});
  if (std::isfinite(spec.min_unloaded_te_arcsec))
    p.constraints.push_back({kTuningBacklash, spec.min_unloaded_te_arcsec, kInf, 1.0});
  if (std::isfinite(spec.max_lte_peak_to_peak_arcsec))
    p.constraints.push_back({kTuningLte, -kInf, spec.max_lte_peak_to_peak_arcsec, 1.0});
  return p;
}

}  // namespace camopt::objectives

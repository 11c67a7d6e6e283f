#include "objectives/cycloid_crowning.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace camopt::objectives {
namespace {

cycloid::LoadedOptions WithoutMaps(cycloid::LoadedOptions o, bool edge_margin) {
  o.keep_pressure = false;
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
        on_evaluation_(std::move(on_evaluation)) {}

 protected:
  void DoEval(std::span<const double> x, std::span<double> y) const override {
    const std::vector<double> key(x.begin(), x.end());
    auto it = std::find_if(memory_.begin(), memory_.end(),
                           [&](const auto& m) { return m.first == key; });
    if (it == memory_.end()) {
      const CrowningEvaluation e = model_.Evaluate(x[0], tune_length_ ? x[1] : fixed_length_mm_);
      memory_.push_back({key, e});
      if (on_evaluation_) on_evaluation_(e);
      it = std::prev(memory_.end());
    }
    y[0] = it->second.stress_MPa;
    y[1] = it->second.edge_margin_um;
  }
  void DoEvalWithJacobian(std::span<const double>, std::span<double>, std::span<double>) const override {
    throw std::logic_error("the cycloid crowning problem is value-only (use a derivative-free solver)");
  }

 private:
  CycloidCrowningModel& model_;
  bool tune_length_;
  double fixed_length_mm_;
  std::function<void(const CrowningEvaluation&)> on_evaluation_;
  mutable std::vector<std::pair<std::vector<double>, CrowningEvaluation>> memory_;
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

// See lcr_sizing3d.h. The LCR pipeline and the slices model instantiated for ceres::Jet<double, 8>.
#include "sizing/lcr_sizing3d.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <stdexcept>

#include "model/common/geometry.h"
#include "model/contact/hertz.h"
#include "model/contact/roller_half_space.h"
#include "model/lcr/contact3d_edge.h"
#include "model/lcr/cycle.h"
#include "model/lcr/forces.h"
#include "model/lcr/profile.h"

namespace camopt::sizing {
using namespace camopt::objectives;
namespace {

// e, r_dA, r_dB, d_rA, d_rB (at most 6 line variables) and two crowning variables: the usual
// problems; the larger Jet only when more crowning parameters or the lengths are variables.
constexpr int kJetSize = 8;
constexpr int kJetSizeLarge = 14;  // 6 + 3 crowning pairs + roller length + cam thickness
// The solvers meet constraints to about their tolerance; the 3D stress limit is tightened by more
// than the line limits of lcr_min_size.cc (1e-5) because its rows sit at fixed angles of the dense
// grid, whose maximum may move to a neighbouring angle (a second-order change, ~1e-5 here).
constexpr double kStressMargin3D = 1e-4;
constexpr double kEdgeMargin = 1e-3;       // the edge rows: >= this (dimensionless)
constexpr double kLimitMargin = 1e-5;      // as lcr_min_size.cc
constexpr double kLengthMargin_mm = 1e-4;  // as lcr_min_size.cc
constexpr double kNearFraction = 0.03;     // contacts within 3% of the limit get rows
constexpr int kPeaksPerCam = 4;
// Each fresh stress peak also gets rows this many dense-check angles either side: a tracked
// contact's peak moves along the angle as the design changes (a few dense steps per polish round),
// and rows that bracket it let the next dense check find it held more often (the crowned example:
// 23 -> 16 polish solves, the outer diameter within 0.005 mm).
constexpr int kPeakNeighbours = 2;
constexpr int kEdgeContacts = 6;           // overload contacts checked per cam
constexpr int kMaxRounds = 8;
// The verification (header step 3): tightening rounds, and the largest pressure at a contact's
// end cell as a share of the peak that still counts as "off the ends" (a crowned contact that
// ends inside the roller has exactly 0 there; an edge-loaded one has the peak itself there).
constexpr int kVerifyRounds = 3;
constexpr double kEdgeShareLimit = 0.01;

// The torque of the edge rows over the design torque: the overload's when one is given (the end
// margin falls as the load grows, so it holds at the design torque too), else 1.
double EdgeTorqueRatio(const LcrSizingSpec& s, const LcrSizing3DSpec& s3) {
  return s3.overload_torque_Nmm > 0 ? s3.overload_torque_Nmm / s.output_torque_Nmm : 1.0;
}

int RollerVariables(const LcrSizingSpec& s) { return s.fixed_roller_diameter_mm ? 0 : (s.same_roller ? 1 : 2); }
int BaseVariables(const LcrSizingSpec& s) { return 4 + RollerVariables(s); }

template <typename T>
lcr::Reducer<T> DesignOf(const LcrSizingSpec& s, std::span<const T> x) {
  const int rollers = RollerVariables(s);
  const T rr_a = rollers > 0 ? x[3] / T(2.0) : T(*s.fixed_roller_diameter_mm / 2.0);
  const T rr_b = rollers == 2 ? x[4] / T(2.0) : rr_a;
  lcr::Reducer<T> r;
  r.eccentricity = x[0];
  r.input = {s.lobes_a, s.rollers_a, x[1], rr_a, T(s.roller_length_mm), T(s.cam_thickness_mm)};
  r.output = {s.lobes_b, s.rollers_b, x[2], rr_b, T(s.roller_length_mm), T(s.cam_thickness_mm)};
  return r;
}

// The crowning of one cam: the fixed one with the variables of the header's order set.
template <typename T>
lcr::RollerCrowning<T> CrowningOf(const LcrSizing3DSpec& s3, std::span<const T> x, int base_vars, int side) {
  lcr::RollerCrowning<T> c = s3.crowning.cast<T>();
  int o = base_vars;
  if (s3.coefficient_range_mm) c.coefficient = x[o + side], o += 2;
  if (s3.radius_range_mm) c.radius = x[o + side], o += 2;
  if (s3.flat_length_range_mm) c.flat_length = x[o + side], o += 2;
  return c;
}

// The roller length and cam thickness variables (header's order) set on both cams of r.
template <typename T>
void SetLengths(const LcrSizing3DSpec& s3, std::span<const T> x, int base_vars, lcr::Reducer<T>& r) {
  int o = base_vars + s3.extra_variables() - int(bool(s3.roller_length_range_mm)) - int(bool(s3.cam_thickness_range_mm));
  if (s3.roller_length_range_mm) r.input.roller_length = r.output.roller_length = x[o++];
  if (s3.cam_thickness_range_mm) r.input.cam_thickness = r.output.cam_thickness = x[o++];
}

// Margin of one contact (header): the line margin of lcr_sizing.cc with the slices peak.
template <typename T>
T StressMargin3D(const LcrSizing3DSpec& s3, double p_lim, double e_star, const lcr::CamSide<T>& cam,
                 const T& force, const T& curvature, const lcr::RollerCrowning<T>& crowning) {
  const T rr = cam.roller_radius;
  const T r_eff = rr * (T(1.0) - rr * curvature);
  if (!(Value(r_eff) > 0) || !(Value(force) > 0)) {
    const T c = contact::LineContactLoadPerRadius(T(p_lim), cam.contact_length(), T(e_star));
    return (r_eff - force / c) / rr;
  }
  const auto sol = lcr::RollerContactSlices(force, r_eff, cam.contact_length(), e_star, crowning,
                                            T(s3.contact.misalignment_rad), s3.contact.slices);
  const T ratio = sol.peak_pressure / T(p_lim);
  return r_eff / rr * (T(1.0) - ratio * ratio);
}

template <typename T>
T EdgeMarginAt(const LcrSizing3DSpec& s3, double e_star, const lcr::CamSide<T>& cam, const T& force,
               const T& curvature, const lcr::RollerCrowning<T>& crowning) {
  const T rr = cam.roller_radius;
  const T r_eff = rr * (T(1.0) - rr * curvature);
  if (!(Value(r_eff) > 0) || !(Value(force) > 0)) return T(-1.0);  // undercut: no contact to assess
  const T gamma(s3.contact.misalignment_rad);
  const auto sol =
      lcr::RollerContactSlices(force, r_eff, cam.contact_length(), e_star, crowning, gamma, s3.contact.slices);
  return lcr::EdgeMargin(sol, force, r_eff, cam.contact_length(), e_star, crowning, gamma);
}

// Force and curvature of one roller of one cam at θ (the load stage, no friction: linear in torque).
template <typename T>
std::pair<T, T> ContactAt(const LcrSizingSpec& s, const lcr::Reducer<T>& r, int side, double theta, int roller) {
  const lcr::LoadCase load{s.output_torque_Nmm, 0.0, 0.0};
  const lcr::SideLoads<T> sl = lcr::AnalyzeSide(r, s.material, load, side == 0 ? lcr::Side::kInput : lcr::Side::kOutput,
                                                T(theta), lcr::Stages{true, false, false});
  return {sl.force[roller], sl.contacts[roller].curvature};
}

// The 3D rows (stress margins per cam, then edge margins per cam).
template <typename T>
void Evaluate3D(const LcrSizingSpec& s, const LcrSizing3DSpec& s3, double p_lim, const LcrTracked3D& tr,
                std::span<const T> x, std::span<T> y) {
  const int nb = BaseVariables(s);
  lcr::Reducer<T> r = DesignOf(s, x);
  SetLengths(s3, x, nb, r);
  const double e_star = s.material.composite_modulus_MPa();
  const double edge_torque = EdgeTorqueRatio(s, s3);
  size_t o = 0;
  try {
    for (int side = 0; side < 2; ++side)
      for (const LcrContactSample& c : tr.stress)
        if (c.side == side) {
          const auto [f, k] = ContactAt(s, r, side, c.theta_rad, c.roller);
          y[o++] = StressMargin3D(s3, p_lim, e_star, r.side(side == 0 ? lcr::Side::kInput : lcr::Side::kOutput), f, k,
                                  CrowningOf(s3, x, nb, side));
        }
    for (int side = 0; side < 2; ++side)
      for (const LcrContactSample& c : tr.edge)
        if (c.side == side) {
          const auto [f, k] = ContactAt(s, r, side, c.theta_rad, c.roller);
          y[o++] = EdgeMarginAt(s3, e_star, r.side(side == 0 ? lcr::Side::kInput : lcr::Side::kOutput),
                                T(edge_torque) * f, k, CrowningOf(s3, x, nb, side));
        }
  } catch (const std::exception&) {
    for (; o < y.size(); ++o) y[o] = T(std::numeric_limits<double>::quiet_NaN());
  }
}

int Count(const std::vector<LcrContactSample>& v, int side) {
  return int(std::count_if(v.begin(), v.end(), [&](const LcrContactSample& c) { return c.side == side; }));
}

// The polish problem's evaluator: the base problem's outputs (crowning columns zero) then the 3D
// rows. Values are computed together with the Jacobian and both kept for the last x: an
// interior-point or SQP iteration asks for the values at a trial point and, when it accepts the
// point (most iterations), for the Jacobian at the same point. The Jet evaluation costs little
// more than the double one here (the slices solves run in double either way and add one implicit
// step for the derivatives, roller_slices.h), and its value parts are the double evaluation's
// numbers (the same operations on the values), so the values do not change.
class Composite final : public Evaluator {
 public:
  Composite(std::unique_ptr<Evaluator> base, std::unique_ptr<Evaluator> rows, int num_vars,
            std::vector<OutputBlock> blocks)
      : Evaluator(num_vars, std::move(blocks)), base_(std::move(base)), rows_(std::move(rows)) {}

 protected:
  void DoEval(std::span<const double> x, std::span<double> y) const override {
    const std::lock_guard<std::mutex> lock(mutex_);
    Fill(x);
    std::copy(y_.begin(), y_.end(), y.begin());
  }
  void DoEvalWithJacobian(std::span<const double> x, std::span<double> y, std::span<double> jac) const override {
    const std::lock_guard<std::mutex> lock(mutex_);
    Fill(x);
    std::copy(y_.begin(), y_.end(), y.begin());
    std::copy(jac_.begin(), jac_.end(), jac.begin());
  }

 private:
  // Values and Jacobian at x into y_, jac_ (unless x is the last point).
  void Fill(std::span<const double> x) const {
    if (!x_.empty() && std::equal(x.begin(), x.end(), x_.begin(), x_.end())) return;
    const int n = num_vars(), nb = base_->num_vars(), mb = base_->num_outputs(), mr = rows_->num_outputs();
    y_.assign(size_t(num_outputs()), 0.0);
    jac_.assign(size_t(num_outputs()) * n, 0.0);
    std::vector<double> jb(size_t(mb) * nb);
    x_.clear();  // (a throw below leaves no cached point)
    base_->EvalWithJacobian(x.first(nb), std::span<double>(y_).first(mb), jb);
    for (int i = 0; i < mb; ++i)
      for (int j = 0; j < nb; ++j) jac_[size_t(i) * n + j] = jb[size_t(i) * nb + j];
    rows_->EvalWithJacobian(x, std::span<double>(y_).subspan(mb), std::span<double>(jac_).subspan(size_t(mb) * n, size_t(mr) * n));
    x_.assign(x.begin(), x.end());
  }

  std::unique_ptr<Evaluator> base_, rows_;
  mutable std::mutex mutex_;
  mutable std::vector<double> x_, y_, jac_;
};

LcrSizingSpec Tightened(const LcrSizingSpec& spec) {
  LcrSizingSpec t = spec;
  t.limits.contact_stress_MPa = kInf;  // held by the 3D rows
  t.limits.roller_load_N *= 1 - kLimitMargin;
  t.limits.roller_gap_mm += kLengthMargin_mm;
  t.limits.undercut_margin_mm += kLengthMargin_mm;
  if (t.limits.min_efficiency > 0) t.limits.min_efficiency *= 1 + kLimitMargin;
  t.form = LcrConstraintForm::kActiveSet;
  return t;
}

// A start value clamped into its range with 1% of the range's width to spare at either end: a
// start on a bound makes Ipopt push it off by its own rule and SLSQP start on an active bound.
double Interior(double value, const std::array<double, 2>& range) {
  const double pad = 0.01 * (range[1] - range[0]);
  return std::clamp(value, range[0] + pad, range[1] - pad);
}

void AddUnique(std::vector<LcrContactSample>& to, const LcrContactSample& c, bool& changed) {
  if (std::find(to.begin(), to.end(), c) != to.end()) return;
  to.push_back(c);
  changed = true;
}

struct DenseResult {
  LcrDenseCheck check;
  LcrContact3DCheck contact;
  LcrActiveSet near;
  LcrTracked3D fresh;  // contacts near a limit
};

// Step 2's dense check of x. @throws std::domain_error for a degenerate design.
DenseResult Dense(const LcrSizingSpec& spec, const LcrSizing3DSpec& s3, std::span<const double> x, int steps) {
  DenseResult d;
  const int nb = BaseVariables(spec);
  lcr::Reducer<double> r = LcrDesign(spec, x.first(nb));
  SetLengths(s3, x, nb, r);
  LcrSizingSpec no_stress = spec;
  no_stress.limits.contact_stress_MPa = kInf;
  d.check = DenseCheck(no_stress, r, steps, &d.near);
  const double e_star = spec.material.composite_modulus_MPa();
  const lcr::LoadCase load{spec.output_torque_Nmm, 0.0, 0.0};
  const lcr::CycleSeries series = lcr::AnalyzeCycle(r, spec.material, load, steps, lcr::Stages{true, false, false});
  lcr::ContactModelOptions o = s3.contact;
  o.model = lcr::ContactModel::kSlices;
  const double p_lim = spec.limits.contact_stress_MPa;
  const double overload = EdgeTorqueRatio(spec, s3);
  for (int k = 0; k < 2; ++k) {
    const lcr::Side side = k == 0 ? lcr::Side::kInput : lcr::Side::kOutput;
    const lcr::SideSeries& ss = k == 0 ? series.input : series.output;
    const lcr::RollerCrowning<double> crown = CrowningOf<double>(s3, x, nb, k);
    lcr::Contact3DCycleSide c3 = lcr::AnalyzeCycleContact3D(r, side, series, e_star, crown, o);
    d.check.max_stress_MPa[k] = c3.max_contact_stress_MPa;
    // The roller of an angle's largest (estimated) pressure: the one with that angle's force.
    auto roller_of = [&](int i) {
      const auto& f = ss.roller_force_N[i];
      for (size_t j = 0; j < f.size(); ++j)
        if (f[j] == c3.stress_force_N[i]) return int(j);
      return -1;
    };
    const double period = LcrLoadPeriod(spec, side);
    const double vmax = c3.max_contact_stress_MPa;
    const double threshold = (1 - kNearFraction) * std::min(p_lim, vmax);
    std::vector<std::pair<double, int>> peaks;
    if (c3.worst_angle >= 0) peaks.push_back({kInf, c3.worst_angle});
    const auto& v = c3.max_stress_MPa;
    for (int i = 0; i < steps; ++i)
      if (v[i] >= threshold && v[i] >= v[(i + steps - 1) % steps] && v[i] >= v[(i + 1) % steps]) peaks.push_back({v[i], i});
    std::stable_sort(peaks.begin(), peaks.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    std::vector<double> chosen;
    bool changed = false;  // (unused here: the caller merges)
    for (const auto& [value, i] : peaks) {
      const double theta = series.theta_rad[i];
      const bool seen = std::any_of(chosen.begin(), chosen.end(),
                                    [&](double t) { return PhaseDistance(t, theta, period) < period / 8; });
      const int roller = i == c3.worst_angle ? c3.worst_roller : roller_of(i);
      if (seen || roller < 0) continue;
      chosen.push_back(theta);
      AddUnique(d.fresh.stress, {k, theta, roller}, changed);
      for (const int dd : {-kPeakNeighbours, kPeakNeighbours}) {
        const int j = (i + dd + steps) % steps;
        if (const int rj = roller_of(j); rj >= 0) AddUnique(d.fresh.stress, {k, series.theta_rad[j], rj}, changed);
      }
      if (int(chosen.size()) == kPeaksPerCam) break;
    }
    // The edge torque (overload, else design): exact slices solves at the largest forces (one per
    // angle, distinct phases).
    {
      std::vector<double> fm(steps);
      std::vector<int> jm(steps);
      const int rollers = ss.roller_force_N.rollers();
      for (int i = 0; i < steps; ++i) {
        const double* const f = ss.roller_force_N.row(size_t(i));
        jm[i] = int(std::max_element(f, f + rollers) - f);
        fm[i] = f[jm[i]];
      }
      std::vector<std::pair<double, std::pair<int, int>>> forces;
      for (int i = 0; i < steps; ++i)
        if (fm[i] > 0 && fm[i] >= fm[(i + steps - 1) % steps] && fm[i] >= fm[(i + 1) % steps])
          forces.push_back({fm[i], {i, jm[i]}});
      std::stable_sort(forces.begin(), forces.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
      std::vector<double> used;
      const lcr::CamSide<double>& cam = r.side(side);
      for (const auto& [f, ij] : forces) {
        const double theta = series.theta_rad[ij.first];
        if (std::any_of(used.begin(), used.end(), [&](double t) { return PhaseDistance(t, theta, period) < period / 16; }))
          continue;
        used.push_back(theta);
        const auto rc = lcr::RollerContacts(r, side, theta);
        const double m = EdgeMarginAt(s3, e_star, cam, overload * f, rc[ij.second].curvature, crown);
        if (m < d.contact.overload_edge_margin[k]) d.contact.overload_edge_margin[k] = m;
        d.contact.overload_edge_loaded[k] = d.contact.overload_edge_loaded[k] || m <= 0;
        if (m < 0.1) AddUnique(d.fresh.edge, {k, theta, ij.second}, changed);
        if (int(used.size()) == kEdgeContacts) break;
      }
      if (Count(d.fresh.edge, k) == 0) {
        // Keep one row per cam at the largest force so that the end constraint is always present.
        if (!forces.empty())
          AddUnique(d.fresh.edge, {k, series.theta_rad[forces[0].second.first], forces[0].second.second}, changed);
      }
    }
    d.contact.design[k] = std::move(c3);
  }
  const double stress = std::max(d.check.max_stress_MPa[0], d.check.max_stress_MPa[1]);
  if (!(stress <= p_lim)) d.check.violations.push_back({"contact_stress_MPa", stress, p_lim});
  {
    const double m = std::min(d.contact.overload_edge_margin[0], d.contact.overload_edge_margin[1]);
    if (!(m > 0))
      d.check.violations.push_back({s3.overload_torque_Nmm > 0 ? "overload_edge_margin" : "edge_margin", m, 0.0});
  }
  return d;
}

}  // namespace

Problem MakeLcrSizing3DProblem(const LcrSizingSpec& base, const LcrSizing3DSpec& s3, double stress_limit_MPa,
                               const LcrTracked3D& tracked) {
  Problem p = MakeLcrSizingProblem(base);
  const int nb = p.num_vars();
  // The start values are the fixed crowning's (SolveLcrMinSize3D sets them inside the ranges).
  const auto pair = [&](const std::optional<std::array<double, 2>>& range, const char* name, double value) {
    if (!range) return;
    const auto [lo, hi] = *range;
    for (const char* side : {"input", "output"})
      p.variables.push_back({std::string(side) + "_crowning_" + name, lo, hi, std::clamp(value, lo, hi),
                             std::max(hi, 1e-3) / 2});
  };
  pair(s3.coefficient_range_mm, "coefficient_mm", s3.crowning.coefficient);
  pair(s3.radius_range_mm, "radius_mm", s3.crowning.radius);
  pair(s3.flat_length_range_mm, "flat_length_mm", s3.crowning.flat_length);
  if (s3.roller_length_range_mm) {
    const auto [lo, hi] = *s3.roller_length_range_mm;
    p.variables.push_back({"roller_length_mm", lo, hi, std::clamp(base.roller_length_mm, lo, hi), hi / 2});
  }
  if (s3.cam_thickness_range_mm) {
    const auto [lo, hi] = *s3.cam_thickness_range_mm;
    p.variables.push_back({"cam_thickness_mm", lo, hi, std::clamp(base.cam_thickness_mm, lo, hi), hi / 2});
  }
  std::vector<OutputBlock> rows;
  int offset = 0;
  auto add = [&](const std::string& name, int size) {
    rows.push_back({name, offset, size});
    offset += size;
  };
  add("input_stress_margin_3d", Count(tracked.stress, 0));
  add("output_stress_margin_3d", Count(tracked.stress, 1));
  add("input_edge_margin", Count(tracked.edge, 0));
  add("output_edge_margin", Count(tracked.edge, 1));
  const LcrSizingSpec s = base;
  const LcrSizing3DSpec spec3 = s3;
  const LcrTracked3D tr = tracked;
  const int n = p.num_vars();
  const auto f = [s, spec3, tr, stress_limit_MPa](auto x, auto y) { Evaluate3D(s, spec3, stress_limit_MPa, tr, x, y); };
  auto row_eval = n <= kJetSize ? MakeEvaluator<kJetSize>(n, rows, f) : MakeEvaluator<kJetSizeLarge>(n, rows, f);
  std::vector<OutputBlock> blocks = p.evaluator->blocks();
  const int mb = p.evaluator->num_outputs();
  for (OutputBlock b : rows) {
    b.offset += mb;
    blocks.push_back(b);
  }
  p.evaluator = std::make_unique<Composite>(std::move(p.evaluator), std::move(row_eval), n, blocks);
  for (const OutputBlock& b : rows) {
    if (b.size == 0) continue;
    const bool edge = b.name.find("edge") != std::string::npos;
    p.constraints.push_back({b.name, edge ? kEdgeMargin : 0.0, kInf, 1.0});
  }
  (void)nb;
  return p;
}

namespace {

// Sets the outcome's design, crowning, start and evaluation counts from the polish's state.
void StorePolish(const LcrSizingSpec& spec, const LcrSizing3DSpec& s, const std::vector<double>& x,
                 const LcrActiveSet& active, const LcrTracked3D& tracked, int values, int gradients, int iterations,
                 LcrMinSize3DOutcome& out) {
  const int nb = BaseVariables(spec);
  LcrMinSizeOutcome& o = out.outcome;
  o.x = x;
  o.design = LcrDesign(spec, std::span<const double>(x).first(nb));
  SetLengths<double>(s, x, nb, *o.design);
  o.active = active;
  o.result.value_evaluations = values;
  o.result.gradient_evaluations = gradients;
  o.result.iterations = iterations;
  // One start: the line optimum (the multistart of the line search chose it).
  o.starts = {LcrStartOutcome{o.result.status, o.converged, o.converged ? o.check->outer_diameter_mm : 0.0}};
  for (int k = 0; k < 2; ++k) out.crowning[k] = CrowningOf<double>(s, x, nb, k);
  out.tracked = tracked;
}

// Header step 2 from out.outcome.x (its tracked sets and active set) with the 3D stress rows at
// p_fast (the study's limit, or the limit tightened by the verification): rounds of polish and
// dense check until the check holds at p_fast. Fills out (design, check, crowning, tracked) and adds
// the evaluation counts to those already there. Each round's problem has the rows of the round
// before and more (the tracked contacts and the force rows only grow), so its optimum is a lower
// bound of the final outer diameter as far as the local optima are global: once a converged
// round's optimum exceeds `bound`, the polish stops there (out.paused: the lower bound and the round
// to continue from); called again on a paused outcome it continues that round as if it had not
// stopped (the same state, the same counts).
void Polish3D(const LcrSizingSpec& spec, const LcrSizing3DSpec& s, const LcrMinSizeOptions& options, double p_fast,
              LcrMinSize3DOutcome& out, double bound = kInf) {
  LcrMinSizeOutcome& o = out.outcome;
  int first_round = 1;
  if (out.paused) {
    first_round = out.paused->next_round;
    p_fast = out.paused->p_fast_MPa;
    out.paused.reset();
  }
  std::vector<double> x = o.x;
  LcrSizingSpec at = spec;  // the dense check's limits: the study's with the 3D stress limit at p_fast
  at.limits.contact_stress_MPa = p_fast;
  const LcrSizingSpec tight = Tightened(spec);
  LcrActiveSet active = o.active;
  LcrTracked3D tracked = out.tracked;
  int values = o.result.value_evaluations, gradients = o.result.gradient_evaluations,
      iterations = o.result.iterations;
  o.converged = false;
  for (int round = first_round; round <= kMaxRounds; ++round) {
    DenseResult d;
    try {
      d = Dense(at, s, x, options.dense_steps);
    } catch (const std::domain_error& e) {
      o.note = std::string("degenerate geometry: ") + e.what();
      break;
    }
    // The tracked sets grow: the fresh contacts join (the line force peaks are merged by phase).
    bool changed = round == 1;
    for (const auto& c : d.fresh.stress) AddUnique(tracked.stress, c, changed);
    for (const auto& c : d.fresh.edge) AddUnique(tracked.edge, c, changed);
    for (int k = 0; k < 2; ++k)
      for (const LcrSample& f : d.near.force[k]) {
        auto& list = active.force[k];
        if (std::find(list.begin(), list.end(), f) == list.end()) list.push_back(f), changed = true;
      }
    if (round > 1) {
      o.check = d.check;
      out.contact = d.contact;
      if (o.result.ok() && d.check.ok()) {
        o.converged = true;
        break;
      }
      if (!changed) break;
    }
    LcrSizingSpec t = tight;
    t.active = active;
    Problem p = MakeLcrSizing3DProblem(t, s, p_fast * (1 - kStressMargin3D), tracked);
    optimizers::SolverOptions so = options.solver;
    so.initial = x;
    o.result = optimizers::Solve(p, so);
    values += o.result.value_evaluations;
    gradients += o.result.gradient_evaluations;
    iterations += o.result.iterations;
    o.polish_rounds += 1;
    if (o.result.x.empty()) break;
    x = o.result.x;
    // The round's optimum less the solver's relative tolerance: a lower bound also where the last
    // round's optimum and the dense check's diameter differ in their last digits.
    const double lower = o.result.objective * (1 - options.solver.tolerance);
    if (round < kMaxRounds && o.result.ok() && lower > bound) {
      out.paused = LcrPolishPause{round + 1, lower, p_fast, s};
      StorePolish(spec, s, x, active, tracked, values, gradients, iterations, out);
      return;
    }
    if (round == kMaxRounds) {
      try {
        const DenseResult last = Dense(at, s, x, options.dense_steps);
        o.check = last.check;
        out.contact = last.contact;
        o.converged = o.result.ok() && last.check.ok();
      } catch (const std::domain_error& e) {
        o.note = std::string("degenerate geometry: ") + e.what();
      }
    }
  }
  StorePolish(spec, s, x, active, tracked, values, gradients, iterations, out);
}

}  // namespace

LcrMinSize3DOutcome SolveLcrMinSize3D(const LcrSizingSpec& spec, const LcrSizing3DSpec& s3,
                                      const LcrMinSizeOptions& options, double bound) {
  LcrMinSize3DOutcome out;
  // Step 1: the line-model optimum (the fast path) as the start.
  LcrMinSizeOutcome line = SolveLcrMinSize(spec, options);
  if (line.converged) out.line_outer_diameter_mm = line.check->outer_diameter_mm;
  LcrSizing3DSpec s = s3;
  std::vector<double> x = line.x;
  if (x.empty()) {
    out.outcome = std::move(line);
    out.outcome.converged = false;
    out.outcome.note = "the line-model search found no point to start the 3D search from";
    return out;
  }
  if (s.coefficient_range_mm) {
    // Lundberg's coefficient of the largest roller force over the shorter contact length.
    const lcr::Reducer<double> r = LcrDesign(spec, x);
    const double f_max = line.check ? std::max(line.check->max_force_N[0], line.check->max_force_N[1]) : 0.0;
    const double f0 = contact::LundbergCoefficient(f_max, r.input.contact_length(), spec.material.composite_modulus_MPa());
    s.crowning.coefficient = Interior(f0, *s.coefficient_range_mm);
    x.push_back(s.crowning.coefficient);
    x.push_back(s.crowning.coefficient);
  }
  // The other variables start at the fixed values (the parser requires them), clamped.
  const auto start = [&](const std::optional<std::array<double, 2>>& range, double& value, int copies) {
    if (!range) return;
    value = Interior(value, *range);
    for (int i = 0; i < copies; ++i) x.push_back(value);
  };
  double roller_length = spec.roller_length_mm, cam_thickness = spec.cam_thickness_mm;
  start(s.radius_range_mm, s.crowning.radius, 2);
  start(s.flat_length_range_mm, s.crowning.flat_length, 2);
  start(s.roller_length_range_mm, roller_length, 1);
  start(s.cam_thickness_range_mm, cam_thickness, 1);
  out.outcome = line;
  out.outcome.result.status = optimizers::SolverStatus::kFailed;  // until a polish has run
  out.outcome.check.reset();
  out.outcome.x = x;
  out.outcome.polish_rounds = 0;
  out.outcome.note.clear();
  const bool straight = s.crowning.type == contact::CrowningType::kNone;  // no crowning variable exists without a type
  if (straight) {
    // A straight roller carries load on its ends at any force (the end slice touches; the
    // half-space pressure there is singular and grows as the cell shrinks): no design keeps the
    // pressure off the ends, so the edge rows cannot hold. The dense check at the line optimum
    // gives the numbers for the message; no polish.
    LcrMinSizeOutcome& o = out.outcome;
    o.converged = false;
    try {
      const DenseResult d = Dense(spec, s, x, options.dense_steps);
      o.check = d.check;
      out.contact = d.contact;
    } catch (const std::domain_error& e) {
      o.note = std::string("degenerate geometry: ") + e.what();
    }
    o.design = LcrDesign(spec, std::span<const double>(x).first(BaseVariables(spec)));
    o.note = "edge-loaded: straight rollers carry their load on the contact's ends at any torque; crown "
             "the rollers (fixed.crowning with a crowning variable)";
    for (int k = 0; k < 2; ++k) out.crowning[k] = s.crowning;
    return out;
  }
  Polish3D(spec, s, options, spec.limits.contact_stress_MPa, out, bound);
  return out;
}

void ContinueLcrMinSize3D(const LcrSizingSpec& spec, const LcrMinSizeOptions& options, LcrMinSize3DOutcome& out,
                          double bound) {
  if (!out.paused) throw std::invalid_argument("ContinueLcrMinSize3D: the outcome is not paused");
  const LcrSizing3DSpec s = out.paused->spec3d;  // with the start values the first call set
  Polish3D(spec, s, options, out.paused->p_fast_MPa, out, bound);
}

namespace {

// The accurate model's numbers of one cam at one torque on one half_space grid.
struct AccurateSide {
  double peak_MPa = 0, slices_MPa = 0, end_share = 0;
  bool edge_loaded = false, converged = true;
  double cell_dx_mm = 0, cell_dy_mm = 0;
};

// The accurate model's numbers of both cams at one torque on the grid nx × ny ([0]) and on its
// refinement 2nx × 2ny ([1]): one slices cycle, the same worst contacts solved on both grids.
std::array<std::array<AccurateSide, 2>, 2> AccurateAt(const LcrSizingSpec& spec, const LcrSizing3DSpec& s3,
                                                      const lcr::Reducer<double>& r,
                                                      const std::array<lcr::RollerCrowning<double>, 2>& crowning,
                                                      double torque_Nmm, int nx, int ny) {
  std::array<std::array<AccurateSide, 2>, 2> out;
  const double e_star = spec.material.composite_modulus_MPa();
  const lcr::LoadCase load{torque_Nmm, 0.0, 0.0};
  const lcr::CycleSeries series = lcr::AnalyzeCycle(r, spec.material, load, 3600, lcr::Stages{true, false, false});
  lcr::ContactModelOptions o = s3.contact;
  o.model = lcr::ContactModel::kHalfSpace;
  // Each solve from the previous contact's pressure on the same grid, a grid's first from the
  // coarser grid's (contact3d_cycle.h): 1136 → 459 CG iterations in the example's verification.
  lcr::HalfSpaceStarts starts;
  starts.from_coarser_grid = true;
  starts.from_previous_contact = true;
  for (int k = 0; k < 2; ++k) {
    const lcr::Side side = k == 0 ? lcr::Side::kInput : lcr::Side::kOutput;
    const std::vector<lcr::Contact3DCycleSide> cs = lcr::AnalyzeCycleContact3DOnGrids(
        r, side, series, e_star, crowning[k], o, {{nx, ny}, {2 * nx, 2 * ny}}, starts);
    for (int g = 0; g < 2; ++g) {
      const lcr::Contact3DCycleSide& c = cs[g];
      AccurateSide& a = out[g][k];
      a.peak_MPa = c.max_contact_stress_MPa;
      a.slices_MPa = c.slices_peak_at_worst_MPa;
      a.edge_loaded = c.edge_loaded;
      a.converged = c.converged;
      a.cell_dx_mm = c.cell_dx_mm, a.cell_dy_mm = c.cell_dy_mm;
      const auto& p = c.worst_pressure_MPa;
      if (!p.empty() && a.peak_MPa > 0) a.end_share = std::max(p.front(), p.back()) / a.peak_MPa;
    }
  }
  return out;
}

LcrHalfSpaceCheck HalfSpaceCheckOf(const std::array<double, 2>& half_space, const std::array<double, 2>& slices,
                                   const std::array<bool, 2>& edge, double dx, double dy, bool converged) {
  LcrHalfSpaceCheck h;
  for (int k = 0; k < 2; ++k) {
    h.half_space_MPa[k] = half_space[k];
    h.slices_MPa[k] = slices[k];
    h.difference_percent[k] = 100.0 * (slices[k] - half_space[k]) / half_space[k];
    h.edge_loaded[k] = edge[k];
  }
  h.cell_dx_mm = dx, h.cell_dy_mm = dy;
  h.converged = converged;
  return h;
}

}  // namespace

Verification VerifyLcrMinSize3D(const LcrSizingSpec& spec, const LcrSizing3DSpec& s3, const LcrMinSizeOptions& options,
                                LcrMinSize3DOutcome& out, LcrHalfSpaceCheck* first_grid) {
  Verification v;
  v.max_rounds = kVerifyRounds;
  const int nx = s3.contact.grid_nx, ny = s3.contact.grid_ny;
  v.accurate_model = "half_space on " + std::to_string(nx) + "x" + std::to_string(ny) + " and " +
                     std::to_string(2 * nx) + "x" + std::to_string(2 * ny) + " cells (the finer reported, the " +
                     "difference its error) at the slices cycle's 4 worst contacts per cam of 3600 input angles";
  const double p_lim = spec.limits.contact_stress_MPa;
  const double torque = spec.output_torque_Nmm;
  const bool over = s3.overload_torque_Nmm > 0;
  const char* cams[2] = {"input cam", "output cam"};
  double p_fast = p_lim;
  for (int round = 0;; ++round) {
    if (!out.outcome.converged || !out.outcome.design) return v;
    v.ran = true;
    v.checks.clear();
    const lcr::Reducer<double>& r = *out.outcome.design;
    const auto [a0, a1] = AccurateAt(spec, s3, r, out.crowning, torque, nx, ny);
    if (first_grid)
      *first_grid = HalfSpaceCheckOf({a0[0].peak_MPa, a0[1].peak_MPa}, {a0[0].slices_MPa, a0[1].slices_MPa},
                                     {a0[0].edge_loaded, a0[1].edge_loaded}, a0[1].cell_dx_mm, a0[1].cell_dy_mm,
                                     a0[0].converged && a0[1].converged);
    // A stress check that fails beyond its error means another polish: the overload's end check
    // (two more half_space cycles) waits for the design that will be reported.
    bool stress_fails = false;
    for (int k = 0; k < 2; ++k)
      stress_fails = stress_fails || a1[k].peak_MPa > p_lim + std::abs(a1[k].peak_MPa - a0[k].peak_MPa);
    const bool last = round >= kVerifyRounds;
    std::array<AccurateSide, 2> o0 = a0, o1 = a1;
    if (over && (!stress_fails || last)) {
      const auto [v0, v1] = AccurateAt(spec, s3, r, out.crowning, s3.overload_torque_Nmm, nx, ny);
      o0 = v0, o1 = v1;
    }
    for (int k = 0; k < 2; ++k) {
      if (std::isfinite(p_lim)) {
        VerifiedLimit c;
        c.limit = "contact_stress_MPa";
        c.where = cams[k];
        c.limit_value = p_lim;
        c.accurate_value = a1[k].peak_MPa;
        c.estimated_error = std::abs(a1[k].peak_MPa - a0[k].peak_MPa);
        c.fast_value = a1[k].slices_MPa;
        v.checks.push_back(c);
      }
      if (over && stress_fails && !last) continue;  // not evaluated in this round
      VerifiedLimit e;
      e.limit = over ? "overload_edge_pressure_share" : "edge_pressure_share";
      e.where = std::string(cams[k]) + (over ? " at the overload torque" : " at the design torque");
      e.limit_value = kEdgeShareLimit;
      e.accurate_value = o1[k].end_share;
      e.estimated_error = std::abs(o1[k].end_share - o0[k].end_share);
      e.fast_value = NAN;
      v.checks.push_back(e);
    }
    if (v.verified() || last) return v;
    // Tighten the 3D stress limit by the accurate/fast ratio of the cams that break it; an edge
    // share that breaks its limit cannot be tightened here (the slices edge rows already demand a
    // separated end slice): the loop ends and the study reports it.
    double next = p_fast;
    std::string where;
    double accurate = 0;
    for (const VerifiedLimit& c : v.checks)
      if (c.limit == "contact_stress_MPa" && !c.holds()) {
        const double t = TightenedUpperLimit(p_fast, p_lim, c.fast_value, c.accurate_value);
        if (t < next) next = t, where = c.where, accurate = c.accurate_value;
      }
    if (!(next < p_fast)) return v;
    v.history.push_back({round + 1, "contact_stress_MPa", where, p_fast, next, accurate, p_lim});
    p_fast = next;
    Polish3D(spec, s3, options, p_fast, out);
    // The crowning the polish starts from is the outcome's own (the variables carry it).
  }
}

}  // namespace camopt::sizing

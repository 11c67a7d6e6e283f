// The cycloid sizing problem (sizing/cycloid_min_size.h): every constraint row's exact
// derivative against central differences of converged evaluations, and the verified solve.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "model/cycloid/bearing_loads.h"
#include "model/cycloid/geometry_limits.h"
#include "sizing/cycloid_min_size.h"
#include "tests/reference_designs.h"
#include "tests/test_util.h"

namespace camopt::sizing {
namespace cycloid_min_size_test {

// Central differences of converged cycles (compatibility 1e-11, CG 1e-12) against the implicit
// derivatives (CG 1e-10): measured agreement 1e-6 or better on the LTCA rows; the closed forms
// agree to rounding.
constexpr double kRowRelTol = 1e-5;

cycloid::LoadedOptions Tight() {
  cycloid::LoadedOptions o;
  o.profile_cells = 12;
  o.axial_cells = 12;
  o.tolerance = 1e-11;
  o.solver_tolerance = 1e-12;
  o.rough_solver_tolerance = 0;
  o.max_iterations = 400;
  return o;
}

CycloidSizingSpec PaperSpec() {
  CycloidSizingSpec s;
  s.drive = camopt::testing::CycloidNnm();
  s.crowning.type = cycloid::CrowningType::kLogarithmic;
  s.crowning.coefficient_mm = 0.004;
  s.crowning.effective_length_mm = 18.7;
  s.crowning.end_drop_mm = 0.006;
  s.design_torque_Nmm = 350.0e3;
  s.overload_torque_Nmm = 600.0e3;
  s.angles_per_period = 3;
  s.options = Tight();
  s.limits.contact_stress_MPa = 1500;
  s.limits.bore_radius_mm = 40;
  s.limits.min_web_mm = 5;
  s.variables = {{"eccentricity_mm", 1.0, 6.0, 4.5, 1.0},
                 {"roller_position_radius_mm", 40.0, 110.0, 90.0, 10.0},
                 {"roller_radius_mm", 2.0, 10.0, 7.2, 1.0},
                 {"face_width_mm", 10.0, 30.0, 17.0, 10.0},
                 {"effective_length_mm", 10.0, 40.0, 18.7, 10.0},
                 {"delta_position_um", -40.0, 0.0, -16.0, 10.0},
                 {"delta_radius_um", -40.0, 0.0, -8.0, 10.0},
                 {"coefficient_mm", 0.0, 0.02, 0.004, 0.001}};
  return s;
}

// Every output row's derivative by every variable against central differences with the step
// rel_step × the variable's scale, within tol × the largest difference quotient of the row's block
// (the shared check, tests/test_util.h, Scale::kBlockColumn) + 1e-9.
void ExpectRowsMatchCentralDifferences(const Problem& p, const CycloidSizingSpec& spec, const std::vector<double>& x,
                                       const std::vector<double>& jac, double rel_step, double tol) {
  camopt::testing::JacobianCheck check;
  check.rel_tol = tol;
  check.abs_tol = 1e-9;
  check.scale = camopt::testing::JacobianCheck::Scale::kBlockColumn;
  for (int j = 0; j < p.num_vars(); ++j) {
    check.steps.push_back(rel_step * spec.variables[size_t(j)].scale);
    check.variable_names.push_back(spec.variables[size_t(j)].name);
  }
  check.output_names.resize(size_t(p.evaluator->num_outputs()));
  for (const OutputBlock& b : p.evaluator->blocks()) {
    check.row_blocks.push_back({b.offset, b.size});
    for (int r = b.offset; r < b.offset + b.size; ++r) {
      check.output_names[size_t(r)] = b.name + "[" + std::to_string(r - b.offset) + "]";
      check.rows.push_back(r);
    }
  }
  const auto f = [&](const std::vector<double>& z) {
    std::vector<double> y(size_t(p.evaluator->num_outputs()));
    p.evaluator->Eval(z, y);
    return y;
  };
  camopt::testing::ExpectGivenJacobianMatchesCentralDifferences(f, x, f(x), jac, check);
}

TEST(CycloidMinSize, EveryRowsDerivativeMatchesCentralDifferences) {
  CycloidSizingSpec spec = PaperSpec();
  CycloidSizingModel model(spec);
  CycloidFastLimits fast;
  fast.contact_stress_MPa = 1500;
  Problem p = CycloidSizingProblem(model, fast);
  const int n = p.num_vars(), m = p.evaluator->num_outputs();
  std::vector<double> x;
  for (const Variable& v : spec.variables) x.push_back(v.initial);
  std::vector<double> y(m), jac(size_t(m) * n);
  p.evaluator->EvalWithJacobian(x, y, jac);
  ExpectRowsMatchCentralDifferences(p, spec, x, jac, 1e-5, kRowRelTol);
  // The rows are not all flat: the stress rows move with every geometric variable.
  const OutputBlock& peaks = p.evaluator->block(kSizingPeakPressure);
  for (int j = 0; j < 4; ++j) {
    double largest = 0;
    for (int r = peaks.offset; r < peaks.offset + peaks.size; ++r) largest = std::max(largest, std::abs(jac[size_t(r) * n + j]));
    EXPECT_GT(largest, 1.0) << spec.variables[size_t(j)].name;
  }
}

// The life rows (ln L10h / H) against central differences: the pair loads' implicit derivatives,
// the normals, the disc lag and the pins' spin (a Jet through the unloaded TCA) together. Measured
// agreement: see docs/life.md, "Cycloid" (the same converged-cycle tolerances as the other rows).
constexpr double kLifeRowRelTol = 1e-5;

CycloidSizingLife PaperLife() {
  CycloidSizingLife l;
  l.lines = {{350.0e3, 1500.0, 0.6}, {150.0e3, 3000.0, 0.3}, {450.0e3, 0.0, 0.1}};
  l.crank_kind = BearingKind::kRoller;
  l.crank_dynamic_N = 60000;
  l.crank_static_N = 55000;
  l.pins_rated = true;
  l.pins_dynamic_N = 7000;
  l.pins_static_N = 8000;
  l.output = {8, 50.0};
  return l;
}

// The Jacobian `jac` (at x) of one block's rows against central differences with a step of 1e-5 of
// each variable's scale, within kLifeRowRelTol of max(1, |fd|).
void ExpectBlockMatchesCentralDifferences(const Problem& p, const CycloidSizingSpec& spec, const std::vector<double>& x,
                                          const std::vector<double>& jac, const OutputBlock& block,
                                          const std::string& what) {
  const int n = p.num_vars(), m = p.evaluator->num_outputs();
  for (int j = 0; j < n; ++j) {
    const double h = 1e-5 * spec.variables[size_t(j)].scale;
    std::vector<double> xp = x, xm = x, yp(m), ym(m);
    xp[size_t(j)] += h;
    xm[size_t(j)] -= h;
    p.evaluator->Eval(xp, yp);
    p.evaluator->Eval(xm, ym);
    for (int r = block.offset; r < block.offset + block.size; ++r) {
      const double fd = (yp[size_t(r)] - ym[size_t(r)]) / (2 * h);
      EXPECT_NEAR(jac[size_t(r) * n + j], fd, kLifeRowRelTol * std::max(1.0, std::abs(fd)))
          << what << " " << r - block.offset << " by " << spec.variables[size_t(j)].name;
    }
  }
}

TEST(CycloidMinSize, LifeRowsDerivativesMatchCentralDifferences) {
  CycloidSizingSpec spec = PaperSpec();
  spec.life = PaperLife();
  spec.limits.life_h = 5000;
  CycloidSizingModel model(spec);
  CycloidFastLimits fast;
  fast.contact_stress_MPa = 1500;
  fast.life_h = 5000;
  Problem p = CycloidSizingProblem(model, fast);
  const int n = p.num_vars(), m = p.evaluator->num_outputs();
  std::vector<double> x;
  for (const Variable& v : spec.variables) x.push_back(v.initial);
  std::vector<double> y(m), jac(size_t(m) * n);
  p.evaluator->EvalWithJacobian(x, y, jac);
  const OutputBlock& life = p.evaluator->block(kSizingLife);
  ASSERT_EQ(life.size, 2);
  // The rows are ln(L10h / H) of the lives the study reports.
  const CycloidSizingEvaluation e = model.Evaluate(x, false);
  ASSERT_EQ(e.lives.size(), 2u);
  for (int r = 0; r < 2; ++r)
    EXPECT_NEAR(y[size_t(life.offset + r)], std::log(e.lives[size_t(r)].life.L10h / 5000.0), 1e-12);
  ExpectBlockMatchesCentralDifferences(p, spec, x, jac, life, "life row");
  // Not flat: a larger eccentricity lowers the crank bearing's load (T/(n2 e) across the crank).
  EXPECT_GT(jac[size_t(life.offset) * n + 0], 0.1);
}

// The static rows (a momentary torque: P/C0 <= 1/s0 of the crank bearing over its load period and of
// every (crank angle, pin)) at 800 N·m: their values are the model's own s0 and their derivatives
// (through one more cycle, implicit in the pair loads) match central differences.
TEST(CycloidMinSize, StaticRowsDerivativesMatchCentralDifferences) {
  CycloidSizingSpec spec = PaperSpec();
  spec.life = PaperLife();
  spec.limits.life_h = 5000;
  spec.limits.min_static_safety = 1.5;
  spec.limits.static_torque_Nmm = 800e3;
  CycloidSizingModel model(spec);
  CycloidFastLimits fast;
  fast.contact_stress_MPa = 1500;
  fast.life_h = 5000;
  fast.min_static_safety = 1.5;
  Problem p = CycloidSizingProblem(model, fast);
  const int n = p.num_vars(), m = p.evaluator->num_outputs();
  std::vector<double> x;
  for (const Variable& v : spec.variables) x.push_back(v.initial);
  std::vector<double> y(m), jac(size_t(m) * n);
  p.evaluator->EvalWithJacobian(x, y, jac);
  const OutputBlock& rows = p.evaluator->block(kSizingStatic);
  // The crank bearing over its load period (the sizing's angles × the output pins' period), then
  // every (crank angle, pin).
  const size_t crank = size_t(spec.angles_per_period) *
                       size_t(cycloid::OutputPinPeriodInMeshPeriods(spec.life->output, spec.drive.teeth));
  ASSERT_EQ(size_t(rows.size), crank + size_t(spec.angles_per_period) * size_t(spec.drive.rollers));
  const CycloidSizingEvaluation e = model.Evaluate(x, false);
  double largest = 0.0;
  for (int r = 0; r < rows.size; ++r) largest = std::max(largest, y[size_t(rows.offset + r)]);
  EXPECT_NEAR(e.min_static_safety, 1.0 / largest, 1e-12 / largest);
  // The crank bearing's rows against its loads from an independent cycle at 800 N·m.
  const auto [d, c] = model.Design(x);
  const cycloid::LoadedTca tca(d, c, spec.material, spec.options);
  const cycloid::CycleResult at = cycloid::RunCycle(tca, 800e3, model.crank_angles());
  const std::vector<double> b = cycloid::CrankBearingLoads(d, spec.life->output, at.meshes, 800e3);
  ASSERT_EQ(b.size(), crank);
  for (size_t k = 0; k < crank; ++k)
    EXPECT_NEAR(y[size_t(rows.offset) + k] * spec.life->crank_static_N, b[k], 1e-4 * std::max(1.0, b[k])) << k;
  ExpectBlockMatchesCentralDifferences(p, spec, x, jac, rows, "static row");
}

// The output mechanism's rows (stiffness, lost motion, output-pin stress, crank-bearing load, the
// holes' fit): the paper's drive with 8 pins r_w 7 mm on R_w 50 mm in holes with 10 µm radial
// clearance (r_h = 7 + e + 0.01 mm, following the sized e), cantilever over 25 mm.
CycloidSizingOutput PaperOutput() {
  CycloidSizingOutput o;
  o.pins.pins = 8;
  o.pins.pin_circle_radius_mm = 50.0;
  o.pins.pin_radius_mm = 7.0;
  o.pins.hole_radius_mm = 11.51;  // not used: r_h = r_c + e + c
  o.clearance_mm = 0.01;
  o.support = cycloid::PinSupport::kCantilever;
  o.span_mm = 25.0;
  return o;
}

TEST(CycloidMinSize, OutputMechanismRowsDerivativesMatchCentralDifferences) {
  CycloidSizingSpec spec = PaperSpec();
  spec.output = PaperOutput();
  spec.limits.min_torsional_stiffness_Nm_per_arcmin = 300;
  spec.limits.max_lost_motion_arcmin = 2;
  spec.limits.output_pin_stress_MPa = 400;
  spec.limits.eccentric_bearing_load_N = 20000;
  for (bool both_ends : {false, true}) {
    spec.output->support = both_ends ? cycloid::PinSupport::kBothEnds : cycloid::PinSupport::kCantilever;
    spec.output->span_mm = both_ends ? 0.0 : 25.0;  // both ends: the span follows the face width
    CycloidSizingModel model(spec);
    CycloidFastLimits fast;
    fast.contact_stress_MPa = 1500;
    fast.min_torsional_stiffness_Nm_per_arcmin = 300;
    fast.max_lost_motion_arcmin = 2;
    fast.output_pin_stress_MPa = 400;
    fast.eccentric_bearing_load_N = 20000;
    Problem p = CycloidSizingProblem(model, fast);
    const int n = p.num_vars();
    std::vector<double> x;
    for (const Variable& v : spec.variables) x.push_back(v.initial);
    // The LTCA's rows (stiffness, lost motion, crank bearing) with steps of 1e-5 of each variable's
    // scale, as the other rows; the output pins' stress and the holes' fit (closed forms of the pins'
    // solve) with 1e-4: the solve's rotation is closed to 1e-15 rad, ~1e-12 of the pin force, which
    // a step of 1e-5 mm of e amplifies to 1e-4 of the derivative (measured on the probe of one
    // solve: the differences approach the Jet from 1e-3 to 1e-4 mm and leave it below 1e-5).
    int rows = 0;
    for (const auto& [step, names] :
         {std::pair<double, std::vector<const char*>>{1e-5, {kSizingStiffness, kSizingLostMotion, kSizingCrankBearing}},
          std::pair<double, std::vector<const char*>>{1e-4, {kSizingOutputPinStress, kSizingOutputHoles}}}) {
      camopt::testing::JacobianCheck check;
      check.rel_tol = kRowRelTol;
      check.abs_tol = 1e-7;
      check.scale = camopt::testing::JacobianCheck::Scale::kRow;
      for (const Variable& v : spec.variables) {
        check.steps.push_back(step * v.scale);
        check.variable_names.push_back(v.name);
      }
      for (const char* name : names) {
        const OutputBlock& b = p.evaluator->block(name);
        for (int r = b.offset; r < b.offset + b.size; ++r) check.rows.push_back(r);
      }
      EXPECT_EQ(camopt::testing::ExpectEvaluatorJacobianMatchesCentralDifferences(*p.evaluator, x, check),
                int(check.rows.size()) * n);
      rows += int(check.rows.size());
    }
    // 15 mesh periods (15 teeth, 8 pins) of 3 angles: 45 samples of the stress and bearing rows.
    EXPECT_EQ(p.evaluator->block(kSizingOutputPinStress).size, 45);
    EXPECT_EQ(rows, 1 + 1 + 45 + 45 + 1);
    // The rows are the values the model reports, and they move: a larger pin circle is stiffer (longer
    // arms of the ring pins).
    std::vector<double> y(size_t(p.evaluator->num_outputs())), jac(y.size() * size_t(n));
    p.evaluator->EvalWithJacobian(x, y, jac);
    const CycloidSizingEvaluation e = model.Evaluate(x, false);
    EXPECT_EQ(y[size_t(p.evaluator->block(kSizingStiffness).offset)], e.stiffness_Nm_per_arcmin);
    EXPECT_GT(jac[size_t(p.evaluator->block(kSizingStiffness).offset) * n + 1], 0.0);
    EXPECT_GT(e.stiffness_Nm_per_arcmin, 100.0);
    EXPECT_GT(e.max_output_pin_stress_MPa, 50.0);
  }
}

// The lubricated rows (model/cycloid/lubrication.h): η and the oil temperature of the housing's
// balance at the design torque, the paper's drive with fixed (sliding) ring pins whose film sits in
// the mixed regime (σ 0.1 µm each surface), the output pins sliding in their holes (8 pins r_w 7 mm
// on R_w 50 mm, r_h = 7 + e + 0.01 mm following the sized e) and a Palmgren crank bearing, at
// 1500 rpm with a housing of 1.8 W/K and 30 W/K of forced cooling (η 0.78, the oil at 57 °C).
CycloidSizingLubrication PaperLubrication() {
  CycloidSizingLubrication l;
  l.spec.composite_roughness_mm = 0.1e-3 * std::sqrt(2.0);
  l.spec.ring_pins_rotate = false;
  l.spec.crank_bearing = {3.0, 0.0004, 60.0};
  l.mechanism = {8, 50.0};
  l.pins = cycloid::OutputPinContact{7.0, 0.0, 0.0};
  l.hole_clearance_mm = 0.01;
  l.input_speed_rpm = 1500;
  l.cooling = {0.12, 15.0, 30.0, 25.0};
  l.balance_limit_C = 150;
  return l;
}

TEST(CycloidMinSize, LubricatedRowsDerivativesMatchCentralDifferences) {
  CycloidSizingSpec spec = PaperSpec();
  spec.lubrication = PaperLubrication();
  spec.limits.min_efficiency = 0.9;
  spec.limits.max_oil_temperature_C = 100;
  for (bool given : {true, false}) {
    spec.lubrication->temperature_C = given ? std::optional<double>(60.0) : std::nullopt;
    CycloidSizingModel model(spec);
    CycloidFastLimits fast;
    fast.contact_stress_MPa = 1500;
    fast.min_efficiency = 0.9;
    fast.max_oil_temperature_C = 100;
    Problem p = CycloidSizingProblem(model, fast);
    const int n = p.num_vars();
    std::vector<double> x;
    for (const Variable& v : spec.variables) x.push_back(v.initial);
    camopt::testing::JacobianCheck check;
    check.rel_tol = kRowRelTol;
    check.abs_tol = 1e-9;
    check.scale = camopt::testing::JacobianCheck::Scale::kRow;
    for (const Variable& v : spec.variables) {
      check.steps.push_back(1e-5 * v.scale);
      check.variable_names.push_back(v.name);
    }
    check.rows.push_back(p.evaluator->block(kSizingEfficiency).offset);
    if (!given) check.rows.push_back(p.evaluator->block(kSizingOilTemperature).offset);
    bool temperature_row = false;  // a given temperature is no row
    for (const OutputBlock& b : p.evaluator->blocks()) temperature_row = temperature_row || b.name == kSizingOilTemperature;
    EXPECT_EQ(given, !temperature_row);
    EXPECT_EQ(camopt::testing::ExpectEvaluatorJacobianMatchesCentralDifferences(*p.evaluator, x, check),
              int(check.rows.size()) * n);
    // The rows are the values the model reports, in the mixed regime, and they move: a larger
    // eccentricity lowers the crank bearing's load and the output pins' forces (T/(n2 e), 4T/(π R_w)
    // spread over the pins) but slides the output pins faster (e Ω).
    std::vector<double> y(size_t(p.evaluator->num_outputs())), jac(y.size() * size_t(n));
    p.evaluator->EvalWithJacobian(x, y, jac);
    const CycloidSizingEvaluation e = model.Evaluate(x, false);
    EXPECT_EQ(y[size_t(p.evaluator->block(kSizingEfficiency).offset)], e.efficiency);
    EXPECT_GT(e.efficiency, 0.7);
    EXPECT_LT(e.efficiency, 0.999);
    if (given) EXPECT_EQ(e.oil_temperature_C, 60.0);
    else EXPECT_GT(e.oil_temperature_C, 30.0);
    for (int j = 0; j < 4; ++j)
      EXPECT_NE(jac[size_t(p.evaluator->block(kSizingEfficiency).offset) * n + j], 0.0) << spec.variables[size_t(j)].name;
    // The efficiency objective: one disc's loss, its derivative the same Jet's.
    CycloidSizingSpec loss_spec = spec;
    loss_spec.objective = CycloidSizeObjective::kPowerLoss;
    CycloidSizingModel loss_model(loss_spec);
    Problem q = CycloidSizingProblem(loss_model, fast);
    EXPECT_EQ(q.objective, kSizingPowerLoss);
    camopt::testing::JacobianCheck objective = check;
    objective.rows = {0};
    EXPECT_EQ(camopt::testing::ExpectEvaluatorJacobianMatchesCentralDifferences(*q.evaluator, x, objective), n);
    std::vector<double> yq(size_t(q.evaluator->num_outputs()));
    q.evaluator->Eval(x, yq);
    EXPECT_EQ(yq[0], e.power_loss_W);
  }
}

}  // namespace cycloid_min_size_test
}  // namespace camopt::sizing


namespace camopt::sizing {
namespace cycloid_min_size_test {

// The fast model of the sizing tests: 16 × 16 cells per pair, 4 crank angles per mesh period (the
// accurate check doubles both).
cycloid::LoadedOptions Fast() {
  cycloid::LoadedOptions o;
  o.profile_cells = 16;
  o.axial_cells = 16;
  return o;
}

CycloidMinSizeOptions Ipopt() {
  CycloidMinSizeOptions o;
  o.solver.backend = optimizers::Backend::kIpopt;
  o.solver.tolerance = 1e-6;
  o.solver.constraint_tolerance = 1e-3;
  o.solver.stall_iterations = 3;
  o.solver.stall_violation = 1.0;
  o.solver.stall_change = 1e-4;
  o.solver.max_evaluations = 200;
  o.starts = 2;
  return o;
}

void ExpectEveryLimitHolds(const CycloidMinSizeOutcome& r) {
  ASSERT_TRUE(r.verification.ran);
  for (const VerifiedLimit& c : r.verification.checks)
    EXPECT_TRUE(c.holds()) << c.limit << " " << c.where << ": " << c.accurate_value << " against " << c.limit_value
                           << " ± " << c.estimated_error;
  EXPECT_TRUE(r.verified);
}

CycloidSizingSpec Ratio29(cycloid::CrowningType crowning) { return camopt::testing::CycloidRatio29Sizing(crowning); }

TEST(CycloidMinSize, PaperDriveSizedAtItsOwnLcmPeakIsNoLargerThanThePaper) {
  // The load-distribution paper's drive (15 teeth, R_p 90 mm, r_p 7.2 mm, e 4.5 mm, 17 mm face,
  // Δa −16 µm, Δρ −8 µm) with its LCM crowning (f = 5 µm, L = B) at 350 N·m: its own accurate
  // peak becomes the limit, the contact must stay inside the face at 550 N·m, and the geometry,
  // modifications and crowning are free. The sized drive must be no larger than the paper's and
  // hold every limit on the accurate model.
  CycloidSizingSpec spec;
  spec.drive = camopt::testing::CycloidNnm();
  spec.crowning.type = cycloid::CrowningType::kLogarithmic;
  spec.crowning.coefficient_mm = 0.005;
  spec.design_torque_Nmm = 350e3;
  spec.overload_torque_Nmm = 550e3;
  spec.angles_per_period = 4;
  spec.options = Fast();
  const CycloidAccurateCheck paper = CheckCycloidDesign(spec, spec.drive, spec.crowning);
  ASSERT_GT(paper.accurate.edge_margin_um, 0.0);  // the paper's design keeps its contact inside at 550 N·m
  spec.limits.contact_stress_MPa = paper.accurate.stress_MPa;
  spec.variables = {{"eccentricity_mm", 1.0, 6.0, 4.5, 1.0},
                    {"roller_position_radius_mm", 40.0, 110.0, 90.0, 10.0},
                    {"roller_radius_mm", 2.0, 10.0, 7.2, 1.0},
                    {"delta_position_um", -40.0, 0.0, -16.0, 10.0},
                    {"delta_radius_um", -40.0, 0.0, -8.0, 10.0},
                    {"coefficient_mm", 0.0, 0.02, 0.005, 0.001}};
  const CycloidMinSizeOutcome r = SolveCycloidMinSize(spec, Ipopt());
  ASSERT_FALSE(r.x.empty());
  ExpectEveryLimitHolds(r);
  const double paper_diameter = 2 * (90.0 + 7.2);
  EXPECT_LE(r.drive.roller_position_radius_mm, 90.0);
  EXPECT_LE(r.check.accurate.outer_diameter_mm, paper_diameter);
  EXPECT_DOUBLE_EQ(r.check.accurate.outer_diameter_mm, 2 * (r.drive.roller_position_radius_mm + r.drive.roller_radius_mm));
  EXPECT_LE(r.check.accurate.stress_MPa, spec.limits.contact_stress_MPa * 1.001);
  // The stress limit binds and costs size: raising it shrinks the drive.
  ASSERT_TRUE(r.limit_cost.count("contact_stress_MPa"));
  EXPECT_LT(r.limit_cost.at("contact_stress_MPa"), 0.0);
  std::printf("paper drive: LCM peak %.1f MPa (error %.1f); sized D %.2f mm (paper %.1f), a %.3f, rho %.3f, e %.3f\n",
              paper.accurate.stress_MPa, paper.stress_error_MPa, r.check.accurate.outer_diameter_mm, paper_diameter,
              r.drive.roller_position_radius_mm, r.drive.roller_radius_mm, r.drive.eccentricity_mm);
}

TEST(CycloidMinSize, Ratio29CrowningBuysASmallerDriveThanStraightTeeth) {
  const CycloidMinSizeOutcome crowned = SolveCycloidMinSize(Ratio29(cycloid::CrowningType::kLogarithmic), Ipopt());
  const CycloidMinSizeOutcome straight = SolveCycloidMinSize(Ratio29(cycloid::CrowningType::kNone), Ipopt());
  ExpectEveryLimitHolds(crowned);
  ExpectEveryLimitHolds(straight);
  // The loop aims at the accurate value itself within the limit (the straight tooth's edge peak
  // grows with refinement, so its error estimate is large).
  EXPECT_LE(crowned.check.accurate.stress_MPa, 1500 * 1.001);
  EXPECT_LE(straight.check.accurate.stress_MPa, 1500 * 1.001);
  const double dc = crowned.check.accurate.outer_diameter_mm, ds = straight.check.accurate.outer_diameter_mm;
  EXPECT_LT(dc, ds);
  std::printf("ratio 29, 20 N·m: crowned D %.3f mm, straight D %.3f mm: crowning saves %.1f%%\n", dc, ds,
              100 * (ds - dc) / ds);
}

TEST(CycloidMinSize, IpoptAndSlsqpAgreeInDiameter) {
  const CycloidSizingSpec spec = Ratio29(cycloid::CrowningType::kLogarithmic);
  const CycloidMinSizeOutcome ipopt = SolveCycloidMinSize(spec, Ipopt());
  CycloidMinSizeOptions o = Ipopt();
  o.solver.backend = optimizers::Backend::kSlsqp;
  const CycloidMinSizeOutcome slsqp = SolveCycloidMinSize(spec, o);
  ASSERT_TRUE(ipopt.converged);
  ASSERT_TRUE(slsqp.converged);
  const double di = ipopt.check.accurate.outer_diameter_mm, ds = slsqp.check.accurate.outer_diameter_mm;
  EXPECT_NEAR(di, ds, 1e-3 * di);
  std::printf("Ipopt D %.4f mm, SLSQP D %.4f mm (%.4f%%)\n", di, ds, 100 * std::abs(di - ds) / di);
}

TEST(CycloidMinSize, RowDerivativesHoldAtTheUndercutBoundary) {
  // A ratio-29 drive whose tooth is 2 µm from undercut (the smallest convex radius of the pin
  // centre path just above ρ'): the closed-form rows and the LTCA rows against central differences.
  CycloidSizingSpec spec = Ratio29(cycloid::CrowningType::kLogarithmic);
  spec.options.tolerance = 1e-11;
  spec.options.solver_tolerance = 1e-12;
  spec.options.rough_solver_tolerance = 0;
  spec.options.max_iterations = 400;
  spec.angles_per_period = 2;
  // ρ' = ρ + Δρ chosen 2 µm below the centre path's smallest convex radius.
  cycloid::Drive d = spec.drive;
  d.roller_radius_mm = 1.0;
  d.delta_radius_mm = -0.005;
  const double rho_max = cycloid::MinConvexCentreRadius(d) - d.delta_radius_mm;
  spec.drive.roller_radius_mm = rho_max - 0.002;
  spec.variables[2] = {"roller_radius_mm", 0.5, 5.0, spec.drive.roller_radius_mm, 1.0};
  spec.variables[4] = {"delta_radius_um", -30.0, 0.0, -5.0, 10.0};
  CycloidSizingModel model(spec);
  Problem p = CycloidSizingProblem(model, CycloidFastLimits{1500, 0, 0, kInf});
  const int n = p.num_vars(), m = p.evaluator->num_outputs();
  std::vector<double> x;
  for (const Variable& v : spec.variables) x.push_back(v.initial);
  std::vector<double> y(m), jac(size_t(m) * n);
  p.evaluator->EvalWithJacobian(x, y, jac);
  const int undercut = p.evaluator->block(kSizingUndercut).offset;
  ASSERT_NEAR(y[undercut], 0.002, 1e-9);
  ExpectRowsMatchCentralDifferences(p, spec, x, jac, 1e-6, 1e-4);  // steps stay inside the 2 µm
}

}  // namespace cycloid_min_size_test
}  // namespace camopt::sizing

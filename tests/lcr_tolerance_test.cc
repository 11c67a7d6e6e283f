// Tests of the LCR tolerance model (model/lcr/tolerance.h) and transmission error
// (model/lcr/transmission_error.h): exact gaps against closed forms, the compliant model against
// the stiffness model, Jet sensitivities against central differences, linear against Monte-Carlo.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "model/lcr/transmission_error.h"
#include "tests/reference_designs.h"

namespace camopt::lcr {
namespace lcr_tolerance_test {

using camopt::testing::LcrII;
using camopt::testing::Steel;

constexpr double kArcsec = 180.0 / kPi * 3600.0;

// The nominal reducer touches every roller: all exact gaps vanish.
TEST(LcrTolerance, NominalGapsAreZero) {
  const Reducer<double> r = LcrII();
  const Deviations<double> none;
  for (double theta : {0.0, 0.3, 1.7, 4.0})
    for (Side s : {Side::kInput, Side::kOutput})
      for (double g : RollerGaps(r, s, none, theta, Vec2<double>(0.0, 0.0))) EXPECT_NEAR(g, 0.0, 1e-10);
}

// Turning a turret's rollers by ε about the input axis closes roller k by a_k ε (the closure
// ψ a_k − c_k of the stiffness model): the gap moves by −a_k ε.
TEST(LcrTolerance, RollerPitchShiftClosesByTheArm) {
  const Reducer<double> r = LcrII();
  const double eps = 1e-6, theta = 0.9;
  for (Side s : {Side::kInput, Side::kOutput}) {
    Deviations<double> d;
    d.roller_angle[SideIndex(s)].assign(r.side(s).rollers, eps);
    const std::vector<double> g = RollerGaps(r, s, d, theta, Vec2<double>(0.0, 0.0));
    const auto contacts = RollerContacts(r, s, theta);
    for (size_t k = 0; k < g.size(); ++k) EXPECT_NEAR(g[k], -contacts[k].arm * eps, 1e-3 * std::abs(contacts[k].arm) * eps + 1e-13);
  }
}

// Δe alone: the cam centre moves by Δe u(θ) toward the rollers' normals d_k (into the cam), so
// to first order c_k = Δe u(θ)·d_k (closed form through the pitch point, contact.h).
TEST(LcrTolerance, EccentricityErrorClosedForm) {
  const Reducer<double> r = LcrII();
  Deviations<double> d;
  d.eccentricity = 2e-3;  // 2 µm
  for (double theta : {0.2, 2.5})
    for (Side s : {Side::kInput, Side::kOutput}) {
      const std::vector<double> g = RollerGaps(r, s, d, theta, Vec2<double>(0.0, 0.0));
      const auto contacts = RollerContacts(r, s, theta);
      for (size_t k = 0; k < g.size(); ++k) {
        const double closed = d.eccentricity * U(theta).dot(contacts[k].direction);
        EXPECT_NEAR(g[k], closed, 0.01 * d.eccentricity + 1e-12) << k;
      }
    }
}

// Uniformly undersized rollers (clearance c on every roller) at a light torque: the output turns
// by the first-contact rotation of the stiffness model, c/max(s a_B) + ρ c/max(−s a_A) (s: the
// load's sense), written here from the arms alone.
TEST(LcrTolerance, UniformRollerUndersizeGivesFirstContactRotation) {
  const Reducer<double> r = LcrII();
  const double c = 2e-3, light = 1e-3;  // 2 µm clearance, 1e-3 N·mm
  Deviations<double> d;
  for (int s : {0, 1}) d.roller_radius[s].assign(s == 0 ? r.input.rollers : r.output.rollers, -c);
  const double sense = LoadedArmSign(r, Side::kOutput);
  const double rho = double(r.output.lobes) * r.input.rollers / (double(r.output.rollers) * r.input.lobes);
  for (double theta : {0.0, 0.4, 1.3}) {
    double amax_b = 0, amax_a = 0;
    for (const auto& k : RollerContacts(r, Side::kOutput, theta)) amax_b = std::max(amax_b, sense * k.arm);
    for (const auto& k : RollerContacts(r, Side::kInput, theta)) amax_a = std::max(amax_a, -sense * k.arm);
    const double closed = sense * (c / amax_b + rho * c / amax_a);
    const double te = ExactTransmissionError(r, Steel(), d, light, {theta})[0];
    EXPECT_NEAR(te, closed, 0.01 * std::abs(closed));
  }
}

// With no deviations the compliant model is the stiffness model (same code, one home): forces and
// the output rotation agree to 1e-9, also through the general solver with (zero) gaps.
TEST(LcrTolerance, CompliantEqualsStiffnessModelWithoutTolerances) {
  const Reducer<double> r = LcrII();
  const double t = LoadedArmSign(r, Side::kOutput) * 80000.0;
  const Deviations<double> zero;
  for (double theta : {0.0, 0.5, 2.2}) {
    const auto d = rigidity::DeflectAtAngle<double>(r, Steel(), theta, t, 0.0);
    for (const Deviations<double>* dev : {static_cast<const Deviations<double>*>(nullptr), &zero}) {
      const CompliantAngle<double> c = CompliantAtAngle<double>(r, Steel(), theta, t, dev);
      EXPECT_NEAR(c.output_rotation, d.output_rotation, 1e-9 * std::abs(d.output_rotation));
      EXPECT_NEAR(*std::max_element(c.force_input.begin(), c.force_input.end()), d.max_force_input, 1e-9 * d.max_force_input);
      EXPECT_NEAR(*std::max_element(c.force_output.begin(), c.force_output.end()), d.max_force_output, 1e-9 * d.max_force_output);
      double torque = 0;
      const auto contacts = RollerContacts(r, Side::kOutput, theta);
      for (size_t k = 0; k < contacts.size(); ++k) torque += c.force_output[k] * contacts[k].arm;
      EXPECT_NEAR(torque, t, 1e-9 * std::abs(t));  // the solver's equation holds
    }
  }
}

// Jet sensitivities S_p against central differences of the exact model.
TEST(LcrTolerance, SensitivitiesMatchCentralDifferences) {
  const Reducer<double> r = LcrII();
  ToleranceBands b;
  b.eccentricity_mm = 2e-3, b.turret_radius_mm = 2e-3, b.roller_diameter_mm = 4e-3, b.roller_pitch_rad = 1e-5,
  b.profile_mm = 2e-3, b.bearing_clearance_mm = 2e-3;
  const auto params = ToleranceParameters(r, b);
  const double torque = 80000.0, theta = 0.7;
  const double t = LoadedArmSign(r, Side::kOutput) * torque;
  using J = ceres::Jet<double, 1>;
  const AngleLoads<double> a = AnalyzeAngle(r, Steel(), LoadCase{torque, 0.0, 0.0}, theta);
  const Vec2<double> dir = a.eccentric_load / a.eccentric_load.norm();
  const double tolerance = 2e-4;  // relative, of the largest sensitivity of its kind
  for (size_t p : {size_t(0), size_t(1), size_t(2), size_t(3), size_t(20), size_t(40), size_t(params.size() - 3),
                   size_t(params.size() - 1)}) {
    Deviations<J> dj;
    AddDeviation(dj, r, params[p], J(0.0, 0));
    const double ad = CompliantAtAngle<J>(r, Steel(), theta, t, &dj, dir).output_rotation.v[0];
    const double h = 1e-2 * params[p].band;
    auto f = [&](double x) {
      Deviations<double> d;
      AddDeviation(d, r, params[p], x);
      return CompliantAtAngle<double>(r, Steel(), theta, t, &d, dir).output_rotation;
    };
    // The bearing clearance is one-sided (0 … c): the second-order one-sided difference.
    const double fd = params[p].key == 5 ? (-3 * f(0.0) + 4 * f(h) - f(2 * h)) / (2 * h) : (f(h) - f(-h)) / (2 * h);
    EXPECT_NEAR(ad, fd, tolerance * std::max(std::abs(fd), 1e-3)) << "parameter " << p << " key " << params[p].key;
  }
}

// Small tolerances: the linear model follows the exact one sample by sample within 5% of the
// peak-to-peak, and its RMS matches the Monte-Carlo RMS within 5%.
TEST(LcrTolerance, LinearAgreesWithMonteCarloAtSmallTolerances) {
  const Reducer<double> r = LcrII();
  ToleranceBands b;
  b.eccentricity_mm = 0.2e-3, b.turret_radius_mm = 0.2e-3, b.roller_diameter_mm = 0.4e-3,
  b.roller_pitch_rad = 1.0 / kArcsec, b.profile_mm = 0.2e-3;
  TransmissionErrorOptions o;
  o.output_torque_Nmm = 80000.0;
  o.angle_steps = 24;
  o.samples = 300;
  o.seed = 7;
  const TransmissionErrorResult res = AnalyzeTransmissionError(r, Steel(), b, o);
  EXPECT_LT(res.linear_vs_exact_max_error, 0.05);
  EXPECT_NEAR(res.monte_carlo_rms_arcsec, res.linear_rms_arcsec, 0.05 * res.linear_rms_arcsec);
  EXPECT_LE(res.monte_carlo_max_arcsec, res.linear_worst_case_arcsec * 1.05);
  EXPECT_GT(res.monte_carlo_max_arcsec, 0.0);
  double share = 0;
  for (const auto& c : res.contributions) share += c.variance_share;
  EXPECT_NEAR(share, 1.0, 1e-12);
}

TEST(LcrTolerance, MonteCarloIsDeterministicPerSeed) {
  const Reducer<double> r = LcrII();
  ToleranceBands b;
  b.roller_diameter_mm = 4e-3, b.bearing_clearance_mm = 3e-3;
  TransmissionErrorOptions o;
  o.output_torque_Nmm = 80000.0, o.lost_motion_torque_Nmm = 2400.0, o.angle_steps = 12, o.samples = 5, o.seed = 3;
  const auto a = AnalyzeTransmissionError(r, Steel(), b, o), c = AnalyzeTransmissionError(r, Steel(), b, o);
  EXPECT_EQ(a.monte_carlo_max_arcsec, c.monte_carlo_max_arcsec);
  EXPECT_EQ(a.lost_motion_arcmin, c.lost_motion_arcmin);
  o.seed = 4;
  EXPECT_NE(AnalyzeTransmissionError(r, Steel(), b, o).monte_carlo_max_arcsec, a.monte_carlo_max_arcsec);
  EXPECT_GT(a.lost_motion_arcmin, a.lost_motion_nominal_arcmin);  // clearance adds play
}

}  // namespace lcr_tolerance_test
}  // namespace camopt::lcr

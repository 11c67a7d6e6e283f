// Contact-force dynamics of the globoidal turret (eqs. 10–14): the step function, the Hertz
// stiffness against its closed form, energy conservation without damping (and the peak
// penetration from the energy balance), dissipation with damping, the momentum balance over a
// stretch of the run, and the static load limit equal to the quasi-static force T/(l cos α).
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "model/globoidal/contact_dynamics.h"
#include "model/globoidal/paper_example.h"
#include "tests/test_util.h"

namespace camopt::globoidal {
namespace {

constexpr double kDeg = kPi / 180.0;

DynamicsInput HeldCam(double theta_deg) {
  DynamicsInput in;
  in.cam = PaperExampleCam<double>();
  in.cam_speed_rad_s = 0.0;
  in.start_cam_angle_rad = theta_deg * kDeg;
  in.inertia_Nmms2 = 10.0;
  in.time_step_s = 2e-6;
  in.end_time_s = 0.01;
  in.output_every = 1;
  return in;
}

TEST(GloboidalDynamics, AdamsStepFunction) {
  EXPECT_EQ(Step(-1.0, 0.0, 2.0, 1.0, 5.0), 2.0);
  EXPECT_EQ(Step(2.0, 0.0, 2.0, 1.0, 5.0), 5.0);
  EXPECT_NEAR(Step(0.5, 0.0, 2.0, 1.0, 5.0), 3.5, 1e-15);
  // Zero slope at both ends (C¹).
  const double h = 1e-6;
  EXPECT_NEAR((Step(h, 0.0, 0.0, 1.0, 1.0) - Step(0.0, 0.0, 0.0, 1.0, 1.0)) / h, 0.0, 1e-5);
  EXPECT_NEAR((Step(1.0, 0.0, 0.0, 1.0, 1.0) - Step(1.0 - h, 0.0, 0.0, 1.0, 1.0)) / h, 0.0, 1e-5);
}

TEST(GloboidalDynamics, HertzStiffnessEqs11To13) {
  // Steel on steel: E* = E/(2(1 − ν²)).
  const double es = CompositeModulus(206000.0, 0.3, 206000.0, 0.3);
  EXPECT_NEAR(es, 206000.0 / (2 * 0.91), 1e-9);
  // Two equal radii: R = r/2.
  EXPECT_NEAR(ContactStiffness(4.0, 4.0, es), 4.0 / 3.0 * std::sqrt(2.0) * es, 1e-9);
  // In a dwell at φ = 0 the working surface is a plane: K = (4/3) √R_roller E*.
  DynamicsInput in = HeldCam(0.0);
  in.cam.roller_angle = 0.0;
  in.cam.swing = 0.0;
  in.cam.motion = motion::MotionProgram<double>({{motion::MotionLaw::kDwell, 0.0, 2 * kPi}});
  EXPECT_NEAR(RollerStiffness(in, 1, 0.3), 4.0 / 3.0 * 2.0 * es, 1e-6);
  // No force without penetration; continuous at δ = 0.
  EXPECT_EQ(ImpactForce(-1e-3, -5.0, 1e5, 1.5, 10.0, 0.01), 0.0);
  EXPECT_NEAR(ImpactForce(1e-12, 1.0, 1e5, 1.5, 10.0, 0.01), 0.0, 1e-9);
  // Full damping beyond the penetration depth d.
  EXPECT_NEAR(ImpactForce(0.02, 3.0, 1e5, 1.5, 10.0, 0.01), 1e5 * std::pow(0.02, 1.5) + 30.0,
              1e-9);
}

// Without damping and with the cam held, the turret rattles between its two rollers and
// J ψ̇²/2 + Σ K δ^2.5/2.5 is conserved; the peak penetration of each roller follows from it.
TEST(GloboidalDynamics, EnergyIsConservedWithoutDamping) {
  for (double theta : {100.0, 30.0}) {
    DynamicsInput in = HeldCam(theta);
    in.contact.max_damping_Ns_per_mm = 0.0;
    in.initial_swing_rate_rad_s = 0.5;
    const DynamicsResult r = SimulateDynamics(in);
    const double e0 = 0.5 * in.inertia_Nmms2 * 0.25;
    double emin = 1e30, emax = 0, dmax[2] = {0, 0};
    for (const auto& s : r.samples) {
      emin = std::min(emin, s.energy_Nmm);
      emax = std::max(emax, s.energy_Nmm);
      for (int j = 0; j < 2; ++j) dmax[j] = std::max(dmax[j], s.penetration_mm[j]);
    }
    EXPECT_NEAR(emin / e0, 1.0, 1e-6);
    EXPECT_NEAR(emax / e0, 1.0, 1e-6);
    for (int j = 0; j < 2; ++j) {
      ASSERT_GT(dmax[j], 0.0) << "both rollers are hit";
      const double expect = std::pow(2.5 * e0 / RollerStiffness(in, j + 1, theta * kDeg), 0.4);
      EXPECT_NEAR(dmax[j] / expect, 1.0, 1e-4) << theta << " roller " << j + 1;
    }
  }
}

// With damping, energy only decreases, and the change of angular momentum over the run equals the
// time integral of the contact moments (trapezoidal rule on the recorded forces).
TEST(GloboidalDynamics, DampingDissipatesAndMomentumBalances) {
  DynamicsInput in = HeldCam(100.0);
  in.contact.max_damping_Ns_per_mm = 20.0;
  in.contact.penetration_depth_mm = 1e-4;
  in.initial_swing_rate_rad_s = 0.5;
  const DynamicsResult r = SimulateDynamics(in);
  double impulse = 0;
  for (size_t i = 1; i < r.samples.size(); ++i) {
    EXPECT_LE(r.samples[i].energy_Nmm, r.samples[i - 1].energy_Nmm * (1 + 1e-9) + 1e-12);
    const auto& a = r.samples[i - 1];
    const auto& b = r.samples[i];
    impulse += 0.5 * (a.swing_acc_rad_s2 + b.swing_acc_rad_s2) * (b.time_s - a.time_s);
  }
  EXPECT_LT(r.samples.back().energy_Nmm, 0.5 * r.samples.front().energy_Nmm);
  // Moments: J ψ̈ = Σ moments, so ∫ψ̈ dt = Δψ̇.
  EXPECT_NEAR(impulse, r.samples.back().swing_rate_rad_s - r.samples.front().swing_rate_rad_s,
              1e-4 * 0.5);
  // Independent: the moments from the recorded forces, −F n·e_φ l on each roller, with
  // n·e_φ = −1 (roller 1) and +1 (roller 2) in a dwell.
  for (const auto& s : r.samples)
    EXPECT_NEAR(in.inertia_Nmms2 * s.swing_acc_rad_s2, 22.0 * (s.force_N[0] - s.force_N[1]),
                1e-9 * std::max(1.0, s.force_N[0] + s.force_N[1]));
}

// The static load limit: with the cam held and damping, the turret settles where the loaded
// roller carries F = T /(l cos α) — the quasi-static force from the torque and the arm.
TEST(GloboidalDynamics, StaticLoadLimitIsTheQuasiStaticForce) {
  for (double theta : {100.0, 30.0, 200.0}) {
    DynamicsInput in = HeldCam(theta);
    in.load_torque_Nmm = 500e3;  // 500 N·m
    in.start_static = false;
    in.contact.max_damping_Ns_per_mm = 120.0;  // about critical for the linearised contact
    in.contact.penetration_depth_mm = 1e-3;
    in.end_time_s = 0.03;
    in.output_every = 100;
    const DynamicsResult r = SimulateDynamics(in);
    const double alpha = EvaluateSurface(in.cam, 1, 22.0, theta * kDeg).pressure_angle;
    const double expect = 500e3 / (22.0 * std::cos(alpha));
    EXPECT_NEAR(r.samples.back().force_N[0] / expect, 1.0, 1e-4) << theta;
    EXPECT_EQ(r.samples.back().force_N[1], 0.0);
    EXPECT_NEAR(QuasiStaticForce(in, theta * kDeg) / expect, 1.0, 1e-12);
    // Started at the static deflection, it stays there.
    in.start_static = true;
    in.end_time_s = 0.002;
    const DynamicsResult s = SimulateDynamics(in);
    for (const auto& x : s.samples) EXPECT_NEAR(x.force_N[0] / expect, 1.0, 1e-9);
  }
  EXPECT_GT(std::abs(EvaluateSurface(PaperExampleCam<double>(), 1, 22.0, 30 * kDeg).pressure_angle),
            10 * kDeg);
}

// Running slowly, the turret follows the modified-sine motion and the loaded roller's force
// follows the quasi-static force (inertia + load over the arm).
TEST(GloboidalDynamics, SlowRunFollowsKinematicsAndQuasiStaticForce) {
  DynamicsInput in;
  in.cam = PaperExampleCam<double>();
  in.cam_speed_rad_s = 2 * kPi * 120 / 60;  // 120 rpm
  in.load_torque_Nmm = 500e3;
  in.contact.max_damping_Ns_per_mm = 120.0;
  in.contact.penetration_depth_mm = 1e-3;
  in.time_step_s = 1e-5;
  in.end_time_s = 0.5;  // one revolution
  in.output_every = 10;
  const DynamicsResult r = SimulateDynamics(in);
  double worst_angle = 0, worst_force = 0;
  for (const auto& s : r.samples) {
    // Quasi-static deflection: roller 1 compressed by δ = (F/K)^(2/3), i.e. ψ − φ_i =
    // −δ/(l cos α).
    const double q = QuasiStaticForce(in, s.cam_angle_rad);
    const double alpha = EvaluateSurface(in.cam, 1, 22.0, s.cam_angle_rad).pressure_angle;
    const double dpsi =
        -std::pow(q / RollerStiffness(in, 1, s.cam_angle_rad), 1 / 1.5) / (22.0 * std::cos(alpha));
    worst_angle = std::max(worst_angle, std::abs(s.swing_rad - s.kin_swing_rad - dpsi) / std::abs(dpsi));
    worst_force = std::max(worst_force, std::abs(s.force_N[0] - q) / q);
  }
  EXPECT_LT(worst_angle, 0.05);
  EXPECT_LT(worst_force, 0.05);
}

// AD gradients of the contact law: K(R₁, R₂, E₁, μ₁, E₂, μ₂) and F(δ, δ̇) in the damping ramp
// (δ < d) and beyond it.
TEST(GloboidalDynamics, ContactLawGradients) {
  auto k = [](const auto& x) {
    using T = std::decay_t<decltype(x[0])>;
    return std::vector<T>{ContactStiffness(x[0], x[1], CompositeModulus(x[2], x[3], x[4], x[5]))};
  };
  camopt::testing::ExpectJacobianMatchesCentralDifferences<6>(
      k, {4.0, 9.0, 206000.0, 0.3, 190000.0, 0.28}, 1e-6, 1e-6);
  for (double delta : {0.004, 0.02}) {
    auto f = [](const auto& x) {
      using T = std::decay_t<decltype(x[0])>;
      return std::vector<T>{ImpactForce(x[0], x[1], 2e5, 1.5, 10.0, 0.01)};
    };
    camopt::testing::ExpectJacobianMatchesCentralDifferences<2>(f, {delta, 3.0}, 1e-6, 1e-6);
  }
}

// The anticlockwise cam is the mirror image with the rollers swapped: its roller 2 carries what
// roller 1 of the clockwise cam carries, sample by sample.
TEST(GloboidalDynamics, AnticlockwiseMirrorsTheForces) {
  DynamicsInput in;
  in.cam = PaperExampleCam<double>();
  in.cam_speed_rad_s = 2 * kPi * 10;
  in.load_torque_Nmm = 500e3;
  in.inertia_Nmms2 = 1.0;
  in.end_time_s = 0.02;
  in.output_every = 20;
  const DynamicsResult a = SimulateDynamics(in);
  in.cam.direction = -1;
  const DynamicsResult b = SimulateDynamics(in);
  ASSERT_EQ(a.samples.size(), b.samples.size());
  for (size_t i = 0; i < a.samples.size(); ++i) {
    EXPECT_NEAR(b.samples[i].force_N[1], a.samples[i].force_N[0], 1e-6 * a.samples[i].force_N[0]);
    EXPECT_NEAR(b.samples[i].force_N[0], a.samples[i].force_N[1], 1e-6);
    EXPECT_NEAR(b.samples[i].swing_rad, a.samples[i].swing_rad, 1e-12);
  }
}

TEST(GloboidalDynamics, BadInputThrows) {
  DynamicsInput in = HeldCam(0.0);
  in.inertia_Nmms2 = 0.0;
  EXPECT_THROW(SimulateDynamics(in), std::invalid_argument);
  in = HeldCam(0.0);
  in.time_step_s = -1;
  EXPECT_THROW(SimulateDynamics(in), std::invalid_argument);
}

}  // namespace
}  // namespace camopt::globoidal

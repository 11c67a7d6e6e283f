// The papers' reference designs, shared by every suite and the benchmarks: LCR I, II, III of
// Table 2; the disc-cam example of Rzine et al. and an oscillating-follower disc cam; the cycloid
// paper's NNM drive; the LCR II sizing duty of the −90 study.
#pragma once

#include "model/cycloid/tooth_profile.h"
#include "model/disc_cam/disc_cam.h"
#include "model/lcr/contact.h"
#include "model/lcr/reducer.h"
#include "model/motion/motion_program.h"
#include "sizing/cycloid_min_size.h"
#include "objectives/lcr_sizing.h"

namespace camopt::testing {

inline lcr::Reducer<double> MakeLcr(double e, int m_a, int n_a, double rd_a, int m_b, int n_b,
                                    double rd_b, double d_r, double length, double thickness) {
  lcr::Reducer<double> r;
  r.eccentricity = e;
  r.input = {m_a, n_a, rd_a, d_r / 2, length, thickness};
  r.output = {m_b, n_b, rd_b, d_r / 2, length, thickness};
  return r;
}

/// Table 2, LCR I (r_i = −399).
inline lcr::Reducer<double> LcrI() { return MakeLcr(1, 19, 20, 39, 20, 21, 44, 6, 5, 4); }
/// Table 2, LCR II (r_i = −90): the prototype.
inline lcr::Reducer<double> LcrII() { return MakeLcr(2, 12, 13, 37, 14, 15, 42, 12, 10, 8); }
/// Table 2, LCR III (r_i = −24).
inline lcr::Reducer<double> LcrIII() { return MakeLcr(4, 4, 5, 36, 5, 6, 41, 18, 16, 14); }

inline lcr::Material Steel() { return {206000.0, 0.3}; }

/// The LCR sizing problem of the −90 study, the paper's LCR II duty: 80 N·m output torque under
/// 1500 MPa contact stress, 1050 N roller load, 0.5 mm undercut margin and 1 mm roller gap. The
/// lobe/roller counts default to LCR II's (12/13 on the input cam, 14/15 on the output cam).
inline objectives::LcrSizingSpec LcrIISizingSpec(
    objectives::LcrConstraintForm form = objectives::LcrConstraintForm::kAggregate, int lobes_a = 12,
    int rollers_a = 13, int lobes_b = 14, int rollers_b = 15) {
  objectives::LcrSizingSpec s;
  s.lobes_a = lobes_a, s.rollers_a = rollers_a, s.lobes_b = lobes_b, s.rollers_b = rollers_b;
  s.output_torque_Nmm = 80000;
  s.limits = {1500, 1050, 0.5, 1.0};
  s.form = form;
  return s;
}

/// Logarithmic (Lundberg) crowning of the cycloid's rollers with coefficient f [mm], the rest as
/// the type's defaults.
inline cycloid::Crowning LogCrowning(double coefficient_mm) {
  cycloid::Crowning c;
  c.type = cycloid::CrowningType::kLogarithmic;
  c.coefficient_mm = coefficient_mm;
  return c;
}

/// The cycloid load-distribution paper's example drive (Table 2: n2 = 15, n1 = 16, a = 90 mm,
/// ρ = 7.2 mm, e = 4.5 mm, B = 17 mm) with its NNM profile modification (Table 3: Δa = −16 µm,
/// Δρ = −8 µm), as cycloid_ltca_nnm_*.json.
inline cycloid::Drive CycloidNnm() {
  cycloid::Drive d;
  d.teeth = 15;
  d.rollers = 16;
  d.roller_position_radius_mm = 90.0;
  d.roller_radius_mm = 7.2;
  d.eccentricity_mm = 4.5;
  d.face_width_mm = 17.0;
  d.delta_position_mm = -0.016;
  d.delta_radius_mm = -0.008;
  return d;
}

/// The disc-cam example of Rzine et al. §5 (docs/disc_cam.md; studies/examples/
/// disc_cam_translating.json): translating roller, r_b = 40, r_f = 10, offset e = 12 (mm);
/// cycloidal rise of 24 mm over 120°, dwell 50°, cycloidal return over 120°, dwell 70°. The sizes
/// can be given as T so that gradients can be taken with respect to them.
template <typename T = double>
disc_cam::DiscCamTpl<T> DiscCamPaperExample(T rb = T(40.0), T rf = T(10.0), T e = T(12.0),
                                            T rise = T(24.0)) {
  constexpr double kDeg = kPi / 180.0;
  using motion::MotionLaw;
  disc_cam::DiscCamTpl<T> cam;
  cam.follower = disc_cam::FollowerType::kTranslatingRoller;
  cam.base_radius = rb;
  cam.roller_radius = rf;
  cam.offset = e;
  cam.motion = motion::MotionProgram<T>({{MotionLaw::kCycloidal, rise, T(120 * kDeg)},
                                         {MotionLaw::kDwell, T(0.0), T(50 * kDeg)},
                                         {MotionLaw::kCycloidal, -rise, T(120 * kDeg)},
                                         {MotionLaw::kDwell, T(0.0), T(70 * kDeg)}});
  return cam;
}

/// An oscillating roller follower (studies/examples/disc_cam_oscillating.json): r_b = 40, r_f = 10,
/// pivot distance f = 100, arm l = 80 (mm); 20° modified-sine rise over 100°, dwell 60°, return
/// over 100°, dwell 100°.
template <typename T = double>
disc_cam::DiscCamTpl<T> DiscCamOscillatingExample(T rb = T(40.0), T rf = T(10.0), T f = T(100.0),
                                                  T l = T(80.0), T rise = T(20 * (kPi / 180.0))) {
  constexpr double kDeg = kPi / 180.0;
  using motion::MotionLaw;
  disc_cam::DiscCamTpl<T> cam;
  cam.follower = disc_cam::FollowerType::kOscillatingRoller;
  cam.base_radius = rb;
  cam.roller_radius = rf;
  cam.pivot_distance = f;
  cam.arm_length = l;
  cam.motion = motion::MotionProgram<T>({{MotionLaw::kModifiedSine, rise, T(100 * kDeg)},
                                         {MotionLaw::kDwell, T(0.0), T(60 * kDeg)},
                                         {MotionLaw::kModifiedSine, -rise, T(100 * kDeg)},
                                         {MotionLaw::kDwell, T(0.0), T(100 * kDeg)}});
  return cam;
}

/// LCR II with its eccentricity and the roller radius of both sides given as T (gradients through
/// them), and the effective radius R' = r_r (1 − r_r κ) of output roller 3 at input angle 0.3 rad:
/// the contact the 3D-contact gradient tests differentiate.
template <typename T>
struct LcrIIContact {
  lcr::Reducer<T> reducer;
  T effective_radius;
};
template <typename T>
LcrIIContact<T> LcrIIOutputRoller3(T eccentricity, T roller_radius) {
  LcrIIContact<T> c;
  c.reducer.eccentricity = eccentricity;
  c.reducer.input = {12, 13, T(37.0), roller_radius, T(10.0), T(8.0)};
  c.reducer.output = {14, 15, T(42.0), roller_radius, T(10.0), T(8.0)};
  const auto contacts = lcr::RollerContacts(c.reducer, lcr::Side::kOutput, T(0.3));
  c.effective_radius = c.reducer.output.roller_radius * (T(1.0) - c.reducer.output.roller_radius * contacts[3].curvature);
  return c;
}

/// The ratio-29 cycloid sizing of the sizing tests and benchmarks (studies/examples/
/// cycloid_min_size_ratio29.json is the same problem with the overload): 29 teeth, 30 pins,
/// 20 N·m on the disc, 1500 MPa, 8 mm face; e, a, ρ, Δa, Δρ and (crowned) the LCM coefficient free,
/// starting at a = 35, ρ = 2.5, e = 0.9 mm, Δa −10, Δρ −5 µm, f = 2 µm; 16 × 16 cells, 4 angles per
/// mesh period. overload_Nm > 0 adds the contact-inside-the-face row at that torque.
inline sizing::CycloidSizingSpec CycloidRatio29Sizing(cycloid::CrowningType crowning, double overload_Nm = 0) {
  sizing::CycloidSizingSpec s;
  s.drive.teeth = 29;
  s.drive.rollers = 30;
  s.drive.roller_position_radius_mm = 35;
  s.drive.roller_radius_mm = 2.5;
  s.drive.eccentricity_mm = 0.9;
  s.drive.face_width_mm = 8;
  s.drive.delta_position_mm = -0.010;
  s.drive.delta_radius_mm = -0.005;
  s.crowning.type = crowning;
  s.crowning.coefficient_mm = 0.002;
  s.design_torque_Nmm = 20e3;
  s.overload_torque_Nmm = overload_Nm * 1e3;
  s.angles_per_period = 4;
  s.options.profile_cells = 16;
  s.options.axial_cells = 16;
  s.limits.contact_stress_MPa = 1500;
  s.variables = {{"eccentricity_mm", 0.3, 2.0, 0.9, 0.1},
                 {"roller_position_radius_mm", 8.0, 60.0, 35.0, 10.0},
                 {"roller_radius_mm", 0.5, 5.0, 2.5, 1.0},
                 {"delta_position_um", -30.0, 0.0, -10.0, 10.0},
                 {"delta_radius_um", -30.0, 0.0, -5.0, 10.0}};
  if (crowning == cycloid::CrowningType::kLogarithmic)
    s.variables.push_back({"coefficient_mm", 0.0, 0.02, 0.002, 0.001});
  return s;
}

}  // namespace camopt::testing

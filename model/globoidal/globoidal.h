// Globoidal cam with an oscillating, dual-stopping (two-roller) turret (Ge, Wang & Zhang,
// "Model and simulation of globoidal cam mechanisms with oscillating and dual stopping
// followers", docs/papers.md §5).
//
// Cam frame oxyz: oz is the cam axis, the turret axis lies in the plane oxy at distance C from
// oz, and oy is the projection of the turret's initial line. Roller j (1 = lower, 2 = upper) sits
// at the turret angle φʲ(θ) = φ₀ʲ + p φ_i(θ) (eq. 1), where φ_i is the turret swing given by a
// MotionProgram (motion_program.h; modified sine in the paper, eq. 2) and φ₀ʲ the initial angle
// (eq. 7). The roller axis sweeps the ruled trajectory surface (eq. 4)
//   r(l, θ) = ((C − l cos φʲ) sin θ, (C − l cos φʲ) cos θ, l sin φʲ),
// and the working surface is its offset by the roller radius R along the unit normal toward the
// rib between the two rollers. That offset is exactly the envelope of the roller cylinders: its
// point lies at distance R from the roller axis (the foot is r(l, θ)) and its normal is normal to
// r_θ, the velocity of the roller axis relative to the cam (the meshing condition).
//
// Beyond the paper (documented in docs/globoidal.md): the pressure angle between the contact
// normal and the roller's own velocity, tan α = l φ' /(C − l cos φ); the principal curvatures of
// the trajectory surface from its fundamental forms, the undercut margin 1 − R κ_max (the offset
// folds where it reaches 0) and the working surface's normal curvature across the roller, which
// gives the equivalent radius of eq. (12).
//
// Lengths in mm, angles in rad; all functions are templates over T (double or ceres::Jet).
#pragma once

#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products

#include "model/common/scalar.h"
#include "model/motion/motion_program.h"

namespace camopt::globoidal {

template <typename T>
using Vec3 = Eigen::Matrix<T, 3, 1>;

/// The design of the paper's §2–3.
template <typename T>
struct GloboidalCam {
  T center_distance = T(45.0);  ///< C [mm]
  T roller_radius = T(4.0);     ///< R [mm]
  T pitch_radius = T(22.0);     ///< R_e, turret axis to roller middle [mm]
  T roller_length = T(5.0);     ///< m [mm]
  T clearance = T(1.0);         ///< e, roller end to cam body [mm]
  T roller_angle = T(kPi / 4);  ///< β, angle between the two roller axes [rad]
  T swing = T(kPi / 9);         ///< φ_f, oscillating angle of the turret [rad]
  int direction = 1;            ///< p: +1 when the first motion is clockwise, −1 otherwise
  /// φ_i(θ) [rad] over one cam revolution: rises of +φ_f and −φ_f and dwells.
  motion::MotionProgram<T> motion;
};

/// Eq. (7): initial angle of roller j (1 or 2) with both rollers at their top (t = 1) or bottom
/// (t = −1) dead point: φ₀ʲ = ((−1)^(j−1) β − t φ_f)/2 [rad].
template <typename T>
T InitialAngle(const T& roller_angle, const T& swing, int j, int t) {
  const T sign_j = T(j == 1 ? 1.0 : -1.0);
  return (sign_j * roller_angle - T(double(t)) * swing) / T(2.0);
}

/// Eqs. (8)–(9): the ends of the trajectory surface along the roller axis, measured from the
/// turret axis: l₁ = R_e + m/2 + e (the roller's inner end plus the clearance to the cam body) and
/// l₂ = R_e − m/2 [mm].
template <typename T>
struct AxisLimits {
  T l1, l2;
};
template <typename T>
AxisLimits<T> RollerAxisLimits(const GloboidalCam<T>& cam) {
  return {cam.pitch_radius + cam.roller_length / T(2.0) + cam.clearance,
          cam.pitch_radius - cam.roller_length / T(2.0)};
}

/// Turret angle of roller j and its derivatives with respect to the cam angle.
template <typename T>
struct RollerAngle {
  T phi, dphi, d2phi, d3phi;  ///< φʲ [rad], dφ/dθ, d²φ/dθ², d³φ/dθ³
};

/// Eq. (1) with φ₀ʲ from eq. (7) for t = p: the program starts at the dead point from which the
/// first motion (direction p) leaves, so both rollers' ranges are symmetric about the plane oxy.
template <typename T>
RollerAngle<T> RollerAngleAt(const GloboidalCam<T>& cam, int j, const T& theta) {
  const motion::Svaj<T> s = cam.motion.Evaluate(theta);
  const T p(double(cam.direction));
  return {InitialAngle(cam.roller_angle, cam.swing, j, cam.direction) + p * s.s, p * s.v, p * s.a,
          p * s.j};
}

/// Eq. (4): the point of the roller axis at distance l from the turret axis, in the cam frame.
template <typename T>
Vec3<T> TrajectoryPoint(const GloboidalCam<T>& cam, const T& phi, const T& l, const T& theta) {
  using std::cos;
  using std::sin;
  const T d = cam.center_distance - l * cos(phi);  // eq. (3)
  return Vec3<T>(d * sin(theta), d * cos(theta), l * sin(phi));
}

/// One point of roller j's trajectory surface and of the working surface it generates.
template <typename T>
struct SurfacePoint {
  T l, theta;
  RollerAngle<T> angle;
  Vec3<T> axis_point;  ///< r(l, θ), eq. (4) [mm]
  Vec3<T> axis_dir;    ///< r_l: unit direction of the roller axis, away from the turret axis
  Vec3<T> r_theta;     ///< ∂r/∂θ: velocity of the axis point relative to the cam [mm/rad]
  Vec3<T> swing_dir;   ///< e_φ: direction of the roller's own velocity (turret rotation)
  Vec3<T> turret_axis; ///< e_a: unit vector along the turret axis
  Vec3<T> normal;      ///< unit normal from the roller axis to the working surface (into the rib)
  Vec3<T> working;     ///< working-surface point r + R n [mm]
  T pressure_angle;    ///< α = atan2(l φ', C − l cos φ), signed like φ' [rad]
  T kappa1, kappa2;    ///< principal curvatures of the trajectory surface w.r.t. n [1/mm], κ1 ≥ κ2
  T offset_jacobian;   ///< det(I − R S) = (1 − R κ1)(1 − R κ2): area ratio working/trajectory
  T undercut_margin;   ///< 1 − R κ1: the working surface folds (undercut) where it is ≤ 0
  T working_curvature; ///< normal curvature of the working surface across the roller [1/mm]
                       ///< (direction n × r_l), > 0 where the rib is convex there
  T contact_radius;    ///< eq. (12) equivalent radius 1/(1/R + working_curvature) [mm]
};

/// Evaluates roller j's surfaces at (l, θ). The normal's side is chosen on the value of n·e_φ,
/// which never vanishes (its magnitude is (C − l cos φ)/|r_l × r_θ| > 0 for l cos φ < C).
template <typename T>
SurfacePoint<T> EvaluateSurface(const GloboidalCam<T>& cam, int j, const T& l, const T& theta) {
  using std::atan2;
  using std::cos;
  using std::sin;
  using std::sqrt;
  SurfacePoint<T> p;
  p.l = l;
  p.theta = theta;
  p.angle = RollerAngleAt(cam, j, theta);
  const T phi = p.angle.phi, f1 = p.angle.dphi, f2 = p.angle.d2phi;
  const T cp = cos(phi), sp = sin(phi), ct = cos(theta), st = sin(theta);
  const T d = cam.center_distance - l * cp;
  const T d1 = l * sp * f1;                         // ∂d/∂θ
  const T d2 = l * (cp * f1 * f1 + sp * f2);        // ∂²d/∂θ²
  p.axis_point = Vec3<T>(d * st, d * ct, l * sp);
  p.axis_dir = Vec3<T>(-cp * st, -cp * ct, sp);
  p.r_theta = Vec3<T>(d1 * st + d * ct, d1 * ct - d * st, l * cp * f1);
  const Vec3<T> r_lt(sp * f1 * st - cp * ct, sp * f1 * ct + cp * st, cp * f1);
  const Vec3<T> r_tt(d2 * st + T(2.0) * d1 * ct - d * st, d2 * ct - T(2.0) * d1 * st - d * ct,
                     l * (cp * f2 - sp * f1 * f1));
  p.swing_dir = Vec3<T>(sp * st, sp * ct, cp);
  p.turret_axis = Vec3<T>(ct, -st, T(0.0));

  // Normal toward the rib: roller 1 (larger φ) touches the rib on its −e_φ side, roller 2 on its
  // +e_φ side.
  Vec3<T> n = p.axis_dir.cross(p.r_theta);
  n /= sqrt(n.squaredNorm());
  const double want = j == 1 ? -1.0 : 1.0;
  if (Value(n.dot(p.swing_dir)) * want < 0.0) n = -n;  // a sign choice, not a kink (see above)
  p.normal = n;
  p.working = p.axis_point + cam.roller_radius * n;
  const T sigma(want);
  p.pressure_angle = atan2(-sigma * n.dot(p.turret_axis), sigma * n.dot(p.swing_dir));

  // Fundamental forms of r (E = 1 since r_l is a unit vector; r_ll = 0 on a ruled surface).
  const T E = p.axis_dir.squaredNorm(), F = p.axis_dir.dot(p.r_theta),
          G = p.r_theta.squaredNorm();
  const T L(0.0), M = r_lt.dot(n), N = r_tt.dot(n);
  const T det_i = E * G - F * F;
  // Shape operator S = I⁻¹ II (in the (l, θ) coordinates).
  const T s11 = (G * L - F * M) / det_i, s12 = (G * M - F * N) / det_i;
  const T s21 = (E * M - F * L) / det_i, s22 = (E * N - F * M) / det_i;
  const T H = (s11 + s22) / T(2.0), K = s11 * s22 - s12 * s21;
  const T disc = H * H - K;  // ≥ 0; zero only at planar points (then both κ vanish)
  const T root = IfThenElse(Compare::kGreater, disc, 0.0,
                            sqrt(IfThenElse(Compare::kGreater, disc, 0.0, disc, T(1.0))), T(0.0));
  p.kappa1 = H + root;
  p.kappa2 = H - root;
  const T R = cam.roller_radius;
  p.offset_jacobian = T(1.0) - T(2.0) * R * H + R * R * K;
  p.undercut_margin = T(1.0) - R * p.kappa1;

  // Normal curvature of the working surface across the roller: S_W = S (I − R S)⁻¹, applied to the
  // unit tangent t = n × r_l written in (l, θ) coordinates.
  const Vec3<T> t = n.cross(p.axis_dir);
  const T tl = t.dot(p.axis_dir), tt = t.dot(p.r_theta);
  const T ca = (G * tl - F * tt) / det_i, cb = (E * tt - F * tl) / det_i;
  const T a11 = T(1.0) - R * s11, a12 = -R * s12, a21 = -R * s21, a22 = T(1.0) - R * s22;
  const T det_a = a11 * a22 - a12 * a21;  // = offset_jacobian
  // (I − R S)⁻¹ c, then S applied.
  const T ya = (a22 * ca - a12 * cb) / det_a, yb = (-a21 * ca + a11 * cb) / det_a;
  const T za = s11 * ya + s12 * yb, zb = s21 * ya + s22 * yb;
  // <S_W t, t> with the metric of r: zᵀ I c.
  p.working_curvature = za * (E * ca + F * cb) + zb * (F * ca + G * cb);
  p.contact_radius = T(1.0) / (T(1.0) / R + p.working_curvature);
  return p;
}

/// Closed form of the pressure angle (derived in docs/globoidal.md): tan α = l φ'/(C − l cos φ).
template <typename T>
T PressureAngleClosedForm(const GloboidalCam<T>& cam, const RollerAngle<T>& a, const T& l) {
  using std::atan2;
  using std::cos;
  return atan2(l * a.dphi, cam.center_distance - l * cos(a.phi));
}

/// The paper's motion program: rise of φ_f over θ_f1, dwell, return over θ_f2, dwell, all with
/// one law (modified sine in the paper). Angles in rad.
template <typename T>
motion::MotionProgram<T> RiseDwellReturnDwell(motion::MotionLaw law, const T& swing,
                                              const T& rise_angle, const T& dwell1,
                                              const T& return_angle, const T& dwell2) {
  return motion::MotionProgram<T>({{law, swing, rise_angle},
                                   {motion::MotionLaw::kDwell, T(0.0), dwell1},
                                   {law, -swing, return_angle},
                                   {motion::MotionLaw::kDwell, T(0.0), dwell2}});
}

}  // namespace camopt::globoidal

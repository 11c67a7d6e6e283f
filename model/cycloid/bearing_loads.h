// Loads and speeds of the cycloid stage's rolling bearings for the rating life
// (model/common/bearing_life.h, ISO 281): the crank (eccentric) bearing that carries the disc on the
// input shaft's eccentric, and the ring pins where they are rolling elements (rollers on needle or
// roller sleeves on their pins). docs/life.md, "Cycloid".
//
// Frames as tooth_profile.h: fixed frame, crank angle φ, disc centre D = e u(φ), the disc turned by
// −φ/n2 + β (β the disc lag, the LTE) from the fixed frame. The crank frame turns with the crank:
// its x axis is u(φ), the eccentricity direction.
//
// Ring-pin forces. Pair i presses the tooth along its contact normal N_i (unloaded TCA, disc
// frame; N points from the disc towards the roller), so the roller's force on the disc is −F_i N_i,
// F_i the LTCA's load (eq. 25). The normals of a conjugate cycloid mesh pass through the pitch point
// I = D + n2 e u(φ) (Aronhold–Kennedy: I is the instant centre of the disc relative to the ring,
// where the disc's motion, centre speed e and spin −1/n2 per crank radian, has zero velocity). With
// profile modifications Δa, Δρ the contact moves along the tooth and its normal misses I: NNM on the
// paper's drive, by up to 0.60 mm (0.9% of the pitch radius) on the pairs that can carry load and up to
// 1.2 mm near a tip (tests/cycloid_bearing_life_test.cc). The forces use the true normals.
//
// Output mechanism: rigid, zero-clearance output pins (the classical pin-and-hole mechanism: pins of
// radius r_w on a circle R_w of the output flange in holes of radius r_w + e of the disc). Each hole
// centre is its pin centre plus e u(φ), so every pin–hole contact lies on the line through the pin
// centre along u(φ) and every pin force on the disc is −Q_j u(φ), parallel to the eccentricity.
// A pin at the angle φ_j from the crank direction touches its hole on the loaded side when
// sin φ_j > 0; a small rotation of the disc against the output closes pin j's gap by R_w δ sin φ_j,
// so with equal stiffness Q_j = Q_max max(0, sin φ_j), and the moment balance Σ Q_j R_w sin φ_j = T
// gives Q_max = T / (R_w Σ max(0, sin φ_j)²): the sine distribution of the output rollers' forces of
// Blagojević, Marjanović, Đorđević, Stojanović, Disić, "A new design of a two-stage cycloidal speed
// reducer", J. Mech. Des. 133 (2011) 085001, and of Gorla, Davoli, Rosa, Longoni, Chiozzi, Samarani,
// "Theoretical and experimental analysis of a cycloidal speed reducer", J. Mech. Des. 130 (2008)
// 112604 (their force analyses of the output rollers). For an even
// pin count Σ max(0, sin φ_j)² = N_w/4 exactly; as N_w → ∞ the resultant Σ Q_j tends to 4T/(π R_w)
// (Q_max → 4T/(N_w R_w), Σ max(0, sin φ_j) → N_w/π), the continuous limit used when no pin count
// is given. The pins turn with the output at −φ/n2, so φ_j = 2πj/N_w − φ n1/n2 (pin 0 on the x axis
// at φ = 0; the disc's lag, arcseconds, is left out of the output side).
//
// Crank bearing: the disc is in equilibrium under the ring-pin forces, the output-pin forces and
// the bearing's force B (frictionless: B passes through the disc centre), so
// B = −(Σ_i −F_i N_i + Σ_j −Q_j u(φ)). Its magnitude is the bearing's radial load. The state at
// φ + 2π/n1 is the state at φ turned by 2π/n1 (rollers relabelled; docs/cycloid.md, "Mesh period"),
// so the ring-pin resultant is periodic in the crank frame with the mesh period; the output pins'
// pattern repeats every 2π n2/(n1 N_w) of crank angle, and |B| every 2π n2/(n1 gcd(n2, N_w)).
// The bearing's rings turn relative to each other at φ̇ − (−φ̇/n2): n1/n2 revolutions per input
// revolution.
//
// Ring-pin spin (pure rolling on the tooth). The disc moves about the instant centre I at −1/n2 per
// crank radian; the roller turns about its fixed pin at ω_r. No slip at the contact point C
// (C = O_i − ρ n, n the normal in the fixed frame) equates the tangential velocities:
// ω_r (C − O_i)·n = ω_d (C − I)·n, so ω_r = (C − I)·n / (n2 ρ) per crank radian. For the unmodified
// tooth C, O_i and I are collinear and (C − I)·n = S − ρ, S = |O_i − I| =
// (a² + (n1 e)² − 2 a n1 e cos(ψ_i − φ))^½; over one input revolution the phase ψ_i − φ runs once
// through 2π, and ⟨S⟩ = (2/π)(A + B) E(2√(AB)/(A + B)), A = a, B = n1 e (E the complete elliptic
// integral of the second kind), so a roller turns (⟨S⟩ − ρ)/(n2 ρ) times per input revolution
// (e → 0: (a − ρ)/(n2 ρ), a roller between a fixed ring and the disc turning at 1/n2).
#pragma once

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "model/common/bearing_life.h"
#include "model/common/geometry.h"
#include "model/common/scalar.h"
#include "model/cycloid/loaded_tca.h"
#include "model/cycloid/unloaded_tca.h"

namespace camopt::cycloid {

/// The rigid output-pin mechanism: pin_count pins on the output flange's circle of radius
/// pin_circle_radius_mm, in holes of radius (pin radius + e) of the disc. pin_count 0: the
/// continuous limit (a resultant of 4T/(π R_w)).
struct OutputMechanism {
  int pin_count = 0;
  double pin_circle_radius_mm = 0.0;
};

/// The output pins' forces on the disc at crank angle φ [rad] under the disc torque T [N·mm]:
/// the magnitude of their resultant Σ Q_j [N] (the resultant on the disc is −Σ Q_j u(φ)), and each
/// Q_j when `pin_forces` is given (pin_count > 0). Rigid pins, zero clearance (header comment).
/// @tparam T double or ceres::Jet.
/// @throws std::invalid_argument for R_w <= 0, a negative pin count, or 1–2 pins (no moment).
template <typename T>
T OutputPinResultant(const OutputMechanism& m, int teeth, const T& torque_Nmm, const T& crank,
                     std::vector<T>* pin_forces = nullptr) {
  using std::sin;
  if (!(m.pin_circle_radius_mm > 0.0 && std::isfinite(m.pin_circle_radius_mm)))
    throw std::invalid_argument("output mechanism: pin_circle_radius_mm must be finite and > 0");
  if (m.pin_count < 0 || m.pin_count == 1 || m.pin_count == 2)
    throw std::invalid_argument("output mechanism: pin_count must be 0 (continuous) or >= 3, found " +
                                std::to_string(m.pin_count));
  if (pin_forces) pin_forces->clear();
  if (m.pin_count == 0) return T(4.0 / kPi) * torque_Nmm / m.pin_circle_radius_mm;
  const T turn = crank * (double(teeth + 1) / double(teeth));  // φ n1/n2
  std::vector<T> s(size_t(m.pin_count));
  T sum_sq(0.0), sum(0.0);
  for (int j = 0; j < m.pin_count; ++j) {
    const T sj = sin(T(2.0 * kPi * j / m.pin_count) - turn);
    s[size_t(j)] = Value(sj) > 0.0 ? sj : T(0.0);  // a pin off its loaded side carries nothing
    sum_sq += s[size_t(j)] * s[size_t(j)];
    sum += s[size_t(j)];
  }
  const T q_max = torque_Nmm / (m.pin_circle_radius_mm * sum_sq);
  if (pin_forces)
    for (const T& sj : s) pin_forces->push_back(q_max * sj);
  return q_max * sum;
}

/// The period of the output pins' resultant in crank angle measured in mesh periods 2π/n1:
/// n2 / gcd(n2, N_w) (1 in the continuous limit).
inline int OutputPinPeriodInMeshPeriods(const OutputMechanism& m, int teeth) {
  return m.pin_count == 0 ? 1 : teeth / std::gcd(teeth, m.pin_count);
}

/// The pitch point I (instant centre of the disc relative to the ring) in the disc frame at crank
/// angle φ with the disc lag β: n2 e u(φ) from the disc centre, turned into the disc frame.
template <typename T>
Vec2<T> PitchPointInDisc(const DriveTpl<T>& d, const T& crank, const T& lag) {
  return Rotate(Vec2<T>(T(double(d.teeth)) * d.eccentricity_mm * U(crank)), T(crank / double(d.teeth) - lag));
}

/// The roller's spin relative to its pin per crank radian, |(C − I)·N| / (n2 ρ) (pure rolling on
/// the tooth; header comment), from the unloaded TCA's contact point C and normal N of the pair.
/// @tparam T double or ceres::Jet.
template <typename T>
T RollerSpinRate(const DriveTpl<T>& d, const PairGeometry<T>& g, const T& crank) {
  using std::abs;
  const Vec2<T> pitch = PitchPointInDisc(d, crank, T(0.0));
  return abs((g.point - pitch).dot(g.normal)) / (T(double(d.teeth)) * d.roller_radius_mm);
}

/// The revolutions of the crank bearing's rings relative to each other per input revolution:
/// 1 + 1/n2 = n1/n2 (the crank turns +1, the disc −1/n2).
inline double CrankBearingRevolutionsPerInputRevolution(const Drive& d) {
  return double(d.rollers) / double(d.teeth);
}

/// A vector of the disc frame in the crank frame (x along u(φ)): turned by β − φ n1/n2.
template <typename T>
Vec2<T> DiscToCrankFrame(const DriveTpl<T>& d, const Vec2<T>& v, const T& crank, const T& lag) {
  return Rotate(v, T(lag - crank * (double(d.rollers) / double(d.teeth))));
}

/// The ring-pin forces' resultant on the disc, Σ −F_i N_i, in the crank frame: the pairs' loads F_i
/// (roller index, load [N]) with the normals N_i of the unloaded TCA `u` at crank angle φ, the disc
/// lag β turning the disc frame. Over T, so that a sizing's loads, normals and lag carry derivatives.
template <typename T>
Vec2<T> RingPinResultantCrankFrame(const DriveTpl<T>& d, const UnloadedMesh<T>& u,
                                   const std::vector<std::pair<int, T>>& loads, const T& crank, const T& lag) {
  Vec2<T> sum(T(0.0), T(0.0));
  for (const auto& [roller, load] : loads) sum -= load * u.pairs.at(size_t(roller)).normal;
  return DiscToCrankFrame(d, sum, crank, lag);
}

/// The same at one solved mesh (loads from the LTCA, normals from the unloaded TCA at the mesh's
/// crank angle, the lag the mesh's LTE), and the forces' moment about the disc centre [N·mm] through
/// `moment_Nmm` (Σ C_i × −F_i N_i, C_i the contact point; −T at equilibrium).
inline Vec2<double> RingPinResultantCrankFrame(const Drive& d, const MeshLoad& mesh, double* moment_Nmm = nullptr) {
  const UnloadedMesh<double> u = UnloadedTca<double>(d, mesh.crank_angle_rad);
  std::vector<std::pair<int, double>> loads;
  double moment = 0.0;
  for (const PairLoad& p : mesh.pairs) {
    loads.push_back({p.roller, p.load_N});
    const PairGeometry<double>& g = u.pairs.at(size_t(p.roller));
    moment += Cross(g.point, Vec2<double>(-p.load_N * g.normal));
  }
  if (moment_Nmm) *moment_Nmm = moment;
  return RingPinResultantCrankFrame(d, u, loads, mesh.crank_angle_rad, mesh.rotation_rad);
}

/// The classic rigid-body ring-pin loads of the unmodified tooth (equal, rigid-body compliance; no
/// modification, no clearance): every normal passes through the pitch point I = D + n2 e u(φ)
/// (Aronhold–Kennedy), a disc rotation Δφ closes pair i by l_i Δφ with l_i its arm about the disc
/// centre (eq. 26; l_i = e n2 sin α_i, α_i the angle between the normal and the line of centres), so
/// with equal stiffness F_i ∝ l_i ∝ sin α_i on the loaded flank (l_i > 0) and the moment balance
/// Σ F_i l_i = T gives F_i = T l_i / Σ_{l_k > 0} l_k² (Blanche & Yang, "Cycloid drives with machining
/// tolerances", J. Mech. Transm. Autom. Des. 111 (1989) 337; Gorla et al. 2008, eqs. of the
/// rigid-body force analysis). Returns (roller, F_i [N]) for every loaded pin and, through
/// `resultant_crank_frame`, Σ −F_i N_i in the crank frame (N_i = unit(O_i − I), towards the roller).
/// @throws std::invalid_argument for a modified tooth (its normals miss I).
inline std::vector<std::pair<int, double>> RigidRingPinLoads(const Drive& d, double torque_Nmm, double crank,
                                                             Vec2<double>* resultant_crank_frame = nullptr) {
  if (d.delta_position_mm != 0.0 || d.delta_radius_mm != 0.0)
    throw std::invalid_argument("rigid ring-pin loads: the closed form holds for the unmodified tooth only");
  const Vec2<double> centre = d.eccentricity_mm * U(crank);
  const Vec2<double> pitch = double(d.rollers) * d.eccentricity_mm * U(crank);
  std::vector<double> arm(size_t(d.rollers));
  std::vector<Vec2<double>> normal(size_t(d.rollers));
  double sum_sq = 0.0;
  for (int i = 0; i < d.rollers; ++i) {
    const Vec2<double> o = d.roller_position_radius_mm * U(2.0 * kPi * i / d.rollers);
    normal[size_t(i)] = (o - pitch).normalized();
    arm[size_t(i)] = Cross(Vec2<double>(o - centre), normal[size_t(i)]);
    if (arm[size_t(i)] > 0.0) sum_sq += arm[size_t(i)] * arm[size_t(i)];
  }
  std::vector<std::pair<int, double>> loads;
  Vec2<double> sum(0.0, 0.0);
  for (int i = 0; i < d.rollers; ++i)
    if (arm[size_t(i)] > 0.0) {
      const double f = torque_Nmm * arm[size_t(i)] / sum_sq;
      loads.push_back({i, f});
      sum -= f * normal[size_t(i)];
    }
  if (resultant_crank_frame) *resultant_crank_frame = Rotate(sum, -crank);
  return loads;
}

/// The crank bearing's force on the disc in the crank frame from the ring-pin resultant G (crank
/// frame) and the output pins' resultant magnitude Q: B = −G + Q (1, 0).
template <typename T>
Vec2<T> CrankBearingForce(const Vec2<T>& ring_resultant_crank_frame, const T& output_resultant_N) {
  return Vec2<T>(output_resultant_N - ring_resultant_crank_frame.x(), -ring_resultant_crank_frame.y());
}

/// True when the crank angles [rad] are a uniform sampling of whole mesh periods 2π/n1; `periods`
/// receives how many.
inline bool UniformWholeMeshPeriods(const std::vector<double>& a, int rollers, int* periods = nullptr) {
  const size_t n = a.size();
  if (n < 1) return false;
  const double tau = 2.0 * kPi / rollers;
  const double step = n == 1 ? tau : a[1] - a[0];
  for (size_t k = 1; k < n; ++k)
    if (std::abs(a[k] - a[k - 1] - step) > 1e-9 * std::max(1.0, std::abs(step))) return false;
  const double p = step * double(n) / tau;
  if (!(step > 0) || std::abs(p - std::round(p)) > 1e-6 || std::round(p) < 1) return false;
  if (periods) *periods = int(std::round(p));
  return true;
}

/// The crank bearing's load |B| [N] over its whole load period from the ring-pin resultants G_k
/// (crank frame) at a uniform sampling φ_k of P whole mesh periods (N angles; G is periodic with the
/// mesh period in the crank frame): G_k with the output pins at φ_k + m P 2π/n1, m = 0 … M' − 1,
/// M' P a multiple of the output pins' period (OutputPinPeriodInMeshPeriods): N M' uniform samples.
/// @tparam T double or ceres::Jet (G carries the derivatives; the output pins' forces depend on the
/// torque and the crank angle only).
/// @throws std::invalid_argument when the angles are not such a sampling.
template <typename T>
std::vector<T> CrankBearingLoadsOverPeriod(const Drive& d, const OutputMechanism& m,
                                           const std::vector<Vec2<T>>& ring_resultants,
                                           const std::vector<double>& angles, double torque_Nmm) {
  using std::sqrt;
  int periods = 0;
  if (ring_resultants.size() != angles.size() || !UniformWholeMeshPeriods(angles, d.rollers, &periods))
    throw std::invalid_argument("crank bearing load: the crank angles must sample whole mesh periods uniformly");
  const int pin_period = OutputPinPeriodInMeshPeriods(m, d.teeth);
  const int repeats = pin_period / std::gcd(pin_period, periods);
  const double tau = 2.0 * kPi / d.rollers;
  std::vector<T> out;
  for (int r = 0; r < repeats; ++r)
    for (size_t k = 0; k < angles.size(); ++k) {
      const double q = OutputPinResultant<double>(m, d.teeth, torque_Nmm, angles[k] + r * periods * tau);
      const Vec2<T> b = CrankBearingForce(ring_resultants[k], T(q));
      const T b2 = b.squaredNorm();
      out.push_back(Value(b2) > 0.0 ? sqrt(b2) : T(0.0));  // no load: 0 with a zero derivative
    }
  return out;
}

/// The same from a cycle's meshes (double).
inline std::vector<double> CrankBearingLoads(const Drive& d, const OutputMechanism& m,
                                             const std::vector<MeshLoad>& meshes, double torque_Nmm) {
  std::vector<double> angles;
  std::vector<Vec2<double>> ring;
  for (const MeshLoad& mesh : meshes) {
    angles.push_back(mesh.crank_angle_rad);
    ring.push_back(RingPinResultantCrankFrame(d, mesh));
  }
  return CrankBearingLoadsOverPeriod(d, m, ring, angles, torque_Nmm);
}

/// The ring pins' loads and spin rates at every (crank angle, roller) of a cycle's meshes: every
/// roller carries the same load as a function of its phase ψ_i − φ, so over a uniform sampling of
/// whole mesh periods these are one roller's load at uniform phases of its period (one input
/// revolution). Spin rates per crank radian (RollerSpinRate), the weights of the revolution-weighted
/// equivalent load; their mean is the revolutions per input revolution.
struct PinLoadSamples {
  std::vector<double> load_N, spin_rate;
};
inline PinLoadSamples PinBearingLoads(const Drive& d, const std::vector<MeshLoad>& meshes) {
  PinLoadSamples out;
  for (const MeshLoad& mesh : meshes) {
    const UnloadedMesh<double> u = UnloadedTca<double>(d, mesh.crank_angle_rad);
    std::vector<double> load(size_t(d.rollers), 0.0);
    for (const PairLoad& p : mesh.pairs) load.at(size_t(p.roller)) = p.load_N;
    for (int i = 0; i < d.rollers; ++i) {
      out.load_N.push_back(load[size_t(i)]);
      out.spin_rate.push_back(RollerSpinRate(d, u.pairs[size_t(i)], mesh.crank_angle_rad));
    }
  }
  return out;
}

/// One duty-cycle line's samples of a bearing's load: its time share t_i, input speed n_i [rpm],
/// the load [N] at uniform samples of the bearing's load period and each sample's weight (the
/// bearing's rotation over it; equal weights for a constant speed).
struct BearingLineSamples {
  double time_share = 1.0, input_speed_rpm = 0.0;
  std::vector<double> load_N, weight;
};

/// A bearing's life over a duty cycle (docs/life.md, "Cycloid"): model/common/bearing_life.h's.
using camopt::BearingLifeOverCycle;

/// P_i of each line (EquivalentLoad with the weights), then Palmgren–Miner over the lines at the
/// bearing's speeds n_i R: 1/L10h = Σ t_i 60 n_i R (P_i/C)^p / 10⁶ (DutyCycleLifeHours on one-sample
/// lines), P = DutyCycleEquivalentLoad, L10 = (C/P)^p. A line without load (torque 0) has P_i = 0.
/// @throws std::invalid_argument as DutyCycleLifeHours (C <= 0, shares, speeds).
inline BearingLifeOverCycle LifeOverDutyCycle(double dynamic_rating_N, BearingKind kind,
                                              double revolutions_per_input_revolution,
                                              const std::vector<BearingLineSamples>& lines) {
  BearingLifeOverCycle out;
  out.revolutions_per_input_revolution = revolutions_per_input_revolution;
  std::vector<double> shares, speeds;
  for (const BearingLineSamples& l : lines) {
    out.line_equivalent_load_N.push_back(EquivalentLoad(l.load_N, l.weight, kind));
    out.max_load_N = std::max(out.max_load_N, *std::max_element(l.load_N.begin(), l.load_N.end()));
    shares.push_back(l.time_share);
    speeds.push_back(l.input_speed_rpm);
  }
  CombineDutyCycleLines(dynamic_rating_N, kind, shares, speeds, out);
  return out;
}

}  // namespace camopt::cycloid

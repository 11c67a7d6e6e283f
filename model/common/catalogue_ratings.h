// The numbers a precision-reducer catalogue prints besides its bearing ratings, computed as the
// catalogues define them: the three-segment torsional stiffness K1, K2, K3 of the loading branch,
// the angle at any torque, lost motion, hysteresis loss, angular transmission accuracy, the allowed
// number of momentary (emergency-stop) peak torques, and the rated torque at which a life law meets
// a target life. Plain functions on values (double): they process a torsion curve or samples, or
// search a torque; the physics that produces the curve or the life lives elsewhere.
//
// Sources (definitions cited, not copied; equation numbers as printed):
//   [HDAG-CSD] Harmonic Drive AG, "CSD-2A Component Sets, Engineering Data" (1019659, 11/2014),
//              §4.2 "Calculation of the Torsion Angle", eq. 23.1–23.4, with the worked example
//              HFUC-32-100-2UH (T = 60 N·m → φ = 7.15·10⁻⁴ rad = 2.5 arcmin).
//   [HDAG-CHA] Harmonic Drive AG, "CHA series" manual (1018854), "Terminology": torsional
//              stiffness K1, K2, K3 over 0–T1, T1–T2, above T2 (linearisation of the torque–torsion
//              curve, wave generator locked); transmission accuracy "measured over one output
//              revolution without direction reversal, the sum of the largest positive and negative
//              differences between the theoretical and the actual output angle"; lost motion
//              measured on the hysteresis curve at a small fraction of the rated torque.
//   [HDAG-SHG] Harmonic Drive AG, "SHG series" engineering data (1021387, 12/2018), §4.1.1
//              "Torque based dimensioning", eq. 30.10: allowable number of momentary peak torques
//              N = 10⁴ / (2 · n_k/60 · i · t_k), n_k the OUTPUT speed at the peak, i the ratio,
//              t_k its duration (same in the HFUS-2A engineering data, eq. 19.10).
//   [NAB-RV]   Nabtesco, "Precision reduction gear RV" catalogues, "rigidity and lost motion": lost
//              motion is the angle between the mid-points of the hysteresis curve's width at ±3 %
//              of the rated torque; the width at zero torque is the backlash (read through the
//              paraphrase at http://www.chietom.net/News_info/id/641.html; the catalogue page
//              itself was not reachable).
//   [HDL-CSF]  Harmonic Drive LLC, "CSF & CSG Series" catalogue, "Hysteresis Loss" (listed in its
//              contents; the page itself was not reachable): taken as the angle between the two
//              branches at zero torque after loading to +T_r and to −T_r, the loop 0→A→B→A′→B′ of
//              Harmonic Drive's RSF supermini manual §1-8 "Torsional stiffness".
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "model/common/argument_check.h"
#include "model/common/scalar.h"

namespace camopt {

/// Minutes of arc per radian, 10800/π (catalogues give stiffness in N·m/rad or N·m/arcmin).
inline constexpr double kArcminPerRad = 10800.0 / kPi;

/// One point of a torque–torsion curve: the output torque and the output angle (input locked).
struct TorsionPoint {
  double torque_Nm = 0.0;     ///< T [N·m]
  double angle_arcmin = 0.0;  ///< θ [arcmin]
};

/// The three-segment stiffness of a loading branch ([HDAG-CHA], [HDAG-CSD] eq. 23.1–23.3).
struct ThreeSegmentStiffness {
  double k1_Nm_per_arcmin = 0.0;  ///< K1 = T1 / (θ(T1) − θ(0+)), over 0–T1
  double k2_Nm_per_arcmin = 0.0;  ///< K2 = (T2 − T1) / (θ(T2) − θ(T1)), over T1–T2
  double k3_Nm_per_arcmin = 0.0;  ///< K3 = (T_r − T2) / (θ(T_r) − θ(T2)), over T2–T_r
  double contact_angle_arcmin = 0.0;  ///< θ(0+): where positive torque starts (after the lost-motion region)
};

/// Angular transmission accuracy from samples over one output revolution ([HDAG-CHA]).
struct TransmissionAccuracy {
  double largest_positive_arcmin = 0.0;  ///< max_k e_k >= 0 (e_0 = 0)
  double largest_negative_arcmin = 0.0;  ///< min_k e_k <= 0
  double accuracy_arcmin = 0.0;          ///< their difference: the catalogue's accuracy
};

namespace catalogue_ratings_internal {

// model/common/argument_check.h, its messages starting "catalogue ratings: ".
inline constexpr const char* kWhat = "catalogue ratings";
[[noreturn]] inline void Reject(const std::string& f, const std::string& r, double v) { argument_check::Reject(kWhat, f, r, v); }
inline void CheckPositive(const std::string& field, double v) { argument_check::Positive(kWhat, field, v); }

/// Which limit a branch takes at a torque it crosses at zero torque over a lost-motion region.
enum class Side { kFromAbove, kFromBelow };

/// A branch ordered by ascending torque: strictly increasing torque except a run of equal torques
/// at 0 (the lost-motion region, where the angle moves without torque); angles non-decreasing;
/// every value finite; at least two points.
inline void CheckAscendingBranch(const std::string& name, const std::vector<TorsionPoint>& b) {
  if (b.size() < 2) Reject(name + ".size()", ">= 2", double(b.size()));
  for (size_t k = 0; k < b.size(); ++k) {
    const std::string at = name + "[" + std::to_string(k) + "]";
    if (!std::isfinite(b[k].torque_Nm)) Reject(at + ".torque_Nm", "finite", b[k].torque_Nm);
    if (!std::isfinite(b[k].angle_arcmin)) Reject(at + ".angle_arcmin", "finite", b[k].angle_arcmin);
    if (k == 0) continue;
    const TorsionPoint &p = b[k - 1], &q = b[k];
    if (!(q.torque_Nm > p.torque_Nm || (q.torque_Nm == 0.0 && p.torque_Nm == 0.0)))
      Reject(at + ".torque_Nm",
             "> the previous point's " + std::to_string(p.torque_Nm) +
                 " (torque strictly increasing along the branch; only torque 0 may repeat, over the lost motion)",
             q.torque_Nm);
    if (!(q.angle_arcmin >= p.angle_arcmin))
      Reject(at + ".angle_arcmin", ">= the previous point's " + std::to_string(p.angle_arcmin) + " (angle non-decreasing)",
             q.angle_arcmin);
  }
}

/// θ at torque t on an ascending branch by linear interpolation. Where the branch has a run of
/// points at t = 0, kFromAbove gives the last (the angle where positive torque starts) and
/// kFromBelow the first (where negative torque ends).
inline double AngleAt(const std::vector<TorsionPoint>& b, double t, Side side, const std::string& name) {
  if (!std::isfinite(t)) Reject("torque_Nm", "finite", t);
  if (!(t >= b.front().torque_Nm && t <= b.back().torque_Nm))
    Reject("torque_Nm", "within " + name + "'s range [" + std::to_string(b.front().torque_Nm) + ", " +
                            std::to_string(b.back().torque_Nm) + "]",
           t);
  // The first point with torque >= t, or the last with torque <= t.
  if (side == Side::kFromBelow) {
    size_t k = 0;
    while (b[k].torque_Nm < t) ++k;  // b.back().torque_Nm >= t stops it
    if (k == 0 || b[k].torque_Nm == t) return b[k].angle_arcmin;
    const TorsionPoint &p = b[k - 1], &q = b[k];
    return p.angle_arcmin + (q.angle_arcmin - p.angle_arcmin) * (t - p.torque_Nm) / (q.torque_Nm - p.torque_Nm);
  }
  size_t k = b.size() - 1;
  while (b[k].torque_Nm > t) --k;  // b.front().torque_Nm <= t stops it
  if (k == b.size() - 1 || b[k].torque_Nm == t) return b[k].angle_arcmin;
  const TorsionPoint &p = b[k], &q = b[k + 1];
  return p.angle_arcmin + (q.angle_arcmin - p.angle_arcmin) * (t - p.torque_Nm) / (q.torque_Nm - p.torque_Nm);
}

/// An unloading branch (torque descending) checked and turned into ascending order. Its angles
/// fall with the torque, so in ascending order they rise like a loading branch's.
inline std::vector<TorsionPoint> AscendingFromDescending(const std::string& name, const std::vector<TorsionPoint>& b) {
  std::vector<TorsionPoint> a(b.rbegin(), b.rend());
  CheckAscendingBranch(name + " (reversed: its torque must descend)", a);
  return a;
}

}  // namespace catalogue_ratings_internal

/// The angle of a loading branch at a torque, by linear interpolation between its points. The
/// branch runs in ascending torque (strictly, except repeated points at torque 0 over a lost-motion
/// region) with non-decreasing angles, and may span both signs. At torque 0 on a lost-motion region
/// the angle is θ(0+), the right limit: where positive torque starts (first contact).
/// @throws std::invalid_argument for a malformed branch (fewer than 2 points, a non-finite value,
/// torque not increasing, angle decreasing) or a torque outside the branch's range.
inline double TorsionAngleAt(const std::vector<TorsionPoint>& loading_branch, double torque_Nm) {
  catalogue_ratings_internal::CheckAscendingBranch("loading_branch", loading_branch);
  return catalogue_ratings_internal::AngleAt(loading_branch, torque_Nm,
                                             catalogue_ratings_internal::Side::kFromAbove, "loading_branch");
}

/// The three-segment torsional stiffness of a loading branch ([HDAG-CHA] K1, K2, K3; [HDAG-CSD]
/// eq. 23.1–23.3 read backwards):
///   K1 = T1 / (θ(T1) − θ(0+)),  K2 = (T2 − T1) / (θ(T2) − θ(T1)),  K3 = (T_r − T2) / (θ(T_r) − θ(T2)),
/// θ by linear interpolation (TorsionAngleAt). θ(0+) is the angle at first contact: where the
/// branch leaves torque 0 after the lost-motion region (the last of its points at torque 0), so
/// the backlash is not counted as compliance. This is the catalogues' convention: Harmonic Drive
/// measures φ1 from the zero-torque point of its (backlash-free) gear, φ1 = T1/K1, and a curve
/// whose lost-motion region is given as points at zero torque reduces to that.
/// @param t1_Nm T1, @param t2_Nm T2, @param rated_torque_Nm T_r: 0 < T1 < T2 < T_r, all within the
/// branch's range. The branch must include torque 0 (its points at 0 mark θ(0+)).
/// @throws std::invalid_argument for a malformed branch, torques out of order or range, a branch
/// without a point at or crossing torque 0, or an angle that does not rise over a segment (K not
/// finite and > 0).
inline ThreeSegmentStiffness ThreeSegmentTorsionalStiffness(const std::vector<TorsionPoint>& loading_branch,
                                                            double t1_Nm, double t2_Nm, double rated_torque_Nm) {
  using namespace catalogue_ratings_internal;
  CheckAscendingBranch("loading_branch", loading_branch);
  CheckPositive("T1_Nm (t1_Nm)", t1_Nm);
  if (!(std::isfinite(t2_Nm) && t2_Nm > t1_Nm)) Reject("T2_Nm (t2_Nm)", "finite and > T1 = " + std::to_string(t1_Nm), t2_Nm);
  if (!(std::isfinite(rated_torque_Nm) && rated_torque_Nm > t2_Nm))
    Reject("T_r_Nm (rated_torque_Nm)", "finite and > T2 = " + std::to_string(t2_Nm), rated_torque_Nm);
  if (!(loading_branch.front().torque_Nm <= 0.0))
    Reject("loading_branch[0].torque_Nm", "<= 0 (the branch must start at or below torque 0 to give theta(0+))",
           loading_branch.front().torque_Nm);
  auto at = [&](double t) { return AngleAt(loading_branch, t, Side::kFromAbove, "loading_branch"); };
  const double a0 = at(0.0), a1 = at(t1_Nm), a2 = at(t2_Nm), ar = at(rated_torque_Nm);
  ThreeSegmentStiffness s;
  s.contact_angle_arcmin = a0;
  s.k1_Nm_per_arcmin = t1_Nm / (a1 - a0);
  s.k2_Nm_per_arcmin = (t2_Nm - t1_Nm) / (a2 - a1);
  s.k3_Nm_per_arcmin = (rated_torque_Nm - t2_Nm) / (ar - a2);
  const double k[3] = {s.k1_Nm_per_arcmin, s.k2_Nm_per_arcmin, s.k3_Nm_per_arcmin};
  const char* names[3] = {"K1 (the angle over 0..T1)", "K2 (the angle over T1..T2)", "K3 (the angle over T2..T_r)"};
  for (int i = 0; i < 3; ++i)
    if (!(std::isfinite(k[i]) && k[i] > 0.0)) Reject(names[i], "finite and > 0 (the angle must rise over the segment)", k[i]);
  return s;
}

/// The wind-up of a three-segment characteristic at a torque ([HDAG-CSD] eq. 23.1–23.3):
///   φ = T/K1 (T <= T1);  T1/K1 + (T − T1)/K2 (T1 < T <= T2);  T1/K1 + (T2 − T1)/K2 + (T − T2)/K3 (T > T2),
/// odd in T (φ(−T) = −φ(T), the catalogues' symmetric characteristic), measured from first contact.
/// The angle is in the unit of torque over stiffness: N·m with N·m/rad gives rad (×kArcminPerRad
/// for arcmin, [HDAG-CSD] eq. 23.4), N·m with N·m/arcmin gives arcmin.
/// @throws std::invalid_argument for a non-finite torque, T1, T2 not 0 < T1 < T2, or a stiffness
/// not finite and > 0.
inline double ThreeSegmentTorsionAngle(double torque, double t1, double t2, double k1, double k2, double k3) {
  using namespace catalogue_ratings_internal;
  if (!std::isfinite(torque)) Reject("torque", "finite", torque);
  CheckPositive("T1 (t1)", t1);
  if (!(std::isfinite(t2) && t2 > t1)) Reject("T2 (t2)", "finite and > T1 = " + std::to_string(t1), t2);
  CheckPositive("K1 (k1)", k1);
  CheckPositive("K2 (k2)", k2);
  CheckPositive("K3 (k3)", k3);
  const double t = std::abs(torque);
  double phi = 0.0;
  if (t <= t1) {
    phi = t / k1;
  } else if (t <= t2) {
    phi = t1 / k1 + (t - t1) / k2;
  } else {
    phi = t1 / k1 + (t2 - t1) / k2 + (t - t2) / k3;
  }
  return torque < 0.0 ? -phi : phi;
}

/// Lost motion on one branch spanning both signs of torque: θ(+p T_r) − θ(−p T_r), p = fraction
/// (catalogues: 3 % for Nabtesco's RV [NAB-RV], a few per cent for Harmonic Drive [HDAG-CHA]).
/// The branch is a loading branch in ascending torque (as TorsionAngleAt); with a lost-motion region
/// at torque 0 the result includes it (that is what lost motion measures).
/// @param fraction p in (0, 1].  @param rated_torque_Nm T_r > 0; ±p T_r within the branch's range.
/// @throws std::invalid_argument for a malformed branch, T_r not > 0, p outside (0, 1], or ±p T_r
/// outside the branch.
inline double LostMotionArcmin(const std::vector<TorsionPoint>& branch, double rated_torque_Nm, double fraction) {
  using namespace catalogue_ratings_internal;
  CheckAscendingBranch("branch", branch);
  CheckPositive("T_r_Nm (rated_torque_Nm)", rated_torque_Nm);
  if (!(std::isfinite(fraction) && fraction > 0.0 && fraction <= 1.0)) Reject("fraction (of T_r)", "in (0, 1]", fraction);
  const double t = fraction * rated_torque_Nm;
  return AngleAt(branch, t, Side::kFromAbove, "branch") - AngleAt(branch, -t, Side::kFromAbove, "branch");
}

/// Lost motion on a hysteresis loop as Nabtesco defines it [NAB-RV]: the angle between the
/// mid-points of the loop's width at +p T_r and at −p T_r,
///   LM = ½(θ_l + θ_u)(+p T_r) − ½(θ_l + θ_u)(−p T_r),
/// θ_l on the loading branch (torque ascending from −T_r to +T_r), θ_u on the unloading branch
/// (torque descending from +T_r to −T_r). A loop of zero width gives the one-branch value.
/// @throws std::invalid_argument as the one-branch form, for either branch (the unloading branch's
/// torque must descend).
inline double LostMotionArcmin(const std::vector<TorsionPoint>& loading_branch,
                               const std::vector<TorsionPoint>& unloading_branch, double rated_torque_Nm,
                               double fraction) {
  using namespace catalogue_ratings_internal;
  CheckAscendingBranch("loading_branch", loading_branch);
  const std::vector<TorsionPoint> up = AscendingFromDescending("unloading_branch", unloading_branch);
  CheckPositive("T_r_Nm (rated_torque_Nm)", rated_torque_Nm);
  if (!(std::isfinite(fraction) && fraction > 0.0 && fraction <= 1.0)) Reject("fraction (of T_r)", "in (0, 1]", fraction);
  const double t = fraction * rated_torque_Nm;
  auto mid = [&](double torque) {
    return 0.5 * (AngleAt(loading_branch, torque, Side::kFromAbove, "loading_branch") +
                  AngleAt(up, torque, Side::kFromAbove, "unloading_branch"));
  };
  return mid(t) - mid(-t);
}

/// Hysteresis loss [HDL-CSF]: the width of the loop at zero torque after loading to ±T_r,
///   H = θ_u(0, arriving from +T_r) − θ_l(0, arriving from −T_r),
/// θ_l on the loading branch (torque ascending from −T_r), θ_u on the unloading branch (torque
/// descending from +T_r). Where a branch crosses zero torque over a lost-motion region, the angle
/// is where it first reaches zero torque (the loading branch's first point at 0, the unloading
/// branch's first point at 0 coming down), so a backlash is included: Nabtesco calls this width at
/// zero torque the backlash [NAB-RV]; Harmonic Drive's gears have none and call it hysteresis loss.
/// @throws std::invalid_argument for a malformed branch or a branch not spanning torque 0.
inline double HysteresisLossArcmin(const std::vector<TorsionPoint>& loading_branch,
                                   const std::vector<TorsionPoint>& unloading_branch) {
  using namespace catalogue_ratings_internal;
  CheckAscendingBranch("loading_branch", loading_branch);
  const std::vector<TorsionPoint> up = AscendingFromDescending("unloading_branch", unloading_branch);
  return AngleAt(up, 0.0, Side::kFromAbove, "unloading_branch") -
         AngleAt(loading_branch, 0.0, Side::kFromBelow, "loading_branch");
}

/// Angular transmission accuracy from samples of one output revolution in one direction
/// ([HDAG-CHA] "transmission accuracy"): with the ideal output angle θ_out,0 + (θ_in − θ_in,0)/R,
/// the deviations e_k = (θ_out,k − θ_out,0) − (θ_in,k − θ_in,0)/R, and
///   accuracy = max_k e_k − min_k e_k
/// (the sum of the largest positive and the largest negative deviation; it does not depend on the
/// reference sample). Samples need not be uniform; the error between samples is not seen.
/// @param input_angle_deg θ_in,k [deg], strictly monotone (one direction), at least 2, spanning at
/// least one output revolution: |θ_in,last − θ_in,0| / |R| >= 360° (to 1e-9 relative).
/// @param output_angle_deg θ_out,k [deg], one per input sample, finite.
/// @param reduction_ratio R = input angle / output angle, finite and != 0 (negative: the output
/// turns the other way).
/// @throws std::invalid_argument for mismatched sizes, fewer than 2 samples, a non-finite value, a
/// non-monotone input, R = 0, or less than one output revolution.
inline TransmissionAccuracy TransmissionAccuracyFromSamples(const std::vector<double>& input_angle_deg,
                                                            const std::vector<double>& output_angle_deg,
                                                            double reduction_ratio) {
  using namespace catalogue_ratings_internal;
  if (input_angle_deg.size() < 2) Reject("input_angle_deg.size()", ">= 2", double(input_angle_deg.size()));
  if (output_angle_deg.size() != input_angle_deg.size())
    Reject("output_angle_deg.size()", "input_angle_deg.size() (" + std::to_string(input_angle_deg.size()) + ")",
           double(output_angle_deg.size()));
  if (!(std::isfinite(reduction_ratio) && reduction_ratio != 0.0))
    Reject("R (reduction_ratio)", "finite and != 0", reduction_ratio);
  const size_t n = input_angle_deg.size();
  for (size_t k = 0; k < n; ++k) {
    if (!std::isfinite(input_angle_deg[k])) Reject("input_angle_deg[" + std::to_string(k) + "]", "finite", input_angle_deg[k]);
    if (!std::isfinite(output_angle_deg[k]))
      Reject("output_angle_deg[" + std::to_string(k) + "]", "finite", output_angle_deg[k]);
  }
  const double direction = input_angle_deg[1] > input_angle_deg[0] ? 1.0 : -1.0;
  for (size_t k = 1; k < n; ++k)
    if (!(direction * (input_angle_deg[k] - input_angle_deg[k - 1]) > 0.0))
      Reject("input_angle_deg[" + std::to_string(k) + "]", "strictly monotone (one direction, no reversal)",
             input_angle_deg[k]);
  const double span_out_deg = std::abs(input_angle_deg.back() - input_angle_deg.front()) / std::abs(reduction_ratio);
  if (!(span_out_deg >= 360.0 * (1.0 - 1e-9)))
    Reject("the samples' span in output degrees, |input span| / |R|", ">= 360 (one output revolution)", span_out_deg);
  TransmissionAccuracy a;
  double emax = 0.0, emin = 0.0;
  for (size_t k = 0; k < n; ++k) {
    const double e_deg = (output_angle_deg[k] - output_angle_deg[0]) -
                         (input_angle_deg[k] - input_angle_deg[0]) / reduction_ratio;
    emax = std::max(emax, e_deg);
    emin = std::min(emin, e_deg);
  }
  a.largest_positive_arcmin = 60.0 * emax;
  a.largest_negative_arcmin = 60.0 * emin;
  a.accuracy_arcmin = a.largest_positive_arcmin - a.largest_negative_arcmin;
  return a;
}

/// The allowed number of momentary peak torques (emergency stops, collisions) of a strain-wave
/// gear ([HDAG-SHG] eq. 30.10, HFUS-2A eq. 19.10):
///   N_max = 10⁴ / (2 · (n · R / 60) · t),
/// with n the OUTPUT speed [rpm] at the peak, R the reduction ratio and t [s] the duration of each
/// peak. n·R/60·t is the wave generator's revolutions during one peak, each flexing a flexspline
/// tooth twice; the catalogue allows 10⁴ such flexings under peak torque. With R = 1 the formula
/// reads N_max = 10⁴ / (2 n t / 60) in the wave generator's (input) speed n. The catalogue's flow
/// chart also prints "< 10⁴" beside the formula; no cap is applied here (a peak shorter than one
/// flexing gives N_max > 10⁴, which the caller may cap).
/// @param output_speed_rpm n > 0 (a peak at standstill turns no revolutions: no count defined).
/// @param duration_s t > 0.  @param reduction_ratio R > 0.
/// @throws std::invalid_argument for a value not finite and > 0.
inline double AllowedMomentaryPeakCount(double output_speed_rpm, double duration_s, double reduction_ratio) {
  using namespace catalogue_ratings_internal;
  CheckPositive("n_rpm (output_speed_rpm, at the peak)", output_speed_rpm);
  CheckPositive("t_s (duration_s, of each peak)", duration_s);
  CheckPositive("R (reduction_ratio)", reduction_ratio);
  return 1e4 / (2.0 * (output_speed_rpm * reduction_ratio / 60.0) * duration_s);
}

/// The relative bracket width at which RatedTorqueForLife stops.
inline constexpr double kRatedTorqueRelTolerance = 1e-12;
/// How many times RatedTorqueForLife doubles or halves its bracket before it gives up (2^100 ~ 1e30).
inline constexpr int kRatedTorqueMaxBracketSteps = 100;

/// The rated torque for a target life: the T at which life_h(T) = target_life_h, life_h decreasing
/// in T (any life law: a bearing's (C/P)^p with loads from a load-sharing model, a Miner sum of
/// several parts). Design-notes §4: solve, do not scale — T (L(T)/L_target)^(1/p) is exact only for
/// a pure power law.
/// Method: from the guess, the bracket grows by `first_step` (life above the target) or shrinks
/// by it (at or below), the step squared each time up to a factor 2 (2, 2, … by default: doubling or
/// halving), until life_h(lo) > target >= life_h(hi); a guess known to be near the answer (the same
/// rating of a neighbouring model) starts with a small step and is bracketed in one or two runs;
/// then regula falsi (Illinois) on −ln life_h against ln T, which is increasing (bisection where an
/// end's value is infinite; no point nearer an end than rel_tolerance·hi/2), until the life is
/// within 1e-13 (relative) of the target or the bracket is below rel_tolerance·hi. Returns the evaluated
/// torque whose life is nearest the target (within the last bracket); no torque is evaluated twice.
/// A life of +∞ (no load) or 0 is allowed; on a non-monotone law it returns one crossing.
/// @param life_h callable double(double): the life [h] at torque T [N·m]; >= 0, not NaN.
/// @param target_life_h [h], finite and > 0.  @param torque_guess_Nm where to start, finite > 0.
/// @param first_step the bracket's first factor, in (1, 2].
/// @throws std::invalid_argument for a bad target or guess, a life that is NaN or negative, or a
/// life that never crosses the target within 2^100 of the guess (it stays above: the life never
/// falls to the target; at or below: it never reaches it).
template <typename LifeFn>
double RatedTorqueForLife(const LifeFn& life_h, double target_life_h, double torque_guess_Nm,
                          double rel_tolerance = kRatedTorqueRelTolerance, double first_step = 2.0) {
  using namespace catalogue_ratings_internal;
  CheckPositive("target_life_h", target_life_h);
  CheckPositive("torque_guess_Nm", torque_guess_Nm);
  if (!(first_step > 1.0 && first_step <= 2.0))
    throw std::invalid_argument("catalogue ratings: first_step must be in (1, 2], found " + std::to_string(first_step));
  double step = first_step;
  auto next_step = [&] { step = std::min(2.0, step * step); };
  auto life = [&](double t) {
    const double l = life_h(t);
    if (std::isnan(l) || l < 0.0) {
      std::ostringstream os;
      os.precision(12);
      os << "catalogue ratings: life_h(T) must be >= 0 and not NaN, found " << l << " at T = " << t << " N·m";
      throw std::invalid_argument(os.str());
    }
    return l;
  };
  // The bracket's ends keep their torques and lives as evaluated (a torque is never evaluated
  // twice: exp(log T) need not give T back, and each evaluation is a model run).
  double lo = torque_guess_Nm, hi = torque_guess_Nm;
  double life_lo = life(torque_guess_Nm), life_hi = life_lo;
  if (life_lo > target_life_h) {
    for (int k = 0;; ++k) {
      if (k == kRatedTorqueMaxBracketSteps)
        Reject("life_h(T) at T = " + std::to_string(hi) + " N·m",
               "<= the target " + std::to_string(target_life_h) + " h somewhere (it stays above: the life never "
               "falls to the target)",
               life_hi);
      lo = hi, life_lo = life_hi;
      hi *= step;
      next_step();
      life_hi = life(hi);
      if (!(life_hi > target_life_h)) break;
    }
  } else {
    for (int k = 0;; ++k) {
      if (k == kRatedTorqueMaxBracketSteps)
        Reject("life_h(T) at T = " + std::to_string(lo) + " N·m",
               "> the target " + std::to_string(target_life_h) + " h somewhere (it stays at or below: the life "
               "never reaches the target)",
               life_lo);
      hi = lo, life_hi = life_lo;
      lo /= step;
      next_step();
      life_lo = life(lo);
      if (life_lo > target_life_h) break;
    }
  }
  // −ln life is increasing in T; −ln(+∞) = −∞ and −ln 0 = +∞ compare correctly. A life law is
  // close to a power of T, so −ln life is close to linear in ln T: regula falsi with the Illinois
  // modification on g(x) = ln target − ln life(e^x) over x = ln T converges superlinearly (a few
  // evaluations instead of bisection's ~40, each one a model run); it falls back to bisection where
  // an end's value is infinite. Stops when |g| <= 1e-13 (the life within 1e-13 of the target) or the
  // bracket is below rel_tolerance · T.
  auto g_of = [&](double l) { return std::log(target_life_h) - std::log(l); };
  double a = std::log(lo), b = std::log(hi), ga = g_of(life_lo), gb = g_of(life_hi);  // ga < 0 <= gb
  double t_a = lo, t_b = hi;
  // The evaluated torque closest to the target is returned: a life computed by a model with its own
  // solver tolerance is noisy below that tolerance, so the answer is a torque whose life was
  // computed, not an interpolation between two.
  double best = std::abs(ga) <= std::abs(gb) ? t_a : t_b, best_g = std::min(std::abs(ga), std::abs(gb));
  if (best_g <= 1e-13) return best;  // an end of the bracket is already there
  int side = 0;
  for (int it = 0; it < 200; ++it) {
    if (t_b - t_a <= rel_tolerance * t_b) break;
    double x = std::isfinite(ga) && std::isfinite(gb) && gb > ga ? (a * gb - b * ga) / (gb - ga) : 0.5 * (a + b);
    if (!(x > a && x < b)) x = 0.5 * (a + b);
    double t = std::exp(x);
    // A point within half the tolerance of an end is moved to half the tolerance from it (Brent's
    // smallest step): the interpolation then says the crossing is within that distance of the end,
    // and the step across it ends the search, where a point next to the end would only repeat it.
    const double min_step = 0.5 * rel_tolerance * t_b;
    if (t - t_a < min_step) t = t_a + min_step;
    else if (t_b - t < min_step) t = t_b - min_step;
    if (!(t > t_a && t < t_b)) break;  // the bracket is a few ulps wide
    x = std::log(t);
    const double gx = g_of(life(t));
    if (std::abs(gx) < best_g) best = t, best_g = std::abs(gx);
    if (std::abs(gx) <= 1e-13) return t;
    if (gx < 0.0) {
      a = x, ga = gx, t_a = t;
      if (side == -1) gb *= 0.5;  // Illinois: the end kept twice has its value halved
      side = -1;
    } else {
      b = x, gb = gx, t_b = t;
      if (side == 1) ga *= 0.5;
      side = 1;
    }
  }
  return best;
}

/// The allowable (thermal) input speed of a lubricated drive at one torque: the speed n at which the
/// housing's heat balance (model/common/thermal.h) puts the oil at its highest allowed temperature
/// t_max, P_loss(n, t_max) = k A (t_max − t_amb) = `heat_path_W`. With the loss increasing in n at a
/// fixed temperature and falling with the temperature (the viscosity falls), the balance
/// g(t) = P_loss(n, t) − k A (t − t_amb) has its root below t_max exactly for n below this speed: the
/// catalogues' "allowable speed" read as the thermal limit (Nabtesco's allowable output speed at
/// the rated torque, Harmonic Drive's limit for the average input speed).
/// Method: RatedTorqueForLife on the headroom k A (t_max − t_amb) / P_loss(n, t_max), decreasing in n,
/// for the target 1 (bracket from the guess, then Illinois regula falsi on ln headroom against ln n).
/// @param loss_at_limit_W callable double(double n_rpm): the loss [W] at input speed n and t_max; >= 0.
/// @throws std::invalid_argument for heat_path_W <= 0 or a loss that never reaches the heat path
/// within 2^100 of the guess (or exceeds it at every speed).
template <typename LossFn>
double ThermalSpeedLimit(const LossFn& loss_at_limit_W, double heat_path_W, double speed_guess_rpm,
                         double rel_tolerance = kRatedTorqueRelTolerance) {
  catalogue_ratings_internal::CheckPositive("heat_path_W", heat_path_W);
  const auto headroom = [&](double n) {
    const double loss = loss_at_limit_W(n);
    return loss > 0.0 ? heat_path_W / loss : std::numeric_limits<double>::infinity();
  };
  try {
    return RatedTorqueForLife(headroom, 1.0, speed_guess_rpm, rel_tolerance);
  } catch (const std::invalid_argument&) {
    const double at_guess = loss_at_limit_W(speed_guess_rpm);
    std::ostringstream os;
    os.precision(6);
    os << "thermal speed limit: the loss at the oil's limit (" << at_guess << " W at " << speed_guess_rpm
       << " rpm) " << (at_guess < heat_path_W ? "never reaches" : "stays above") << " the housing's heat path of "
       << heat_path_W << " W over 2^100 of that speed";
    throw std::invalid_argument(os.str());
  }
}

}  // namespace camopt

// The lobe cam reducer (LCR) design, templated over the scalar, and its validity checks.
// Paper and notation: docs/papers.md §1 (Machines 2022, 10, 955).
// Units: mm, N, N·mm inside the model; MPa for moduli and stresses.
#pragma once

#include <numeric>
#include <string>
#include <vector>

#include "model/common/material.h"
#include "model/common/scalar.h"

namespace camopt::lcr {

/// One cam of the conjugate cam with its turret of rollers.
template <typename T>
struct CamSide {
  int lobes = 0;       // m
  int rollers = 0;     // n
  T turret_radius{};   // r_d [mm], radius of the roller-centre circle
  T roller_radius{};   // r_r [mm]
  T roller_length{};   // [mm]
  T cam_thickness{};   // [mm]

  /// n − m.
  int difference() const { return rollers - lobes; }
  /// k = n/(n − m): the pitch point lies at e·k from the input axis.
  double pitch_factor() const { return double(rollers) / double(rollers - lobes); }
  /// Line-contact length min(roller length, cam thickness). Continuous; at equal sizes the
  /// derivative is the cam thickness's (a one-sided derivative of the min, a true corner).
  T contact_length() const {
    return IfThenElse(Compare::kLess, roller_length, cam_thickness, roller_length, cam_thickness);
  }

  template <typename U>
  CamSide<U> cast() const {
    return {lobes, rollers, ScalarCast<U>(turret_radius), ScalarCast<U>(roller_radius),
            ScalarCast<U>(roller_length), ScalarCast<U>(cam_thickness)};
  }
};

enum class Side { kInput, kOutput };

/// Input cam A works against the fixed turret, output cam B drives the output turret.
template <typename T>
struct Reducer {
  T eccentricity{};  // e [mm]
  CamSide<T> input, output;

  const CamSide<T>& side(Side s) const { return s == Side::kInput ? input : output; }

  template <typename U>
  Reducer<U> cast() const {
    return {ScalarCast<U>(eccentricity), input.template cast<U>(), output.template cast<U>()};
  }
};

/// Cam and roller material (both the same; E* from model/common/material.h).
using Material = camopt::Material;

struct LoadCase {
  double output_torque_Nmm = 0.0;     // T_o, resisting the output's motion
  double friction_coefficient = 0.0;  // μ of the paper's T_in = (F_t + μ F_r) e
  double cam_weight_N = 0.0;          // W_c, acting in −y of the fixed frame
};

/// A design problem that makes the reducer impossible (not a numerical condition).
struct DesignProblem {
  std::string field;    // e.g. "input.rollers", relative to the reducer object
  std::string message;  // what is wrong
};

/// Structural checks of a design: counts, positive sizes, rollers that overlap, a pitch point
/// outside the turret circle (the pitch curve would loop). Empty when the design is buildable.
/// Undercut is not a structural problem: it is reported by the undercut stage.
template <typename T>
std::vector<DesignProblem> CheckDesign(const Reducer<T>& r) {
  std::vector<DesignProblem> problems;
  if (!(Value(r.eccentricity) > 0)) problems.push_back({"eccentricity_mm", "must be > 0"});
  for (Side s : {Side::kInput, Side::kOutput}) {
    const CamSide<T>& c = r.side(s);
    const std::string name = s == Side::kInput ? "input" : "output";
    if (c.lobes < 1) problems.push_back({name + ".lobes", "must be >= 1"});
    if (c.rollers <= c.lobes) {
      problems.push_back({name + ".rollers", "must be greater than the number of lobes (" +
                                                 std::to_string(c.lobes) + ")"});
      continue;
    }
    if (std::gcd(c.lobes, c.rollers) != 1)
      problems.push_back({name + ".rollers", "lobes and rollers must have no common divisor, " +
                                                 std::to_string(c.lobes) + " and " +
                                                 std::to_string(c.rollers) + " share one"});
    if (c.difference() != 1)
      problems.push_back({name + ".rollers",
                          "rollers − lobes = " + std::to_string(c.difference()) +
                              ": a difference above 1 makes the pitch curve wind " +
                              std::to_string(c.difference()) + " times (a self-crossing cam)"});
    if (!(Value(c.turret_radius) > 0)) problems.push_back({name + ".turret_radius_mm", "must be > 0"});
    if (!(Value(c.roller_radius) > 0)) problems.push_back({name + ".roller_diameter_mm", "must be > 0"});
    if (!(Value(c.roller_length) > 0)) problems.push_back({name + ".roller_length_mm", "must be > 0"});
    if (!(Value(c.cam_thickness) > 0)) problems.push_back({name + ".cam_thickness_mm", "must be > 0"});
    if (!problems.empty()) continue;
    const double gap = 2 * Value(c.turret_radius) * std::sin(kPi / c.rollers) - 2 * Value(c.roller_radius);
    if (gap <= 0)
      problems.push_back({name + ".roller_diameter_mm",
                          "rollers overlap on the turret: gap 2 r_d sin(π/n) − d_r = " +
                              std::to_string(gap) + " mm"});
    const double pitch = Value(r.eccentricity) * c.pitch_factor();
    if (pitch >= Value(c.turret_radius))
      problems.push_back({name + ".turret_radius_mm",
                          "the pitch point e·n/(n−m) = " + std::to_string(pitch) +
                              " mm lies outside the turret radius: the pitch curve loops"});
    if (Value(c.roller_radius) >= Value(c.turret_radius))
      problems.push_back({name + ".roller_diameter_mm", "roller radius must be below the turret radius"});
  }
  if (problems.empty() && long(r.input.lobes) * r.output.rollers == long(r.output.lobes) * r.input.rollers)
    problems.push_back({"output.lobes", "m_A·n_B = m_B·n_A = " + std::to_string(long(r.input.lobes) * r.output.rollers) +
                                            ": the output turret stands still (infinite speed ratio)"});
  return problems;
}

/// Roller gap on a turret: 2 r_d sin(π/n) − d_r [mm].
template <typename T>
T RollerGap(const CamSide<T>& c) {
  using std::sin;
  return T(2.0) * c.turret_radius * T(std::sin(kPi / c.rollers)) - T(2.0) * c.roller_radius;
}

/// Outer diameter 2·max(r_d + r_r) over both cams [mm]. Continuous; where both cams are equally
/// large the derivative is the input cam's (one side of the max's corner): an optimizer that meets
/// the corner sees a valid subgradient.
template <typename T>
T OuterDiameter(const Reducer<T>& r) {
  const T a = r.input.turret_radius + r.input.roller_radius;
  const T b = r.output.turret_radius + r.output.roller_radius;
  return T(2.0) * IfThenElse(Compare::kGreaterEqual, a, b, a, b);
}

}  // namespace camopt::lcr

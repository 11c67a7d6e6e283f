// The lobe cam reducer (LCR) design, templated over the scalar, and its validity checks.
// Paper and notation: docs/papers.md §1 (Machines 2022, 10, 955).
// Units: mm, N, N·mm inside the model; MPa for moduli and stresses.
#pragma once

#include <numeric>
#include <string>
#include <vector>

#include "model/common/design_issue.h"
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
  bool operator==(const CamSide&) const = default;
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
  bool operator==(const Reducer&) const = default;
};

/// Cam and roller material (both the same; E* from model/common/material.h).
using Material = camopt::Material;

struct LoadCase {
  double output_torque_Nmm = 0.0;     // T_o, resisting the output's motion
  double friction_coefficient = 0.0;  // μ of the paper's T_in = (F_t + μ F_r) e
  double cam_weight_N = 0.0;          // W_c, acting in −y of the fixed frame
};

/// Structural checks of a design: counts, positive sizes, rollers that overlap, a pitch point
/// outside the turret circle (the pitch curve would loop). Empty when the design is buildable.
/// Undercut is not a structural problem: it is reported by the undercut stage. Each issue's field
/// is relative to the reducer's study object ("eccentricity_mm", "input.rollers",
/// "output.roller_diameter_mm", ...); value and limit in its units [mm or a count].
template <typename T>
std::vector<DesignIssue> CheckDesign(const Reducer<T>& r) {
  std::vector<DesignIssue> problems;
  auto n = [](double v) { return IssueNumber(v); };
  auto positive = [&](const std::string& field, const char* what, double v) {
    if (!(v > 0)) problems.push_back({field, "the " + std::string(what) + " " + n(v) + " mm must be > 0", v, 0.0});
  };
  positive("eccentricity_mm", "eccentricity", Value(r.eccentricity));
  for (Side s : {Side::kInput, Side::kOutput}) {
    const CamSide<T>& c = r.side(s);
    const std::string name = s == Side::kInput ? "input" : "output";
    const std::string lobes = std::to_string(c.lobes), rollers = std::to_string(c.rollers);
    const std::string one_more = std::to_string(c.lobes + 1);
    if (c.lobes < 1) problems.push_back({name + ".lobes", lobes + " lobes: the cam needs at least 1", double(c.lobes), 1.0});
    if (c.rollers <= c.lobes) {
      problems.push_back({name + ".rollers",
                          "expected more rollers than lobes (" + lobes + "), found " + rollers + ": " + one_more +
                              " rollers (lobes + 1) would fit",
                          double(c.rollers), double(c.lobes + 1)});
      continue;
    }
    if (const int g = std::gcd(c.lobes, c.rollers); g != 1)
      problems.push_back({name + ".rollers",
                          "lobes and rollers must have no common divisor, " + lobes + " and " + rollers +
                              " share " + std::to_string(g) + ": " + one_more + " rollers (lobes + 1) would fit",
                          double(c.rollers), double(c.lobes + 1)});
    if (c.difference() != 1)
      problems.push_back({name + ".rollers",
                          "rollers − lobes = " + std::to_string(c.difference()) +
                              ": a difference above 1 makes the pitch curve wind " +
                              std::to_string(c.difference()) + " times (a self-crossing cam); " + one_more +
                              " rollers (lobes + 1) would fit",
                          double(c.rollers), double(c.lobes + 1)});
    positive(name + ".turret_radius_mm", "turret radius", Value(c.turret_radius));
    positive(name + ".roller_diameter_mm", "roller diameter", 2 * Value(c.roller_radius));
    positive(name + ".roller_length_mm", "roller length", Value(c.roller_length));
    positive(name + ".cam_thickness_mm", "cam thickness", Value(c.cam_thickness));
    if (!problems.empty()) continue;
    const double chord = 2 * Value(c.turret_radius) * std::sin(kPi / c.rollers);
    const double gap = chord - 2 * Value(c.roller_radius);
    if (gap <= 0)
      problems.push_back({name + ".roller_diameter_mm",
                          "rollers overlap on the turret: gap 2 r_d sin(π/n) − d_r = " + n(gap) + " mm for " +
                              rollers + " rollers of " + n(2 * Value(c.roller_radius)) + " mm on a turret radius of " +
                              n(Value(c.turret_radius)) + " mm: a roller diameter below " + n(chord) +
                              " mm, or a turret radius above " +
                              n(Value(c.roller_radius) / std::sin(kPi / c.rollers)) + " mm, would fit",
                          2 * Value(c.roller_radius), chord});
    const double pitch = Value(r.eccentricity) * c.pitch_factor();
    if (pitch >= Value(c.turret_radius))
      problems.push_back({name + ".turret_radius_mm",
                          "the pitch point e·n/(n−m) = " + n(pitch) +
                              " mm lies outside the turret radius: the pitch curve loops; the eccentricity must be "
                              "below " + n(Value(c.turret_radius) / c.pitch_factor()) + " mm for " + rollers +
                              " rollers and " + lobes + " lobes on a " + n(Value(c.turret_radius)) +
                              " mm turret radius (or the turret radius above " + n(pitch) + " mm)",
                          Value(c.turret_radius), pitch});
    if (Value(c.roller_radius) >= Value(c.turret_radius))
      problems.push_back({name + ".roller_diameter_mm",
                          "the roller radius " + n(Value(c.roller_radius)) + " mm must be below the turret radius " +
                              n(Value(c.turret_radius)) + " mm",
                          Value(c.roller_radius), Value(c.turret_radius)});
  }
  if (problems.empty() && long(r.input.lobes) * r.output.rollers == long(r.output.lobes) * r.input.rollers)
    problems.push_back({"output.lobes",
                        "m_A·n_B = m_B·n_A = " + std::to_string(long(r.input.lobes) * r.output.rollers) +
                            ": the output turret stands still (infinite speed ratio); output lobes other than the "
                            "input's (" + std::to_string(r.input.lobes) + ") would turn it",
                        double(r.output.lobes), double(r.input.lobes)});
  return problems;
}

/// Roller gap on a turret: 2 r_d sin(π/n) − d_r [mm].
template <typename T>
CAMOPT_FLATTEN T RollerGap(const CamSide<T>& c) {
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

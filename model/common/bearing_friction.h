// A rolling bearing's friction moment and power loss by Palmgren's classical model, over the
// scalar T (Palmgren, Ball and Roller Bearing Engineering, 1959; the form of SKF's catalogues
// before 2004):
//   M = M0 + M1,
//   M0 = 1e-7 f0 (ν n)^(2/3) dm³   [N·mm]  (ν n ≥ 2000; ν in mm²/s, n in rpm, dm in mm),
//   M1 = f1 P1 dm                  [N·mm]  (P1 the load that sets the load-dependent moment, N).
// Palmgren gives M0 = 160e-7 f0 dm³ below ν n = 2000; here M0 is held at its value at ν n = 2000
// there (158.7e-7 f0 dm³, 0.8% below Palmgren's constant), so that M0 is continuous in ν and n and
// a sizing's derivative exists. f0 (lubrication and bearing type) and f1 (load) are catalogue
// factors, given per bearing.
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>

#include "model/common/scalar.h"

namespace camopt {

/// Palmgren's factors and the bearing's mean diameter.
struct PalmgrenBearing {
  double f0 = 2.0;                 ///< lubrication factor (oil bath, needle and roller bearings: 2–4)
  double f1 = 0.0005;              ///< load factor
  double mean_diameter_mm = 20.0;  ///< dm = (d + D)/2
  bool operator==(const PalmgrenBearing&) const = default;

  void Validate() const {
    if (!(f0 >= 0.0 && f0 < 100.0 && f1 >= 0.0 && f1 < 1.0 && mean_diameter_mm > 0.0))
      throw std::invalid_argument("bearing friction: expected f0 in [0, 100), f1 in [0, 1), dm > 0, found f0 " +
                                  std::to_string(f0) + ", f1 " + std::to_string(f1) + ", dm " +
                                  std::to_string(mean_diameter_mm) + " mm");
  }
};

/// The ν n below which M0 is held (Palmgren's border of the speed-dependent law).
inline constexpr double kPalmgrenMinViscositySpeed = 2000.0;

/// M0 [N·mm] at kinematic viscosity ν [mm²/s] and speed n [rpm] (n ≥ 0).
template <typename T>
T PalmgrenLoadIndependentMoment(const PalmgrenBearing& b, const T& nu, const T& n_rpm) {
  using std::cbrt;
  const T nu_n = IfThenElse(Compare::kLess, nu * n_rpm, kPalmgrenMinViscositySpeed, T(kPalmgrenMinViscositySpeed),
                            T(nu * n_rpm));
  const T dm = T(b.mean_diameter_mm);
  return T(1e-7 * b.f0) * cbrt(nu_n * nu_n) * dm * dm * dm;
}

/// M0 as above from ν, n and their powers ν^(2/3), n^(2/3) computed beforehand (n ≥ 0): the same
/// value, for a sweep over the oil's temperature that takes ν^(2/3) once for many bearings' speeds.
template <typename T>
CAMOPT_FLATTEN T PalmgrenLoadIndependentMoment(const PalmgrenBearing& b, const T& nu, const T& nu_2_3, const T& n_rpm,
                                const T& n_2_3) {
  const double floor_2_3 = std::cbrt(kPalmgrenMinViscositySpeed * kPalmgrenMinViscositySpeed);
  const T nu_n_2_3 = IfThenElse(Compare::kLess, nu * n_rpm, kPalmgrenMinViscositySpeed, T(floor_2_3), T(nu_2_3 * n_2_3));
  const T dm = T(b.mean_diameter_mm);
  return T(1e-7 * b.f0) * nu_n_2_3 * dm * dm * dm;
}

/// M1 = f1 P1 dm [N·mm].
template <typename T>
T PalmgrenLoadDependentMoment(const PalmgrenBearing& b, const T& p1) {
  return T(b.f1) * p1 * T(b.mean_diameter_mm);
}

/// The bearing's power loss M ω [N·mm/s = 1e-3 W] at speed n [rpm] (relative speed of its rings).
template <typename T>
T PalmgrenPowerLoss(const PalmgrenBearing& b, const T& nu, const T& n_rpm, const T& p1) {
  using std::abs;
  const T omega = abs(n_rpm) * T(2.0 * kPi / 60.0);
  return (PalmgrenLoadIndependentMoment(b, nu, abs(n_rpm)) + PalmgrenLoadDependentMoment(b, p1)) * omega;
}

/// A bearing at a given speed and load, what of its loss does not depend on the oil: |n| [rpm],
/// |n|^(2/3), ω [rad/s] and M1 ω [N·mm/s] (a sweep over the oil's temperature computes it once).
template <typename T>
struct PalmgrenAtSpeed {
  T n_rpm{}, n_2_3{}, omega{}, load_dependent{};
};

template <typename T>
CAMOPT_FLATTEN PalmgrenAtSpeed<T> PalmgrenAt(const PalmgrenBearing& b, const T& n_rpm, const T& p1) {
  using std::abs;
  using std::cbrt;
  PalmgrenAtSpeed<T> s;
  s.n_rpm = abs(n_rpm);
  s.n_2_3 = cbrt(s.n_rpm * s.n_rpm);
  s.omega = s.n_rpm * T(2.0 * kPi / 60.0);
  s.load_dependent = PalmgrenLoadDependentMoment(b, p1) * s.omega;
  return s;
}

/// PalmgrenPowerLoss(b, ν, n, p1) [N·mm/s] from PalmgrenAt(b, n, p1) and ν, ν^(2/3).
template <typename T>
T PalmgrenPowerLoss(const PalmgrenBearing& b, const PalmgrenAtSpeed<T>& s, const T& nu, const T& nu_2_3) {
  return PalmgrenLoadIndependentMoment(b, nu, nu_2_3, s.n_rpm, s.n_2_3) * s.omega + s.load_dependent;
}

}  // namespace camopt

// Finite-length roller–cam contact of the LCR (docs/lcr.md "Crowned rollers and 3D
// contact"): roller crowning, misalignment, and the contact models behind one interface.
//
// Each loaded contact: roller radius r_r, contact length l = min(roller length, cam thickness) (the
// overlap, centred on the roller's mid-length; the shorter body's ends are the edges), effective
// radius across rolling R' = r_r (1 − r_r κ) (as for the line model, forces.h), and the gap along
// the roller axis y (from the roller's mid-length)
//     h(y) = crowning drop(y) (model/contact/crowning.h) + γ y,
// γ the misalignment (tilt of the roller axis against the cam axis in the plane of the contact
// normal) [rad].
//   line:       Hertz line contact (model/contact/hertz.h); ignores crowning and misalignment.
//   slices:     model/contact/roller_slices.h (over T: exact derivatives by an implicit step).
//   half_space: model/contact/roller_half_space.h (DC-FFT, double; a verification model).
#pragma once

#include <string>

#include "model/contact/crowning.h"
#include "model/contact/hertz.h"
#include "model/contact/roller_slices.h"
#include "model/lcr/reducer.h"

namespace camopt::lcr {

enum class ContactModel { kLine, kSlices, kHalfSpace };

struct ContactModelOptions {
  ContactModel model = ContactModel::kLine;
  int slices = 40;                 // N of the slices model
  int grid_nx = 64, grid_ny = 256; // grid of the half_space model (across rolling, along the roller)
  double misalignment_rad = 0.0;   // γ
};

/// Roller crowning of one cam side; lengths [mm]. Over T so that a sizing problem can vary them.
template <typename T>
struct RollerCrowning {
  contact::CrowningType type = contact::CrowningType::kNone;
  T radius{};            // circular, partial
  T flat_length{};       // partial
  T coefficient{};       // logarithmic f
  T effective_length{};  // logarithmic Le (> roller length)

  template <typename U>
  RollerCrowning<U> cast() const {
    return {type, ScalarCast<U>(radius), ScalarCast<U>(flat_length), ScalarCast<U>(coefficient),
            ScalarCast<U>(effective_length)};
  }
};

/// "" or why the crowning cannot be used on a roller of length l_r (logarithmic: Le > l_r so that
/// the drop stays finite at the roller's ends; circular/partial: the circle must span the roller).
inline std::string CheckRollerCrowning(const RollerCrowning<double>& c, double roller_length) {
  using contact::CrowningType;
  switch (c.type) {
    case CrowningType::kNone:
      return "";
    case CrowningType::kCircular:
      if (!(c.radius > 0.5 * roller_length)) return "crowning radius must exceed half the roller length";
      return "";
    case CrowningType::kPartial:
      if (!(c.flat_length >= 0 && c.flat_length < roller_length)) return "flat length must be in [0, roller length)";
      if (!(c.radius > 0.5 * (roller_length - c.flat_length)))
        return "crowning radius must exceed half the crowned length";
      return "";
    case CrowningType::kLogarithmic:
      if (!(c.coefficient >= 0)) return "logarithmic crowning coefficient must be >= 0";
      if (!(c.effective_length > roller_length))
        return "effective length must exceed the roller length (Le <= l_r gives an unbounded drop at the "
               "roller's ends whose value depends on the discretisation)";
      return "";
  }
  return "unknown crowning type";
}

/// Gap along the roller axis [mm] at y [mm] from the roller's mid-length.
template <typename T>
T GapAlongRoller(const RollerCrowning<T>& c, const T& misalignment_rad, const T& y) {
  return contact::CrowningDrop(c.type, c.radius, c.flat_length, c.coefficient, c.effective_length, y) +
         misalignment_rad * y;
}

/// The slices model of one roller contact: force F [N], effective radius R' [mm], contact length
/// l [mm]. @pre F >= 0, R' > 0.
template <typename T>
contact::SliceSolution<T> RollerContactSlices(const T& force, const T& r_eff, const T& length, double e_star,
                                              const RollerCrowning<T>& crowning, const T& misalignment_rad,
                                              int slices) {
  contact::SliceOptions o;
  o.slices = slices;
  return contact::SolveRollerSlices<T>(force, r_eff, length, e_star,
                                       [&](const T& y) { return GapAlongRoller(crowning, misalignment_rad, y); }, o);
}

}  // namespace camopt::lcr

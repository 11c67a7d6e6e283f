// The papers' reference designs, shared by every suite and by bench/ (LCR I, II, III of Table 2;
// the cycloid paper's NNM drive).
#pragma once

#include "model/cycloid/tooth_profile.h"
#include "model/lcr/reducer.h"

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

}  // namespace camopt::testing

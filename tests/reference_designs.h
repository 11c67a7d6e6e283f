// The papers' reference designs, shared by every suite (LCR I, II, III of Table 2).
#pragma once

#include "model/lcr/reducer.h"
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

}  // namespace camopt::testing

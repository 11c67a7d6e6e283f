// The load per slice of an LCR roller along its length, for the sliced rating life under tilt
// (model/common/sliced_bearing_life.h; docs/life.md, "Sliced roller life under tilt").
//
// At each sample of the roller's load period (SampleBearingLoad: roller 0's force F and spin rate)
// the roller–cam contact is solved by the slices model (model/lcr/contact3d.h RollerContactSlices:
// crowning and misalignment γ, R' of roller 0's contact there) and slice j carries Q_j = q_j w
// (Σ_j Q_j = F). Assumed: the roller's bearing (needles on the pin) carries the load along its
// length as the cam contact loads the roller (a roller stiff in bending, the pin aligned with the
// roller), over the contact length l = min(roller length, cam thickness).
#pragma once

#include <vector>

#include "model/lcr/contact3d.h"
#include "model/lcr/life.h"

namespace camopt::lcr {

struct RollerSliceSamples {
  std::vector<std::vector<double>> loads;  ///< [sample][slice] Q_j [N]
  std::vector<double> weights;             ///< spin rate at each sample (revolution weights)
  std::vector<double> y_mm;                ///< slice centres from the contact's mid-length
  double revolutions_per_input_revolution = 0.0;
  bool converged = true, edge_loaded = false;
};

/// Roller 0 of cam s over its load period at `steps_per_revolution` samples per input revolution.
/// @throws std::domain_error when a turret cannot carry the torque or a loaded contact is undercut.
inline RollerSliceSamples SampleRollerSliceLoads(const Reducer<double>& r, const Material& material,
                                                 const LoadCase& load, LoadModel model, Side s,
                                                 int steps_per_revolution, const RollerCrowning<double>& crowning,
                                                 double misalignment_rad, int slices) {
  const LcrBearing b = s == Side::kInput ? LcrBearing::kInputRoller : LcrBearing::kOutputRoller;
  const BearingLoadSamples x = SampleBearingLoad(r, material, load, model, b, steps_per_revolution);
  const CamSide<double>& cam = r.side(s);
  const double length = cam.contact_length(), rr = cam.roller_radius, w = length / slices;
  const double e_star = material.composite_modulus_MPa();
  RollerSliceSamples out;
  out.weights = x.spin_rate;
  for (int j = 0; j < slices; ++j) out.y_mm.push_back(-0.5 * length + (j + 0.5) * w);
  double spin = 0.0;
  for (double v : x.spin_rate) spin += v;
  out.revolutions_per_input_revolution = spin / double(x.spin_rate.size());
  const int n = int(x.load_N.size());
  for (int k = 0; k < n; ++k) {
    std::vector<double> q(size_t(slices), 0.0);
    if (x.load_N[size_t(k)] > 0) {
      const double theta = x.period_rad * k / n;
      const double r_eff = rr * (1.0 - rr * RollerContacts(r, s, theta)[0].curvature);
      if (!(r_eff > 0)) throw std::domain_error("a loaded roller sits on an undercut part of the pitch curve");
      const contact::SliceSolution<double> sol =
          RollerContactSlices<double>(x.load_N[size_t(k)], r_eff, length, e_star, crowning, misalignment_rad, slices);
      out.converged = out.converged && sol.converged;
      out.edge_loaded = out.edge_loaded || sol.edge_loaded;
      for (int j = 0; j < slices; ++j) q[size_t(j)] = sol.line_load_N_per_mm[size_t(j)] * w;
    }
    out.loads.push_back(std::move(q));
  }
  return out;
}

}  // namespace camopt::lcr

// See contact3d_cycle.h.
#include "model/lcr/contact3d_cycle.h"

#include <algorithm>
#include <cmath>

#include "model/contact/roller_half_space.h"

namespace camopt::lcr {

namespace {

struct Contact {
  int angle, roller;
  double force, r_eff;
};

}  // namespace

Contact3DCycleSide AnalyzeCycleContact3D(const Reducer<double>& r, Side s, const CycleSeries& series,
                                         double e_star, const RollerCrowning<double>& crowning,
                                         const ContactModelOptions& options) {
  const CamSide<double>& cam = r.side(s);
  const SideSeries& ss = s == Side::kInput ? series.input : series.output;
  const double length = cam.contact_length(), rr = cam.roller_radius;
  const int steps = int(series.theta_rad.size());
  Contact3DCycleSide out;
  out.max_stress_MPa.assign(steps, 0.0);
  out.stress_force_N.assign(steps, 0.0);
  out.stress_radius_mm.assign(steps, 0.0);

  // Every loaded contact with its R' (contact.h's curvature; +inf stress where R' <= 0).
  std::vector<Contact> contacts;
  bool undercut = false;
  double f_max = 0, r_min = kInf, r_max = 0;
  for (int i = 0; i < steps; ++i) {
    const auto rc = RollerContacts(r, s, series.theta_rad[i]);
    for (size_t k = 0; k < rc.size(); ++k) {
      const double f = ss.roller_force_N[i][k];
      if (!(f > 0)) continue;
      const double r_eff = rr * (1.0 - rr * rc[k].curvature);
      if (!(r_eff > 0)) {
        undercut = true;
        out.max_stress_MPa[i] = kInf;
        continue;
      }
      contacts.push_back({i, int(k), f, r_eff});
      f_max = std::max(f_max, f), r_min = std::min(r_min, r_eff), r_max = std::max(r_max, r_eff);
    }
  }
  const auto line = [&](double f, double r_eff) { return contact::LineContactPeakPressure(f, length, r_eff, e_star); };
  const auto slices = [&](double f, double r_eff) {
    return RollerContactSlices<double>(f, r_eff, length, e_star, crowning, options.misalignment_rad, options.slices);
  };

  // Ratio table (slices / line) over (ln F, R').
  const int nf = 13, nr = 5;
  std::vector<double> lf(nf), rv(nr), ratio(nf * nr, 1.0);
  const bool model3d = options.model != ContactModel::kLine && !contacts.empty();
  if (model3d) {
    const double f_lo = f_max * 1e-3;
    for (int a = 0; a < nf; ++a) lf[a] = std::log(f_lo) + (std::log(f_max) - std::log(f_lo)) * a / (nf - 1);
    for (int b = 0; b < nr; ++b) rv[b] = r_min + (r_max - r_min) * b / (nr - 1);
    for (int a = 0; a < nf; ++a)
      for (int b = 0; b < nr; ++b) {
        const double f = std::exp(lf[a]);
        const auto sol = slices(f, rv[b]);
        ratio[a * nr + b] = sol.peak_pressure / line(f, rv[b]);
        out.edge_loaded = out.edge_loaded || sol.edge_loaded;
        out.converged = out.converged && sol.converged;
        out.slice_width_mm = sol.slice_width;
      }
  }
  const auto interpolate = [&](double f, double r_eff) {
    if (!model3d) return 1.0;
    const double u = std::clamp((std::log(f) - lf[0]) / (lf[1] - lf[0]), 0.0, nf - 1.0);
    const double v = r_max > r_min ? std::clamp((r_eff - r_min) / (rv[1] - rv[0]), 0.0, nr - 1.0) : 0.0;
    const int a = std::min(int(u), nf - 2), b = std::min(int(v), std::max(nr - 2, 0));
    const double du = u - a, dv = r_max > r_min ? v - b : 0.0;
    const auto at = [&](int i, int j) { return ratio[i * nr + j]; };
    return (1 - du) * ((1 - dv) * at(a, b) + dv * at(a, b + 1)) + du * ((1 - dv) * at(a + 1, b) + dv * at(a + 1, b + 1));
  };
  std::vector<double> estimate(contacts.size());
  for (size_t c = 0; c < contacts.size(); ++c) {
    const Contact& k = contacts[c];
    estimate[c] = line(k.force, k.r_eff) * interpolate(k.force, k.r_eff);
    if (estimate[c] > out.max_stress_MPa[k.angle]) {
      out.max_stress_MPa[k.angle] = estimate[c];
      out.stress_force_N[k.angle] = k.force;
      out.stress_radius_mm[k.angle] = k.r_eff;
    }
  }
  if (undercut) {
    out.max_contact_stress_MPa = kInf;
    return out;
  }
  if (contacts.empty()) return out;

  // The worst contacts (distinct angles), solved exactly.
  std::vector<size_t> order(contacts.size());
  for (size_t c = 0; c < order.size(); ++c) order[c] = c;
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return estimate[a] > estimate[b]; });
  std::vector<int> used;
  contact::HalfSpaceSolver solver;
  double best = -1;
  for (size_t c : order) {
    if (used.size() >= (model3d ? 4u : 1u)) break;
    const Contact& k = contacts[c];
    if (std::find(used.begin(), used.end(), k.angle) != used.end()) continue;
    used.push_back(k.angle);
    double value = estimate[c];
    std::vector<double> y, p;
    if (model3d) {
      const auto sol = slices(k.force, k.r_eff);
      out.interpolation_error_MPa = std::max(out.interpolation_error_MPa, std::abs(sol.peak_pressure - estimate[c]));
      out.edge_loaded = out.edge_loaded || sol.edge_loaded;
      value = sol.peak_pressure;
      out.max_stress_MPa[k.angle] = value;  // the exact solve replaces its estimate
      y = sol.y_mm;
      p = sol.pressure_MPa;
      if (options.model == ContactModel::kHalfSpace) {
        double hint = 0;
        for (double b : sol.half_width_mm) hint = std::max(hint, b);
        const auto h = contact::SolveRollerHalfSpace(
            k.force, k.r_eff, length, e_star,
            [&](double yy) { return GapAlongRoller(crowning, options.misalignment_rad, yy); }, options.grid_nx,
            options.grid_ny, hint, solver);
        out.converged = out.converged && h.converged;
        out.edge_loaded = out.edge_loaded || h.edge_loaded;
        out.cell_dx_mm = h.dx_mm, out.cell_dy_mm = h.dy_mm;
        if (h.peak_pressure_MPa > best) out.slices_peak_at_worst_MPa = sol.peak_pressure;
        value = h.peak_pressure_MPa;
        y = h.y_mm;
        p = h.pressure_along_y;
      }
    } else {
      const int n = 2;
      y = {-0.5 * length, 0.5 * length};
      p.assign(n, value);
    }
    if (value > best) {
      best = value;
      out.worst_angle = k.angle, out.worst_roller = k.roller;
      out.worst_y_mm = y, out.worst_pressure_MPa = p;
    }
  }
  out.max_contact_stress_MPa = best;
  return out;
}

}  // namespace camopt::lcr

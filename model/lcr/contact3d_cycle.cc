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

// A field of nx × ny cells on the grid of 2nx × 2ny cells over the same extent: each cell's value
// on its four children.
std::vector<double> Refined(const std::vector<double>& coarse, int nx, int ny) {
  std::vector<double> fine(size_t(4) * nx * ny);
  for (int iy = 0; iy < 2 * ny; ++iy)
    for (int ix = 0; ix < 2 * nx; ++ix) fine[size_t(iy) * 2 * nx + ix] = coarse[size_t(iy / 2) * nx + ix / 2];
  return fine;
}

}  // namespace

Contact3DCycleSide AnalyzeCycleContact3D(const Reducer<double>& r, Side s, const CycleSeries& series,
                                         double e_star, const RollerCrowning<double>& crowning,
                                         const ContactModelOptions& options) {
  // One grid, the options' (unused by the slices model), no starts.
  return AnalyzeCycleContact3DOnGrids(r, s, series, e_star, crowning, options, {{options.grid_nx, options.grid_ny}},
                                      {})
      .front();
}

std::vector<Contact3DCycleSide> AnalyzeCycleContact3DOnGrids(const Reducer<double>& r, Side s,
                                                             const CycleSeries& series, double e_star,
                                                             const RollerCrowning<double>& crowning,
                                                             const ContactModelOptions& options,
                                                             const std::vector<std::array<int, 2>>& grids,
                                                             const HalfSpaceStarts& starts) {
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
  const std::vector<double> kappa = CycleCurvatures(r, s, series.theta_rad);
  const size_t rollers = size_t(cam.rollers);
  for (int i = 0; i < steps; ++i) {
    const double* const forces = ss.roller_force_N.row(size_t(i));
    for (size_t k = 0; k < rollers; ++k) {
      const double f = forces[k];
      if (!(f > 0)) continue;
      const double r_eff = rr * (1.0 - rr * kappa[size_t(i) * rollers + k]);
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
    return std::vector<Contact3DCycleSide>(grids.size(), out);
  }
  if (contacts.empty()) return std::vector<Contact3DCycleSide>(grids.size(), out);

  // The worst contacts (distinct angles), solved exactly by the slices model: in the order of a
  // stable sort by falling estimate, each the largest estimate at an angle not yet taken (the
  // first such contact on a tie), found by a pass over the contacts per pick instead of a sort.
  struct Worst {
    size_t c;
    double value;
    std::vector<double> y, p;
    double peak_slices = 0, hint = 0;
  };
  std::vector<Worst> worst;
  std::vector<int> used;
  const size_t wanted = model3d ? 4u : 1u;
  while (used.size() < wanted) {
    size_t c = contacts.size();
    for (size_t i = 0; i < contacts.size(); ++i)
      if ((c == contacts.size() || estimate[i] > estimate[c]) &&
          std::find(used.begin(), used.end(), contacts[i].angle) == used.end())
        c = i;
    if (c == contacts.size()) break;
    const Contact& k = contacts[c];
    used.push_back(k.angle);
    Worst w{c, estimate[c], {}, {}};
    if (model3d) {
      const auto sol = slices(k.force, k.r_eff);
      out.interpolation_error_MPa = std::max(out.interpolation_error_MPa, std::abs(sol.peak_pressure - estimate[c]));
      out.edge_loaded = out.edge_loaded || sol.edge_loaded;
      w.value = w.peak_slices = sol.peak_pressure;
      out.max_stress_MPa[k.angle] = w.value;  // the exact solve replaces its estimate
      w.y = sol.y_mm;
      w.p = sol.pressure_MPa;
      for (double b : sol.half_width_mm) w.hint = std::max(w.hint, b);
    } else {
      w.y = {-0.5 * length, 0.5 * length};
      w.p.assign(2, w.value);
    }
    worst.push_back(std::move(w));
  }

  // Per grid: the half_space solves of the same contacts (half_space only), and the largest.
  std::vector<Contact3DCycleSide> outs(grids.size(), out);
  contact::HalfSpaceSolver solver;
  // The previous grid's pressure per worst contact (a start for the next grid's solve).
  std::vector<contact::RollerHalfSpaceResult> previous(worst.size());
  for (size_t gi = 0; gi < grids.size(); ++gi) {
    Contact3DCycleSide& o = outs[gi];
    const int nx = grids[gi][0], ny = grids[gi][1];
    double best = -1;
    const contact::RollerHalfSpaceResult* last = nullptr;  // this grid's previous contact
    for (size_t w = 0; w < worst.size(); ++w) {
      const Contact& k = contacts[worst[w].c];
      double value = worst[w].value;
      const std::vector<double>* y = &worst[w].y;
      const std::vector<double>* p = &worst[w].p;
      if (model3d && options.model == ContactModel::kHalfSpace) {
        // The start (HalfSpaceStarts): the same contact on the previous grid when this grid
        // halves its cells over the same extent, else this grid's previous contact.
        std::vector<double> start;
        const contact::RollerHalfSpaceResult& coarse = previous[w];
        const double half_x = 1.3 * worst[w].hint;
        if (starts.from_previous_contact && last && !last->pressure_MPa.empty() &&
            int(last->pressure_MPa.size()) == nx * ny)
          start = last->pressure_MPa;
        else if (starts.from_coarser_grid && gi > 0 && nx == 2 * grids[gi - 1][0] &&
                 ny == 2 * grids[gi - 1][1] && coarse.half_x_mm == half_x && !coarse.pressure_MPa.empty())
          start = Refined(coarse.pressure_MPa, grids[gi - 1][0], grids[gi - 1][1]);
        auto h = contact::SolveRollerHalfSpace(
            k.force, k.r_eff, length, e_star,
            [&](double yy) { return GapAlongRoller(crowning, options.misalignment_rad, yy); }, nx, ny,
            worst[w].hint, solver, start.empty() ? nullptr : &start);
        o.converged = o.converged && h.converged;
        o.edge_loaded = o.edge_loaded || h.edge_loaded;
        o.cell_dx_mm = h.dx_mm, o.cell_dy_mm = h.dy_mm;
        o.half_space_iterations += h.iterations;
        if (h.peak_pressure_MPa > best) o.slices_peak_at_worst_MPa = worst[w].peak_slices;
        value = h.peak_pressure_MPa;
        previous[w] = std::move(h);
        last = &previous[w];
        y = &previous[w].y_mm;
        p = &previous[w].pressure_along_y;
      }
      if (value > best) {
        best = value;
        o.worst_angle = k.angle, o.worst_roller = k.roller;
        o.worst_y_mm = *y, o.worst_pressure_MPa = *p;
      }
    }
    o.max_contact_stress_MPa = best;
  }
  return outs;
}

}  // namespace camopt::lcr

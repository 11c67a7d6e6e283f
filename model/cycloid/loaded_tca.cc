#include "model/cycloid/loaded_tca.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "model/common/roots.h"
#include "model/contact/hertz.h"

namespace camopt::cycloid {

namespace {

// Separation of a circle of signed curvature κ from its tangent at distance x: R − sqrt(R² − x²)
// written as κx² / (1 + sqrt(1 − κ²x²)), finite at κ = 0 (eqs. 17–18).
double CircleSeparation(double kappa, double x) {
  const double kx = kappa * x;
  return kappa * x * x / (1.0 + std::sqrt(std::max(0.0, 1.0 - kx * kx)));
}

// Grid half-sizes come from a ladder 0.005 mm · 2^(k/4) so that grids (and the solver's cached
// kernels) repeat from one pair and crank angle to the next.
double LadderAbove(double x) {
  const double base = 0.005;
  const int k = std::max(0, int(std::ceil(4.0 * std::log2(std::max(x, base) / base) - 1e-9)));
  return base * std::exp2(k / 4.0);
}

// One pair's force law, modelled as a power law through its last solved point (F1, δ1):
// δ = δ1 (F / F1)^γ. A Hertzian pair follows such a law closely over a small range (γ ≈ 0.9 for a
// line contact, 2/3 for a point contact); γ is measured from the pair's last two solved points
// and kept from the previous crank angle otherwise, so one solve at a new angle already gives a
// good model. Through the origin, continuous and increasing: the equilibrium stays well posed.
struct PairModel {
  double compliance0 = 0;  // δ/F, used when nothing is solved yet
  double f1 = 0, d1 = 0;   // last solved (F, δ)
  double f0 = 0, d0 = 0;   // the one before (0, 0 if none)
  double gamma = 0.9;
  bool solved = false;
  void Add(double f, double d) {
    if (!(f > 0 && d > 0)) return;
    if (solved) {
      f0 = f1;
      d0 = d1;
      const double lf = std::log(f / f0), ld = std::log(d / d0);
      if (std::abs(lf) > 1e-4) gamma = std::clamp(ld / lf, 0.5, 1.2);
    }
    f1 = f;
    d1 = d;
    solved = true;
  }
  double Force(double delta) const {
    if (delta <= 0) return 0.0;
    if (!solved) return delta / compliance0;
    return f1 * std::pow(delta / d1, 1.0 / gamma);
  }
};

// Solves Σ l_i F_i(l_i (Δ − bl_i)) = M for Δ >= 0 by bisection (the left side is continuous,
// non-decreasing and piecewise linear in Δ).
double SolveDeflection(const std::vector<PairModel>& models, const std::vector<double>& arms,
                       const std::vector<double>& backlash, double moment) {
  auto total = [&](double delta_phi) {
    double m = 0;
    for (size_t i = 0; i < models.size(); ++i)
      m += arms[i] * models[i].Force(arms[i] * (delta_phi - backlash[i]));
    return m;
  };
  double hi = 1e-5;
  while (total(hi) < moment && hi < 1.0) hi *= 2.0;
  return BisectIncreasing(total, moment, 0.0, hi, 200, 1e-15, 1e-6).mid();
}

}  // namespace

LoadedTca::LoadedTca(const Drive& drive, const Crowning& crowning, const Material& material,
                     LoadedOptions options)
    : drive_(drive),
      crowning_(crowning),
      material_(material),
      options_(options),
      solver_(contact::SolverOptions{options.solver_tolerance, 2000}),
      rough_solver_(contact::SolverOptions{
          std::max(options.solver_tolerance, options.rough_solver_tolerance), 2000}) {
  if (const std::string why = CheckDrive(drive); !why.empty()) throw std::invalid_argument(why);
  if (const std::string why = CheckCrowning(crowning, drive.face_width_mm); !why.empty())
    throw std::invalid_argument(why);
  if (!(material.youngs_modulus_MPa > 0 && material.poisson_ratio > -1 && material.poisson_ratio < 0.5))
    throw std::invalid_argument("Young's modulus must be > 0 and Poisson's ratio in (-1, 0.5)");
  if (options_.profile_cells < 2 || options_.axial_cells < 2)
    throw std::invalid_argument("the contact grid needs at least 2 x 2 cells");
  e_star_ = material.composite_modulus_MPa();
  SetCrowning(crowning);
}

void LoadedTca::SetCrowning(const Crowning& crowning) {
  if (const std::string why = CheckCrowning(crowning, drive_.face_width_mm); !why.empty())
    throw std::invalid_argument(why);
  crowning_ = crowning;
  const double b = drive_.face_width_mm;
  const double dy = b / options_.axial_cells;
  crown_.resize(options_.axial_cells);
  for (int iy = 0; iy < options_.axial_cells; ++iy)
    crown_[iy] = CrowningDrop(crowning_, b, -0.5 * b + (iy + 0.5) * dy);
}

contact::Grid LoadedTca::MakeGrid(double half_x_mm) const {
  contact::Grid g;
  g.nx = options_.profile_cells;
  g.ny = options_.axial_cells;
  g.dx = 2.0 * half_x_mm / g.nx;
  g.dy = drive_.face_width_mm / g.ny;
  g.x0 = -half_x_mm;
  g.y0 = -0.5 * drive_.face_width_mm;
  return g;
}

std::vector<double> LoadedTca::Gap(const contact::Grid& grid, double roller_curvature,
                                   double profile_curvature) const {
  std::vector<double> gap(size_t(grid.nx) * grid.ny);
  std::vector<double> across(grid.nx);
  for (int ix = 0; ix < grid.nx; ++ix) {
    const double x = grid.x0 + (ix + 0.5) * grid.dx;
    across[ix] = CircleSeparation(roller_curvature, x) + CircleSeparation(profile_curvature, x);
  }
  // The cell centres miss the contact point itself (x = y = 0) by half a cell: shift the gap so
  // that the closest cell touches at zero approach. Otherwise a vanishing load would still need
  // an approach of min(gap) (7.5 nm at the FCM example's centre cell, q = 40) and the LTE would not
  // tend to the unloaded TE as the torque goes to zero. The shift is within the discretisation.
  const double lowest = *std::min_element(across.begin(), across.end()) +
                        *std::min_element(crown_.begin(), crown_.end());
  for (int iy = 0; iy < grid.ny; ++iy)
    for (int ix = 0; ix < grid.nx; ++ix)
      gap[size_t(iy) * grid.nx + ix] = across[ix] + crown_[iy] - lowest;
  return gap;
}

MeshLoad LoadedTca::Solve(double torque_Nmm, double crank_angle_rad) {
  if (!(torque_Nmm >= 0)) throw std::invalid_argument("torque must be >= 0");
  MeshLoad out;
  out.crank_angle_rad = crank_angle_rad;
  if (std::isinf(torque_Nmm)) {  // a torque that overflowed its unit conversion (1e308 N·m)
    out.converged = false;
    out.message = "torque balance not met: the torque is not a finite number in N·mm";
    return out;
  }
  const UnloadedMesh<double> unloaded = UnloadedTca<double>(drive_, crank_angle_rad);
  out.unloaded_rotation_rad = unloaded.rotation;
  out.rotation_rad = unloaded.rotation;
  if (unloaded.first_contact < 0) {
    out.converged = false;
    out.message = "no roller on the loaded flank";
    return out;
  }
  const double moment = torque_Nmm;
  if (moment <= 0) return out;               // zero torque: the unloaded state, no loads

  // Candidate pairs: loaded flank, backlash small enough to close.
  struct Candidate {
    const PairGeometry<double>* g;
    double curvature_sum;  // 1/R'
    contact::Grid grid;
    std::vector<double> gap, pressure;
    bool has_grid = false;
    double load = 0, approach = 0, max_p = 0;
    int solver_iterations = 0;
  };
  std::vector<Candidate> cand;
  for (const auto& g : unloaded.pairs) {
    if (!g.loaded_flank || g.backlash > options_.max_backlash_rad) continue;
    const double ksum = g.roller_curvature + g.profile_curvature;
    if (!(ksum > 1e-6)) continue;  // conformal or worse: no Hertzian pair (not met by real drives)
    Candidate c;
    c.g = &g;
    c.curvature_sum = ksum;
    cand.push_back(std::move(c));
  }
  const size_t n = cand.size();
  std::vector<PairModel> models(n);
  std::vector<double> arms(n), backlash(n);
  // First guess of a pair compliance: a line contact of the face width, δ ≈ 2F/(π B E*) · ln(…),
  // with the logarithm ≈ 5; replaced by the pair's own compliance from the previous crank angle.
  const double c_line = 2.0 / (kPi * drive_.face_width_mm * e_star_) * 5.0;
  for (size_t i = 0; i < n; ++i) {
    arms[i] = cand[i].g->arm_mm;
    backlash[i] = cand[i].g->backlash;
    models[i].compliance0 = c_line;
    // The same roller at the previous crank angle: its law is a close first model.
    auto it = memory_.find(cand[i].g->roller);
    if (it != memory_.end() && it->second.f1 > 0 && it->second.d1 > 0) {
      models[i].f1 = it->second.f1;
      models[i].d1 = it->second.d1;
      models[i].gamma = it->second.gamma;
      models[i].solved = true;
    }
  }

  std::vector<bool> solved_here(n, false);
  double delta_phi = 0;
  bool converged = false;
  // The first iterations solve the pairs roughly (they only steer the pair models); once the
  // compatibility holds at the rough level, every pair is solved at the final tolerance, warm
  // started, and only a final-tolerance iteration can end the loop.
  bool final_pass = options_.rough_solver_tolerance <= options_.solver_tolerance;
  int iter = 0;
  for (; iter < options_.max_iterations; ++iter) {
    contact::HalfSpaceSolver& solver = final_pass ? solver_ : rough_solver_;
    delta_phi = SolveDeflection(models, arms, backlash, moment);
    double max_residual = 0, max_approach = 0;
    for (size_t i = 0; i < n; ++i) {
      Candidate& c = cand[i];
      const double approach_target = arms[i] * (delta_phi - backlash[i]);
      const double force = models[i].Force(approach_target);
      if (force <= 0) {
        c.load = 0;
        c.approach = 0;
        c.max_p = 0;
        solved_here[i] = false;
        continue;
      }
      // Solve only pairs whose force moved: an unchanged force has the same approach.
      if (solved_here[i] && std::abs(force - c.load) <= 0.5 * options_.tolerance * force) {
        max_residual = std::max(max_residual, std::abs(c.approach - approach_target));
        max_approach = std::max(max_approach, c.approach);
        continue;
      }
      // Grid across the profile: a multiple of the Hertz half-width at this force.
      const double b_hertz =
          contact::LineContactHalfWidth(force, drive_.face_width_mm, 1.0 / c.curvature_sum, e_star_);
      const double want = LadderAbove(options_.grid_half_width_factor * b_hertz);
      if (!c.has_grid) {
        auto it = memory_.find(c.g->roller);
        double half = want;
        // Keep the previous angle's grid when it still fits: its pressure is a warm start.
        if (it != memory_.end() && it->second.grid.nx == options_.profile_cells) {
          const double prev = -it->second.grid.x0;
          if (prev >= 0.8 * want && prev <= 1.7 * want) half = prev;
        }
        c.grid = MakeGrid(half);
        c.gap = Gap(c.grid, c.g->roller_curvature, c.g->profile_curvature);
        c.has_grid = true;
        if (it != memory_.end() && std::abs(it->second.grid.x0 - c.grid.x0) < 1e-15)
          c.pressure = it->second.pressure;
      } else if (-c.grid.x0 < 0.55 * want) {  // load grew a lot: the contact outgrows the grid
        c.grid = MakeGrid(want);
        c.gap = Gap(c.grid, c.g->roller_curvature, c.g->profile_curvature);
        c.pressure.clear();
      }
      contact::ContactSolution s;
      for (int grow = 0; grow < 6; ++grow) {
        s = c.pressure.size() == c.gap.size()
                ? solver.SolveForLoad(c.grid, c.gap, force, e_star_, c.pressure)
                : solver.SolveForLoad(c.grid, c.gap, force, e_star_);
        ++out.contact_solves;
        out.solver_iterations += s.iterations;
        // A pressure in the outer columns across the profile: the grid cuts the contact.
        bool cut = false;
        for (int iy = 0; iy < c.grid.ny && !cut; ++iy)
          cut = s.pressure_MPa[size_t(iy) * c.grid.nx] > 0 ||
                s.pressure_MPa[size_t(iy) * c.grid.nx + c.grid.nx - 1] > 0;
        if (!cut) break;
        c.grid = MakeGrid(LadderAbove(-c.grid.x0 * 1.4));
        c.gap = Gap(c.grid, c.g->roller_curvature, c.g->profile_curvature);
        c.pressure.clear();
      }
      if (!s.converged && out.message.empty()) out.message = "contact solver: " + s.message;
      c.pressure = s.pressure_MPa;
      c.load = s.load_N;
      c.approach = s.approach_mm;
      c.max_p = s.max_pressure_MPa;
      c.solver_iterations = s.iterations;
      solved_here[i] = true;
      models[i].Add(s.load_N, s.approach_mm);
      max_residual = std::max(max_residual, std::abs(s.approach_mm - approach_target));
      max_approach = std::max(max_approach, s.approach_mm);
    }
    // Pairs left unloaded must not penetrate: their approach target is <= 0 by the model (the
    // model force is 0 only there), so the loaded pairs' compatibility is the whole test.
    if (max_approach > 0 && max_residual <= options_.tolerance * max_approach) {
      if (final_pass) {
        converged = true;
        ++iter;
        break;
      }
      final_pass = true;
      std::fill(solved_here.begin(), solved_here.end(), false);
    }
  }
  out.iterations = iter;
  out.converged = converged && out.message.empty();
  if (!converged) out.message = "compatibility not converged in " + std::to_string(iter) + " iterations";
  // The converged flag is earned: the pair loads must carry the torque, Σ l_i F_i = M, within
  // the compatibility tolerance (pairs not re-solved may lag by half of it). The deflection
  // search stops at 1 rad, so a drive far too soft or a torque far too large fails this check
  // even when every pair is compatible.
  double carried = 0;
  for (size_t i = 0; i < n; ++i) carried += arms[i] * cand[i].load;
  const double balance_tolerance = 2.0 * options_.tolerance;
  if (!(std::isfinite(moment) && std::abs(carried - moment) <= balance_tolerance * moment)) {
    out.converged = false;
    char buf[200];
    std::snprintf(buf, sizeof buf,
                  "torque balance not met: the pair loads carry %.4g%% of the torque (Σ l·F = "
                  "%.4g N·mm against %.4g N·mm; tolerance %.2g%%)",
                  100.0 * carried / moment, carried, moment, 100.0 * balance_tolerance);
    out.message = buf;
  }
  out.deflection_rad = delta_phi;
  out.rotation_rad = unloaded.rotation + delta_phi;

  std::vector<double> displacement;
  for (size_t i = 0; i < n; ++i) {
    Candidate& c = cand[i];
    PairMemory& mem = memory_[c.g->roller];
    if (c.load > 0 && c.approach > 0) {
      mem.f1 = models[i].f1;
      mem.d1 = models[i].d1;
      mem.gamma = models[i].gamma;
      mem.grid = c.grid;
      mem.pressure = c.pressure;
    }
    if (c.load <= 0) continue;
    PairLoad p;
    p.roller = c.g->roller;
    p.load_N = c.load;
    p.approach_mm = c.approach;
    p.max_pressure_MPa = c.max_p;
    p.arm_mm = c.g->arm_mm;
    p.backlash_rad = c.g->backlash;
    p.effective_radius_mm = 1.0 / c.curvature_sum;
    p.grid = c.grid;
    p.solver_iterations = c.solver_iterations;
    if (options_.edge_margin) {
      displacement = solver_.Displacement(c.grid, c.pressure, e_star_);
      double clearance = kInf, edge_p = 0;
      for (int iy : {0, c.grid.ny - 1})
        for (int ix = 0; ix < c.grid.nx; ++ix) {
          const size_t k = size_t(iy) * c.grid.nx + ix;
          clearance = std::min(clearance, c.gap[k] + displacement[k] - c.approach);
          edge_p = std::max(edge_p, c.pressure[k]);
        }
      p.edge_margin_mm = edge_p > 0 ? -edge_p / e_star_ * c.grid.dy : std::max(0.0, clearance);
    }
    if (options_.keep_pressure) p.pressure_MPa = c.pressure;
    out.max_pressure_MPa = std::max(out.max_pressure_MPa, c.max_p);
    out.pairs.push_back(std::move(p));
  }
  out.pairs_in_contact = int(out.pairs.size());
  if (!out.pairs.empty()) {
    out.edge_margin_mm = kInf;
    for (const auto& p : out.pairs) out.edge_margin_mm = std::min(out.edge_margin_mm, p.edge_margin_mm);
  }
  return out;
}

std::vector<double> UniformCrankAngles(int steps, double span_rad) {
  std::vector<double> a(steps);
  for (int k = 0; k < steps; ++k) a[k] = span_rad * k / steps;
  return a;
}

CycleResult RunCycle(LoadedTca& tca, double torque_Nmm, const std::vector<double>& angles,
                     const std::function<void(double)>& progress) {
  CycleResult r;
  const size_t n = angles.size();
  for (size_t k = 0; k < n; ++k) {
    r.meshes.push_back(tca.Solve(torque_Nmm, angles[k]));
    if (progress) progress(double(k + 1) / n);
  }
  r.lte_arcsec.resize(n);
  for (size_t k = 0; k < n; ++k) r.lte_arcsec[k] = r.meshes[k].rotation_rad * kArcsecPerRad;
  // Periodic when the angles sample a whole number of mesh periods uniformly.
  const int n1 = tca.drive().rollers;
  const double period = 2.0 * kPi / n1;
  bool periodic = n >= 3;
  double step = 0, span = 0;
  if (periodic) {
    step = angles[1] - angles[0];
    for (size_t k = 1; k < n && periodic; ++k)
      periodic = std::abs(angles[k] - angles[k - 1] - step) < 1e-9 * std::max(1.0, std::abs(step));
    span = step * n;
    const double periods = span / period;
    periodic = periodic && step > 0 && std::abs(periods - std::round(periods)) < 1e-6 &&
               std::round(periods) >= 1;
  }
  r.gear_ratio.resize(n);
  const double n2 = tca.drive().teeth;
  for (size_t k = 0; k < n; ++k) {
    double slope = 0;  // dβ/dφ
    if (n >= 2) {
      if (periodic) {
        const size_t kp = (k + 1) % n, km = (k + n - 1) % n;
        slope = (r.meshes[kp].rotation_rad - r.meshes[km].rotation_rad) / (2.0 * step);
      } else {
        const size_t kp = std::min(k + 1, n - 1), km = k == 0 ? 0 : k - 1;
        const double h = angles[kp] - angles[km];
        if (std::abs(h) > 0) slope = (r.meshes[kp].rotation_rad - r.meshes[km].rotation_rad) / h;
      }
    }
    // The disc turns by −φ/n2 − β (clockwise for a counter-clockwise crank): |dφ_out/dφ| =
    // 1/n2 + dβ/dφ, and the ratio is its inverse.
    r.gear_ratio[k] = 1.0 / (1.0 / n2 + slope);
  }
  if (n > 0) {
    const auto [lo, hi] = std::minmax_element(r.lte_arcsec.begin(), r.lte_arcsec.end());
    r.lte_peak_to_peak_arcsec = *hi - *lo;
    double s = 0;
    for (double v : r.lte_arcsec) s += std::abs(v);
    r.lte_mean_abs_arcsec = s / n;
    const auto [glo, ghi] = std::minmax_element(r.gear_ratio.begin(), r.gear_ratio.end());
    r.gear_ratio_peak_to_peak = *ghi - *glo;
    r.edge_margin_mm = kInf;
  }
  for (size_t k = 0; k < n; ++k) {
    const MeshLoad& m = r.meshes[k];
    if (m.max_pressure_MPa > r.max_pressure_MPa) {
      r.max_pressure_MPa = m.max_pressure_MPa;
      r.max_pressure_index = int(k);
    }
    r.max_pairs_in_contact = std::max(r.max_pairs_in_contact, m.pairs_in_contact);
    r.contact_solves += m.contact_solves;
    r.solver_iterations += m.solver_iterations;
    r.converged = r.converged && m.converged;
    if (!m.pairs.empty()) r.edge_margin_mm = std::min(r.edge_margin_mm, m.edge_margin_mm);
  }
  if (!std::isfinite(r.edge_margin_mm)) r.edge_margin_mm = 0;
  return r;
}

}  // namespace camopt::cycloid

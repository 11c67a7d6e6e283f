#include "model/cycloid/loaded_tca.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>

#include "model/common/roots.h"
#include <ceres/jet.h>

#include "model/contact/hertz.h"

namespace camopt::cycloid {

namespace {

// Separation of a circle of signed curvature κ from its tangent at distance x: R − sqrt(R² − x²)
// written as κx² / (1 + sqrt(1 − κ²x²)), finite at κ = 0 (eqs. 17–18).
double CircleSeparation(double kappa, double x) {
  const double kx = kappa * x;
  return kappa * x * x / (1.0 + std::sqrt(std::max(0.0, 1.0 - kx * kx)));
}
// The same over a Jet; where |κx| >= 1 (the cell lies beyond a very sharp tooth's quarter circle)
// the double version's clamped root is 0, and so is this one's (no NaN from the root's derivative).
template <typename T>
T CircleSeparation(const T& kappa, double x) {
  using std::sqrt;
  const T kx = kappa * x;
  const T radicand = 1.0 - kx * kx;
  if (!(Value(radicand) > 0.0)) return kappa * x * x;
  return kappa * x * x / (1.0 + sqrt(radicand));
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

using J1 = ceres::Jet<double, 1>;

// Distance from the contact's axial end to the face end [mm], the smaller of the two sides, with
// the end located within a cell: along each side the row maxima P (over x) fall like sqrt(distance
// to the end) near an elliptical end, so P² is linear there and the end lies t/(1 − t) cells beyond
// the outermost loaded row k, t = P_k² / P_(k−1)². When the end row itself is loaded the distance
// is dy/2 − dy·t/(1 − t) down to t = 1/3 (end exactly at the face end), continued linearly (C¹)
// beyond: −(9/4)·dy·(t − 1/3), bounded for a pressure that rises towards the edge (a straight
// tooth). Continuous in the crowning up to the P² model's error when a row enters contact.
template <typename T>
T EndDistanceFromRows(const contact::Grid& g, const std::vector<T>& rows) {
  using std::abs;
  const double half = 0.5 * g.ny * g.dy;
  T result(kInf);
  bool any = false;
  auto take = [&](const T& d) {
    if (!any || d < result) result = d;
    any = true;
  };
  for (int side : {-1, 1}) {
    // Rows outward from the face centre on this side.
    std::vector<int> out;
    if (side > 0)
      for (int iy = g.ny / 2; iy < g.ny; ++iy) out.push_back(iy);
    else
      for (int iy = (g.ny - 1) / 2; iy >= 0; --iy) out.push_back(iy);
    int k = -1;
    for (int j = 0; j < int(out.size()); ++j)
      if (rows[out[j]] > T(0.0)) k = j;
    if (k < 0) continue;
    const double dist_k = std::abs(g.y_centre_mm(out[k]));
    if (k == 0 || !(rows[out[k - 1]] > T(0.0))) {
      take(T(half - dist_k - 0.5 * g.dy));
      continue;
    }
    const T pk = rows[out[k]], pp = rows[out[k - 1]];
    const T t = (pk * pk) / (pp * pp);
    T d;
    if (k == int(out.size()) - 1)
      d = t <= T(1.0 / 3.0) ? T(0.5 * g.dy) - g.dy * t / (T(1.0) - t) : T(-2.25 * g.dy) * (t - T(1.0 / 3.0));
    else if (t < T(0.5))
      d = T(half - dist_k) - g.dy * (t / (T(1.0) - t));
    else
      d = T(half - dist_k - g.dy) + T(0.0) * t;  // min(t/(1 − min(t, 0.5)), 1) = 1 for t >= 0.5
    take(d);
  }
  return any ? result : T(0.0);
}

// The end distance's derivative as a linear functional of a pressure change dp with each row's
// peak cell frozen: (cell, ∂E/∂p_cell) for the cells it depends on (at most the two outermost
// loaded rows' peaks of one side).
std::vector<std::pair<size_t, double>> EndDistanceWeights(const contact::Grid& g, const std::vector<double>& p) {
  // Each row's maximum over x (its first largest cell) and that cell.
  std::vector<J1> rows(g.ny, J1(0.0));
  std::vector<size_t> cell(g.ny, 0);
  for (int iy = 0; iy < g.ny; ++iy)
    for (int ix = 0; ix < g.nx; ++ix) {
      const size_t k = size_t(iy) * g.nx + ix;
      if (p[k] > rows[iy].a) rows[iy].a = p[k], cell[iy] = k;
    }
  std::vector<std::pair<size_t, double>> w;
  for (int iy = 0; iy < g.ny; ++iy) {
    if (!(rows[iy].a > 0)) continue;
    for (J1& r : rows) r.v[0] = 0.0;
    rows[iy].v[0] = 1.0;
    const double c = EndDistanceFromRows<J1>(g, rows).v[0];
    if (c != 0) w.emplace_back(cell[iy], c);
  }
  return w;
}

// Distance from the contact's axial end to the face end [mm], the smaller of the two sides, with
// the end located within a cell: along each side the row maxima P (over x) fall like sqrt(distance
// to the end) near an elliptical end, so P² is linear there and the end lies t/(1 − t) cells beyond
// the outermost loaded row k, t = P_k² / P_(k−1)². When the end row itself is loaded the distance
// is dy/2 − dy·t/(1 − t) down to t = 1/3 (end exactly at the face end), continued linearly (C¹)
// beyond: −(9/4)·dy·(t − 1/3), bounded for a pressure that rises towards the edge (a straight
// tooth). Continuous in the crowning up to the P² model's error when a row enters contact.
double EndDistance(const contact::Grid& g, const std::vector<double>& p) {
  std::vector<double> rows(g.ny, 0.0);
  for (int iy = 0; iy < g.ny; ++iy)
    for (int ix = 0; ix < g.nx; ++ix) rows[iy] = std::max(rows[iy], p[size_t(iy) * g.nx + ix]);
  return EndDistanceFromRows<double>(g, rows);
}

}  // namespace

LoadedTca::LoadedTca(const Drive& drive, const Crowning& crowning, const Material& material,
                     LoadedOptions options)
    : drive_(drive),
      crowning_(crowning),
      material_(material),
      options_(options),
      solver_(std::make_shared<contact::HalfSpaceSolver>(
          contact::SolverOptions{options.solver_tolerance, 2000, false, options.precondition_solves})),
      // The steering solves run the plain iteration: warm started at 1e-2 they stop after 2.8
      // iterations plain and 2.6 preconditioned (each then two FFT pairs); preconditioned, they
      // leave the final solves 4.3 instead of 7.2 iterations, but the NNM cycle takes 5 452
      // contact FFT pairs against 5 096 this way (docs/performance.md).
      rough_solver_(std::make_shared<contact::HalfSpaceSolver>(contact::SolverOptions{
          std::max(options.solver_tolerance, options.rough_solver_tolerance), 2000, false, false})) {
  if (const auto issues = CheckDrive(drive); !issues.empty()) throw std::invalid_argument(issues.front().message);
  if (const std::string why = CheckCrowning(crowning, drive.face_width_mm); !why.empty())
    throw std::invalid_argument(why);
  if (!(material.youngs_modulus_MPa > 0 && material.poisson_ratio > -1 && material.poisson_ratio < 0.5))
    throw std::invalid_argument("Young's modulus must be > 0 and Poisson's ratio in (-1, 0.5)");
  if (options_.profile_cells < 2 || options_.axial_cells < 2)
    throw std::invalid_argument("the contact grid needs at least 2 x 2 cells");
  e_star_ = material.composite_modulus_MPa();
  SetCrowning(crowning);
}

LoadedTca LoadedTca::WithCrowning(const Crowning& crowning) const {
  LoadedTca copy = *this;
  copy.SetCrowning(crowning);
  return copy;
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

namespace {
// The previous crank angle's pressure of a pair on another grid across the profile (both grids
// centred on the contact point, the same axial rows): linear in x between the old cell centres,
// zero beyond them. Only a starting point of the load-controlled solve (which rescales it to the
// load and iterates to its tolerance): the contact moves little along the profile between angles.
std::vector<double> ResampleAcross(const contact::Grid& from, const std::vector<double>& p,
                                   const contact::Grid& to) {
  std::vector<double> out(size_t(to.cells()), 0.0);
  for (int ix = 0; ix < to.nx; ++ix) {
    const double f = (to.x_centre_mm(ix) - from.x0) / from.dx - 0.5;  // fractional old index
    if (!(f > -0.5 && f < from.nx - 0.5)) continue;
    const int i0 = std::clamp(int(std::floor(f)), 0, from.nx - 2);
    const double t = std::clamp(f - i0, 0.0, 1.0);
    for (int iy = 0; iy < to.ny; ++iy) {
      const size_t row = size_t(iy) * from.nx;
      out[size_t(iy) * to.nx + ix] = (1.0 - t) * p[row + i0] + t * p[row + i0 + 1];
    }
  }
  return out;
}

// A pair's load sensitivity dp/dW (non-zero on its contact set) at the previous crank angle as a
// start of the next one on the contact set of `to_pressure`: each axial row's contact interval
// across the profile is stretched onto the new row's interval (edge to edge, linear between the
// old cell centres, scaled by the ratio of the widths), and the rows in contact likewise (linear
// between two old rows). A frozen set's load sensitivity is edge-singular, like a punch's: it
// moves with the set's edges, and a stretch of the strip maps its shape onto itself (the overall
// scale is set by the load condition in SensitivityForLoad). Empty when the old field has no
// contact.
std::vector<double> StretchToSet(const contact::Grid& from, const std::vector<double>& w,
                                 const contact::Grid& to, const std::vector<double>& to_pressure) {
  auto rows = [](const contact::Grid& g, const std::vector<double>& f, int& lo, int& hi) {
    lo = g.ny, hi = -1;
    for (int iy = 0; iy < g.ny; ++iy)
      for (int ix = 0; ix < g.nx; ++ix)
        if (f[size_t(iy) * g.nx + ix] != 0) {
          lo = std::min(lo, iy), hi = std::max(hi, iy);
          break;
        }
  };
  int lo0, hi0, lo1, hi1;
  rows(from, w, lo0, hi0);
  rows(to, to_pressure, lo1, hi1);
  if (hi0 < 0 || hi1 < 0) return {};
  std::vector<double> out(size_t(to.cells()), 0.0);
  // Old row oy stretched onto new row iy's interval [l1, r1] (cells), added with the weight v;
  // its values scaled by the ratio of the widths (a strip's sensitivity per unit row load is
  // inversely proportional to its width).
  auto stretch_row = [&](int oy, int iy, int l1, int r1, double v) {
    const double* old_row = w.data() + size_t(oy) * from.nx;
    int l0 = -1, r0 = -1;
    for (int ix = 0; ix < from.nx; ++ix)
      if (old_row[ix] != 0) {
        if (l0 < 0) l0 = ix;
        r0 = ix;
      }
    if (l0 < 0) return;
    const double a0 = from.x0 + l0 * from.dx, b0 = from.x0 + (r0 + 1) * from.dx;  // edges [mm]
    const double a1 = to.x0 + l1 * to.dx, b1 = to.x0 + (r1 + 1) * to.dx;
    const double scale = v * (b0 - a0) / (b1 - a1);
    for (int ix = l1; ix <= r1; ++ix) {
      const double x = a0 + (to.x_centre_mm(ix) - a1) / (b1 - a1) * (b0 - a0);
      const double f = std::clamp((x - from.x0) / from.dx - 0.5, double(l0), double(r0));
      const int i0 = std::min(int(std::floor(f)), std::max(l0, r0 - 1));
      const double u = r0 > l0 ? std::clamp(f - i0, 0.0, 1.0) : 0.0;
      out[size_t(iy) * to.nx + ix] += scale * ((1.0 - u) * old_row[i0] + u * old_row[std::min(i0 + 1, r0)]);
    }
  };
  for (int iy = lo1; iy <= hi1; ++iy) {
    int l1 = -1, r1 = -1;
    for (int ix = 0; ix < to.nx; ++ix)
      if (to_pressure[size_t(iy) * to.nx + ix] > 0) {
        if (l1 < 0) l1 = ix;
        r1 = ix;
      }
    if (l1 < 0) continue;
    // The row's place in the old rows in contact (centres, linear between two rows).
    const double t = (iy + 0.5 - lo1) / (hi1 + 1 - lo1);
    const double fy = std::clamp(lo0 + t * (hi0 + 1 - lo0) - 0.5, double(lo0), double(hi0));
    const int oy = std::min(int(std::floor(fy)), std::max(lo0, hi0 - 1));
    const double v = hi0 > lo0 ? std::clamp(fy - oy, 0.0, 1.0) : 0.0;
    stretch_row(oy, iy, l1, r1, 1.0 - v);
    if (v > 0) stretch_row(std::min(oy + 1, hi0), iy, l1, r1, v);
  }
  return out;
}

// A pressure in the outer columns across the profile: the grid cuts the contact.
bool CutAcross(const contact::Grid& g, const std::vector<double>& p) {
  for (int iy = 0; iy < g.ny; ++iy)
    if (p[size_t(iy) * g.nx] > 0 || p[size_t(iy) * g.nx + g.nx - 1] > 0) return true;
  return false;
}
}  // namespace

MeshLoad LoadedTca::Solve(double torque_Nmm, double crank_angle_rad, LtcaWarmStart* warm) const {
  if (!(torque_Nmm >= 0)) throw std::invalid_argument("torque must be >= 0");
  MeshLoad out;
  out.crank_angle_rad = crank_angle_rad;
  // A solve without a loaded state (below: an infinite torque, no roller on the loaded flank) is
  // reported as not converged; its slope is a placeholder 0 so that a cycle's series stay whole.
  if (options_.crank_slope) out.rotation_slope = 0.0;
  if (std::isinf(torque_Nmm)) {  // a torque that overflowed its unit conversion (1e308 N·m)
    out.converged = false;
    out.message = "torque balance not met: the torque is not a finite number in N·mm";
    return out;
  }
  const UnloadedMesh<double> unloaded = UnloadedTca<double>(drive_, crank_angle_rad, shape_ ? &shape_ : nullptr);
  out.unloaded_rotation_rad = unloaded.rotation;
  out.rotation_rad = unloaded.rotation;
  if (unloaded.first_contact < 0) {
    out.converged = false;
    out.message = "no roller on the loaded flank";
    return out;
  }
  const double moment = torque_Nmm;
  if (moment <= 0) {  // zero torque: the unloaded state, no loads
    if (options_.crank_slope) out.rotation_slope = CrankSlope(out, nullptr);
    return out;
  }

  // Candidate pairs: loaded flank, backlash small enough to close.
  struct Candidate {
    const PairGeometry<double>* g;
    double curvature_sum;  // 1/R'
    contact::Grid grid;
    std::vector<double> gap, pressure;
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
  // with the logarithm ≈ 5.
  const double c_line = 2.0 / (kPi * drive_.face_width_mm * e_star_) * 5.0;
  for (size_t i = 0; i < n; ++i) {
    arms[i] = cand[i].g->arm_mm;
    backlash[i] = cand[i].g->backlash;
    models[i].compliance0 = c_line;
  }
  // The grids come from the inputs only: each pair's force under that linear first model (a
  // deterministic estimate; at least a tenth of the largest), as a ladder size of a multiple of
  // its Hertz half-width. A grid grows only when the converged contact reaches its outer columns.
  {
    const double d0 = SolveDeflection(models, arms, backlash, moment);
    std::vector<double> f_est(n);
    double f_max = 0;
    for (size_t i = 0; i < n; ++i) {
      f_est[i] = models[i].Force(arms[i] * (d0 - backlash[i]));
      f_max = std::max(f_max, f_est[i]);
    }
    for (size_t i = 0; i < n; ++i) {
      const double b_hertz = contact::LineContactHalfWidth(
          std::max(f_est[i], 0.1 * f_max), drive_.face_width_mm, 1.0 / cand[i].curvature_sum, e_star_);
      cand[i].grid = MakeGrid(LadderAbove(options_.grid_half_width_factor * b_hertz));
      cand[i].gap = Gap(cand[i].grid, cand[i].g->roller_curvature, cand[i].g->profile_curvature);
    }
  }
  // The warm start: the same roller's law and pressure from the caller's previous solve.
  if (warm) {
    for (size_t i = 0; i < n; ++i) {
      auto it = warm->pairs.find(cand[i].g->roller);
      if (it == warm->pairs.end()) continue;
      const LtcaWarmStart::Pair& w = it->second;
      if (w.f1 > 0 && w.d1 > 0) {
        models[i].f1 = w.f1;
        models[i].d1 = w.d1;
        models[i].gamma = w.gamma;
        models[i].solved = true;
      }
      const contact::Grid& g = cand[i].grid;
      if (w.grid.nx == g.nx && w.grid.ny == g.ny && w.grid.dx == g.dx && w.grid.x0 == g.x0 &&
          w.pressure.size() == cand[i].gap.size())
        cand[i].pressure = w.pressure;
      else if (w.grid.ny == g.ny && w.grid.dy == g.dy && w.grid.nx > 1 &&
               w.pressure.size() == size_t(w.grid.cells()))
        cand[i].pressure = ResampleAcross(w.grid, w.pressure, g);
    }
  }

  std::vector<bool> solved_here(n, false);
  double delta_phi = 0;
  bool converged = false, cut_on_last_iteration = false;
  // The first iterations solve the pairs roughly (they only steer the pair models); once the
  // compatibility holds at the rough level, every pair is solved at the final tolerance, warm
  // started, and only a final-tolerance iteration can end the loop.
  bool final_pass = options_.rough_solver_tolerance <= options_.solver_tolerance;
  int iter = 0;
  for (; iter < options_.max_iterations; ++iter) {
    contact::HalfSpaceSolver& solver = final_pass ? *solver_ : *rough_solver_;
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
      const contact::ContactSolution s =
          c.pressure.size() == c.gap.size()
              ? solver.SolveForLoad(c.grid, c.gap, force, e_star_, c.pressure)
              : solver.SolveForLoad(c.grid, c.gap, force, e_star_);
      ++out.contact_solves;
      out.solver_iterations += s.iterations;
      if (!s.converged && final_pass && out.message.empty()) out.message = "contact solver: " + s.message;
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
        // A converged contact that reaches the outer columns is cut by its grid: grow that grid
        // (a ladder size 1.4 times larger) and iterate on. Decided on the converged state only,
        // so the grid does not depend on the path (nor on a warm start).
        // With no iteration left to solve a grown grid, the loop ends unconverged on the state
        // as solved (each loaded pair keeps its grid and pressure).
        bool cut = false;
        for (size_t i = 0; i < n; ++i) cut = cut || (cand[i].load > 0 && CutAcross(cand[i].grid, cand[i].pressure));
        if (cut && iter + 1 >= options_.max_iterations) {
          ++iter;
          cut_on_last_iteration = true;
          break;
        }
        bool grown = false;
        for (size_t i = 0; i < n; ++i) {
          Candidate& c = cand[i];
          if (c.load <= 0 || !CutAcross(c.grid, c.pressure)) continue;
          c.grid = MakeGrid(LadderAbove(-c.grid.x0 * 1.4));
          c.gap = Gap(c.grid, c.g->roller_curvature, c.g->profile_curvature);
          c.pressure.clear();
          solved_here[i] = false;
          grown = true;
        }
        if (!grown) {
          converged = true;
          ++iter;
          break;
        }
        continue;
      }
      final_pass = true;
      std::fill(solved_here.begin(), solved_here.end(), false);
    }
  }
  out.iterations = iter;
  out.converged = converged && out.message.empty();
  if (cut_on_last_iteration)
    out.message = "a contact reaches the edge of its grid after the last of " + std::to_string(iter) +
                  " iterations (no iteration left to solve it on a larger grid)";
  else if (!converged)
    out.message = "compatibility not converged in " + std::to_string(iter) + " iterations";
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
    if (warm && c.load > 0 && c.approach > 0) {
      LtcaWarmStart::Pair& w = warm->pairs[c.g->roller];
      w.f1 = models[i].f1;
      w.d1 = models[i].d1;
      w.gamma = models[i].gamma;
      w.grid = c.grid;
      w.pressure = c.pressure;
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
      displacement = solver_->Displacement(c.grid, c.pressure, e_star_);
      double clearance = kInf, edge_p = 0;
      for (int iy : {0, c.grid.ny - 1})
        for (int ix = 0; ix < c.grid.nx; ++ix) {
          const size_t k = size_t(iy) * c.grid.nx + ix;
          clearance = std::min(clearance, c.gap[k] + displacement[k] - c.approach);
          edge_p = std::max(edge_p, c.pressure[k]);
        }
      p.edge_margin_mm = edge_p > 0 ? -edge_p / e_star_ * c.grid.dy : std::max(0.0, clearance);
      p.end_distance_mm = EndDistance(c.grid, c.pressure);
    }
    if (options_.keep_pressure || options_.crank_slope) p.pressure_MPa = c.pressure;
    out.max_pressure_MPa = std::max(out.max_pressure_MPa, c.max_p);
    out.pairs.push_back(std::move(p));
  }
  out.pairs_in_contact = int(out.pairs.size());
  if (!out.pairs.empty()) {
    out.edge_margin_mm = kInf;
    out.end_distance_mm = kInf;
    for (const auto& p : out.pairs) {
      out.edge_margin_mm = std::min(out.edge_margin_mm, p.edge_margin_mm);
      out.end_distance_mm = std::min(out.end_distance_mm, p.end_distance_mm);
    }
  }
  // The slope at the state reached (converged or not: an unconverged solve is reported as such).
  if (options_.crank_slope) {
    const double slope = CrankSlope(out, warm);
    out.rotation_slope = std::isfinite(slope) ? slope : 0.0;  // the placeholder, as above
    if (!std::isfinite(slope) && out.converged) {
      out.converged = false;
      out.message = "the LTE's slope over the crank angle is not a finite number";
    }
  }
  if (!options_.keep_pressure)
    for (PairLoad& p : out.pairs) p.pressure_MPa = {};
  return out;
}

double LoadedTca::CrankSlope(MeshLoad& solved, LtcaWarmStart* warm) const {
  // Each pair's load sensitivity starts from the same roller's at the previous solve: on the same
  // frozen contact set it is the same field (it depends on the set and grid only, not on the
  // load), and as the set grows or shrinks between angles its shape moves with the set's edges
  // (StretchToSet). NNM cycle: 8.6 → 6.8 CG iterations per load sensitivity
  // (docs/performance.md); the stopping test is unchanged.
  LoadSensitivities sens;
  sens.by_pair.resize(solved.pairs.size());
  if (warm)
    for (size_t i = 0; i < solved.pairs.size(); ++i) {
      auto it = warm->pairs.find(solved.pairs[i].roller);
      if (it == warm->pairs.end()) continue;
      const contact::Grid& from = it->second.sensitivity_grid;
      const std::vector<double>& w = it->second.load_sensitivity;
      const contact::Grid& to = solved.pairs[i].grid;
      if (w.empty() || w.size() != size_t(from.cells())) continue;
      if (from.ny == to.ny && from.dy == to.dy)
        sens.by_pair[i] = StretchToSet(from, w, to, solved.pairs[i].pressure_MPa);
    }
  const double slope =
      Differentiate(solved, {"crank_angle_rad"}, options_.crank_slope_tolerance, true, &sens).front().rotation_rad;
  solved.slope_iterations = sens.iterations;
  if (warm)
    for (size_t i = 0; i < solved.pairs.size(); ++i) {
      auto it = warm->pairs.find(solved.pairs[i].roller);
      if (it == warm->pairs.end()) continue;
      it->second.sensitivity_grid = solved.pairs[i].grid;
      it->second.load_sensitivity = std::move(sens.by_pair[i]);
    }
  return slope;
}

LoadedTca LoadedTca::WithModification(double delta_position_mm, double delta_radius_mm) const {
  LoadedTca copy = *this;
  copy.drive_.delta_position_mm = delta_position_mm;
  copy.drive_.delta_radius_mm = delta_radius_mm;
  if (const auto issues = CheckDrive(copy.drive_); !issues.empty())
    throw std::invalid_argument(issues.front().message);
  return copy;
}

LoadedTca LoadedTca::WithDesign(const Drive& drive, const Crowning& crowning) const {
  LoadedTca copy = *this;
  copy.drive_ = drive;
  if (const auto issues = CheckDrive(copy.drive_); !issues.empty())
    throw std::invalid_argument(issues.front().message);
  copy.SetCrowning(crowning);
  return copy;
}

LoadedTca::Derivative LoadedTca::Differentiate(const MeshLoad& solved, const std::string& parameter) const {
  return Differentiate(solved, std::vector<std::string>{parameter}).front();
}

std::vector<LoadedTca::Derivative> LoadedTca::Differentiate(
    const MeshLoad& solved, const std::vector<std::string>& parameters) const {
  return Differentiate(solved, parameters, options_.sensitivity_tolerance, false);
}

std::vector<LoadedTca::Derivative> LoadedTca::Differentiate(const MeshLoad& solved,
                                                            const std::vector<std::string>& parameters,
                                                            double tol, bool rotation_only,
                                                            LoadSensitivities* load_sensitivities) const {
  using J = ceres::Jet<double, 1>;
  const size_t np = parameters.size();
  const size_t n = solved.pairs.size();
  // What each parameter changes: the torque (the moment balance), Δa/Δρ (arms, backlash, tooth
  // curvature, β0 through the unloaded TCA with a Jet), or the crowning drop per axial row.
  enum class Kind { kTorque, kGeometry, kCrowning, kFaceWidth };
  std::vector<Kind> kind(np);
  std::vector<std::vector<double>> dcrown(np);
  std::vector<std::map<int, PairGeometry<J>>> dgeom(np);
  std::vector<double> d_beta0(np, 0.0);
  for (size_t j = 0; j < np; ++j) {
    const std::string& parameter = parameters[j];
    if (parameter == "torque_Nmm") {
      kind[j] = Kind::kTorque;
    } else if (parameter == "delta_position_mm" || parameter == "delta_radius_mm" ||
               parameter == "crank_angle_rad" || parameter == "eccentricity_mm" ||
               parameter == "roller_position_radius_mm" || parameter == "roller_radius_mm") {
      kind[j] = Kind::kGeometry;
      DriveTpl<J> dj = drive_.cast<J>();
      J crank(solved.crank_angle_rad);
      (parameter == "delta_position_mm"           ? dj.delta_position_mm
       : parameter == "delta_radius_mm"           ? dj.delta_radius_mm
       : parameter == "eccentricity_mm"           ? dj.eccentricity_mm
       : parameter == "roller_position_radius_mm" ? dj.roller_position_radius_mm
       : parameter == "roller_radius_mm"          ? dj.roller_radius_mm
                                                  : crank).v[0] = 1.0;
      const UnloadedMesh<J> u = UnloadedTca<J>(dj, crank);
      d_beta0[j] = u.rotation.v[0];
      for (const auto& g : u.pairs) dgeom[j][g.roller] = g;
    } else {
      // ∂(crowning drop per axial row)/∂s through the drop formula with a ceres::Jet (exact). The
      // face width b also moves the rows (y = −b/2 + (iy + ½) b/q) and, when the logarithmic
      // crowning's effective length is the face width, L.
      const bool face = parameter == "face_width_mm";
      kind[j] = face ? Kind::kFaceWidth : Kind::kCrowning;
      J b(drive_.face_width_mm);
      J radius(crowning_.radius_mm), flat(crowning_.flat_length_mm), coefficient(crowning_.coefficient_mm),
          length(crowning_.effective_length_mm > 0 ? crowning_.effective_length_mm : drive_.face_width_mm),
          drop(crowning_.end_drop_mm);
      J* field = face                                 ? &b
                 : parameter == "coefficient_mm"      ? &coefficient
                 : parameter == "effective_length_mm" ? &length
                 : parameter == "end_drop_mm"         ? &drop
                 : parameter == "flat_length_mm"      ? &flat
                 : parameter == "radius_mm"           ? &radius
                                                      : nullptr;
      if (!field) throw std::invalid_argument("Differentiate: unknown parameter " + parameter);
      field->v[0] = 1.0;
      if (face && !(crowning_.effective_length_mm > 0)) length = b;
      const J dy = b / double(options_.axial_cells);
      dcrown[j].resize(options_.axial_cells);
      for (int iy = 0; iy < options_.axial_cells; ++iy)
        dcrown[j][iy] = CrowningDrop<J>(crowning_.type, radius, flat, coefficient, length,
                                        -0.5 * b + (iy + 0.5) * dy, drop).v[0];
      // The gap is shifted so that its lowest cell touches: the shift's derivative is the lowest
      // row's (the across-profile part does not depend on s).
      const int low = int(std::min_element(crown_.begin(), crown_.end()) - crown_.begin());
      const double d_low = dcrown[j][low];
      for (double& d : dcrown[j]) d -= d_low;
    }
  }
  std::vector<Derivative> out(np);
  for (size_t j = 0; j < np; ++j) out[j].parameter = parameters[j];
  std::vector<double> compliance(n);
  std::vector<contact::HalfSpaceSolver::Sensitivity> by_load(n);
  // gap_rate, d_arm, d_backlash, dload per parameter and pair.
  std::vector<std::vector<double>> gap_rate(np, std::vector<double>(n, 0.0)),
      d_arm(np, std::vector<double>(n, 0.0)), d_backlash(np, std::vector<double>(n, 0.0)),
      dload(np, std::vector<double>(n, 0.0));
  // The gap's rate dh/ds per parameter and pair on the pair's grid (kept for the adjoint products).
  std::vector<std::vector<std::vector<double>>> dgaps(np, std::vector<std::vector<double>>(n));
  bool converged = true;
  long iterations = 0;
  for (size_t i = 0; i < n; ++i) {
    const PairLoad& p = solved.pairs[i];
    if (p.pressure_MPa.size() != size_t(p.grid.cells()))
      throw std::invalid_argument("Differentiate: the solve must keep its pressures");
    const std::vector<double> zero(p.pressure_MPa.size(), 0.0);
    const std::vector<double>* start = nullptr;
    if (load_sensitivities && i < load_sensitivities->by_pair.size() && !load_sensitivities->by_pair[i].empty())
      start = &load_sensitivities->by_pair[i];
    by_load[i] = solver_->SensitivityForLoad(p.grid, p.pressure_MPa, zero, 1.0, e_star_, tol, start);
    iterations += by_load[i].iterations;
    if (load_sensitivities) {
      load_sensitivities->iterations += by_load[i].iterations;
      if (i < load_sensitivities->by_pair.size()) load_sensitivities->by_pair[i] = by_load[i].pressure_MPa;
    }
    compliance[i] = by_load[i].approach_mm;
    converged = converged && by_load[i].converged;
    for (size_t j = 0; j < np; ++j) {
      if (kind[j] == Kind::kTorque) continue;
      std::vector<double> dgap(p.pressure_MPa.size());
      if (kind[j] == Kind::kGeometry) {
        // The gap across the profile through the tooth's curvature (the roller's is unmodified),
        // shifted so that the lowest cell touches: its derivative at the lowest column.
        const PairGeometry<J>& g = dgeom[j].at(p.roller);
        d_arm[j][i] = g.arm_mm.v[0];
        d_backlash[j][i] = g.backlash.v[0];
        std::vector<double> across(p.grid.nx), d_across(p.grid.nx);
        for (int ix = 0; ix < p.grid.nx; ++ix) {
          const double x = p.grid.x_centre_mm(ix);
          const J sep = CircleSeparation(g.roller_curvature, x) + CircleSeparation(g.profile_curvature, x);
          across[ix] = sep.a;
          d_across[ix] = sep.v[0];
        }
        const int low = int(std::min_element(across.begin(), across.end()) - across.begin());
        for (int iy = 0; iy < p.grid.ny; ++iy)
          for (int ix = 0; ix < p.grid.nx; ++ix)
            dgap[size_t(iy) * p.grid.nx + ix] = d_across[ix] - d_across[low];
      } else {
        for (int iy = 0; iy < p.grid.ny; ++iy)
          for (int ix = 0; ix < p.grid.nx; ++ix) dgap[size_t(iy) * p.grid.nx + ix] = dcrown[j][iy];
        if (kind[j] == Kind::kFaceWidth) {
          // The rows stretch with b (dy = b/q): the displacement of the same pressures changes by
          // (∂K/∂b) p, which acts on the contact equations as a gap change, and the same force
          // now needs Σ p dA with a larger cell: at fixed load cA Σ dp = −F / b.
          const std::vector<double> du =
              contact::DisplacementRateByCellHeight(p.grid, p.pressure_MPa, e_star_);
          const double per_b = 1.0 / options_.axial_cells;
          for (size_t k = 0; k < dgap.size(); ++k) dgap[k] += du[k] * per_b;
          dload[j][i] = -p.load_N / drive_.face_width_mm;
        }
      }
      // Reciprocity: with K w = c·1 on the frozen set (w = dp/dW, the load sensitivity) and
      // K dp = dδ·1 − dh there with Σ dp = 0 at fixed load, wᵀK dp = c Σ dp = 0 gives
      // dδ = Σ w dh / Σ w: the approach's rate without a second solve (K symmetric).
      double wh = 0, ws = 0;
      for (size_t k = 0; k < dgap.size(); ++k) {
        wh += by_load[i].pressure_MPa[k] * dgap[k];
        ws += by_load[i].pressure_MPa[k];
      }
      // With cA Σ dp = dW (face width) the same product adds c·dW: dδ = c dW + Σ w dh / Σ w.
      gap_rate[j][i] = (ws != 0 ? wh / ws : 0.0) + compliance[i] * dload[j][i];
      if (!rotation_only) dgaps[j][i] = std::move(dgap);
    }
  }
  // δ_i = l_i (Δφc − φ_bl,i) and Σ l_i F_i = T differentiated, with dδ_i = c_i dF_i + a_i:
  // dF_i = (l_i dΔφc + r_i) / c_i, r_i = dl_i (Δφc − φ_bl,i) − l_i dφ_bl,i − a_i.
  const double deflection = solved.deflection_rad;
  std::vector<std::vector<double>> df(np, std::vector<double>(n, 0.0));
  for (size_t j = 0; j < np; ++j) {
    Derivative& d = out[j];
    d.converged = converged;
    const bool torque = kind[j] == Kind::kTorque;
    std::vector<double> r(n);
    double num = torque ? 1.0 : 0.0, den = 0;
    for (size_t i = 0; i < n; ++i) {
      const PairLoad& p = solved.pairs[i];
      const double l = p.arm_mm;
      r[i] = d_arm[j][i] * (deflection - p.backlash_rad) - l * d_backlash[j][i] - gap_rate[j][i];
      num -= d_arm[j][i] * p.load_N + l * r[i] / compliance[i];
      den += l * l / compliance[i];
    }
    d.deflection_rad = den > 0 ? num / den : 0.0;
    d.rotation_rad = d_beta0[j] + d.deflection_rad;
    d.unloaded_rotation_rad = d_beta0[j];
    for (size_t i = 0; i < n; ++i) df[j][i] = (solved.pairs[i].arm_mm * d.deflection_rad + r[i]) / compliance[i];
  }
  if (rotation_only) {
    for (Derivative& d : out) d.cg_iterations = iterations;
    return out;
  }
  // The pressures' derivatives by the adjoint: at fixed load the frozen set's pressure change is
  // dp = −M dh + dW·w, M the symmetric solution operator of K u − μ·1 = g, Σ u = 0 on the set
  // (the (1,1) block of the inverse of the symmetric bordered matrix), so a linear functional
  // gᵀdp = −(M g)ᵀ dh + dW·gᵀw: one solve per functional (the pair's peak cell; the end
  // distance through its row maxima), shared by every parameter, instead of one per parameter.
  bool any_gap = false;
  for (size_t j = 0; j < np; ++j) any_gap = any_gap || kind[j] != Kind::kTorque;
  auto adjoint = [&](const PairLoad& p, const std::vector<std::pair<size_t, double>>& g) {
    std::vector<double> functional(p.pressure_MPa.size(), 0.0);
    for (const auto& [k, c] : g) functional[k] += c;
    contact::HalfSpaceSolver::Sensitivity z =
        solver_->AdjointOfFunctional(p.grid, p.pressure_MPa, functional, e_star_, tol);
    converged = converged && z.converged;
    iterations += z.iterations;
    return std::move(z.pressure_MPa);
  };
  // gᵀ dp_j for each parameter j of pair i, z = M g (empty: no gap parameter).
  auto functional = [&](size_t i, const std::vector<std::pair<size_t, double>>& g,
                        const std::vector<double>& z, size_t j) {
    double gw = 0;
    for (const auto& [k, c] : g) gw += c * by_load[i].pressure_MPa[k];
    double v = df[j][i] * gw;
    if (kind[j] == Kind::kTorque) return v;
    const std::vector<double>& h = dgaps[j][i];
    double zh = 0;
    for (size_t k = 0; k < h.size(); ++k) zh += z[k] * h[k];
    return v - zh + dload[j][i] * gw;
  };
  std::vector<double> best(np, -1.0);
  int nearest = -1;
  double nearest_end = kInf;
  for (size_t i = 0; i < n; ++i) {
    const PairLoad& p = solved.pairs[i];
    const size_t peak = size_t(std::max_element(p.pressure_MPa.begin(), p.pressure_MPa.end()) -
                               p.pressure_MPa.begin());
    const std::vector<std::pair<size_t, double>> g_peak = {{peak, 1.0}};
    std::vector<double> z;
    if (any_gap) z = adjoint(p, g_peak);
    for (size_t j = 0; j < np; ++j) {
      Derivative& d = out[j];
      d.pair_load_N.push_back(df[j][i]);
      const double dp = functional(i, g_peak, z, j);
      d.pair_max_pressure_MPa.push_back(dp);
      if (p.max_pressure_MPa > best[j]) {
        best[j] = p.max_pressure_MPa;
        d.max_pressure_MPa = dp;
      }
    }
    if (options_.edge_margin && p.end_distance_mm < nearest_end) {
      nearest_end = p.end_distance_mm;
      nearest = int(i);
    }
  }
  if (nearest >= 0) {
    // The end distance of the pair nearest its face end (the solve's minimum), through the row
    // maxima with their cells frozen: a linear functional of dp with at most a few cells.
    const PairLoad& p = solved.pairs[size_t(nearest)];
    const std::vector<std::pair<size_t, double>> g = EndDistanceWeights(p.grid, p.pressure_MPa);
    std::vector<double> z;
    if (any_gap && !g.empty()) z = adjoint(p, g);
    for (size_t j = 0; j < np; ++j) {
      // Every length of the end distance (half face, row positions, dy) is proportional to b at
      // fixed row maxima: its partial derivative in b is its value over b.
      const double stretch = kind[j] == Kind::kFaceWidth ? p.end_distance_mm / drive_.face_width_mm : 0.0;
      out[j].end_distance_mm = (g.empty() ? 0.0 : functional(size_t(nearest), g, z, j)) + stretch;
    }
  }
  for (Derivative& d : out) {
    d.converged = converged;
    d.cg_iterations = iterations;
  }
  return out;
}

namespace {

// Crank angles on the same phase modulo one roller pitch within this [rad] share their state (see
// RunCycle in the header for the bound on what the match's error moves).
constexpr double kSymmetricPhaseTolerance = 1e-9;

// The roller shift m mod n1 (in [0, n1)) with φ_b = φ_a + m·2π/n1 within the tolerance, or -1.
int SymmetricShift(double phi_a, double phi_b, int rollers) {
  const double pitch = 2.0 * kPi / rollers;
  const double q = (phi_b - phi_a) / pitch;
  if (!(std::abs(q) < 1e9)) return -1;  // also NaN and infinite angles
  const double m = std::round(q);
  if (!(std::abs(phi_b - phi_a - m * pitch) <= kSymmetricPhaseTolerance)) return -1;
  const long r = long(m) % rollers;
  return int(r < 0 ? r + rollers : r);
}

// The state of `source` at the crank angle φ + m·2π/n1: roller i there is roller i + m here
// (turning the crank by one pitch moves each roller centre, in the disc frame, to where its
// predecessor was, one tooth pitch further round). Pairs in roller order, as a solve gives them.
MeshLoad SymmetricCopy(const MeshLoad& source, double crank_angle_rad, int source_index, int shift, int rollers) {
  MeshLoad m = source;
  m.crank_angle_rad = crank_angle_rad;
  m.symmetric_source = source_index;
  m.roller_shift = shift;
  for (PairLoad& p : m.pairs) p.roller = (p.roller + shift) % rollers;
  std::stable_sort(m.pairs.begin(), m.pairs.end(),
                   [](const PairLoad& a, const PairLoad& b) { return a.roller < b.roller; });
  m.iterations = 0;
  m.contact_solves = 0;
  m.solver_iterations = 0;
  m.slope_iterations = 0;
  return m;
}

// For a copy made by RunCycle, the position in `source.pairs` of each of its pairs, when `source`
// is its source (on its phase and its pairs, relabelled, the copy's bit for bit); else nullopt.
std::optional<std::vector<size_t>> SymmetricPairMap(const MeshLoad& copy, const MeshLoad& source, int rollers) {
  if (source.symmetric_source >= 0 || copy.pairs.size() != source.pairs.size()) return std::nullopt;
  const int shift = SymmetricShift(source.crank_angle_rad, copy.crank_angle_rad, rollers);
  const bool same_slope = copy.rotation_slope == source.rotation_slope ||
                          (std::isnan(copy.rotation_slope) && std::isnan(source.rotation_slope));
  if (shift < 0 || shift != copy.roller_shift || copy.rotation_rad != source.rotation_rad || !same_slope)
    return std::nullopt;
  std::vector<size_t> map(copy.pairs.size());
  for (size_t i = 0; i < copy.pairs.size(); ++i) {
    const PairLoad& c = copy.pairs[i];
    const int from = (c.roller - shift + rollers) % rollers;
    size_t j = 0;
    while (j < source.pairs.size() && source.pairs[j].roller != from) ++j;
    if (j == source.pairs.size()) return std::nullopt;
    const PairLoad& s = source.pairs[j];
    if (s.load_N != c.load_N || s.max_pressure_MPa != c.max_pressure_MPa || s.arm_mm != c.arm_mm ||
        s.pressure_MPa != c.pressure_MPa)
      return std::nullopt;
    map[i] = j;
  }
  return map;
}

}  // namespace

double SmoothPeakPressure(const CycleResult& cycle, double temperature_MPa) {
  double m = 0;
  for (const MeshLoad& mesh : cycle.meshes)
    for (const PairLoad& p : mesh.pairs) m = std::max(m, p.max_pressure_MPa);
  if (!(temperature_MPa > 0)) return m;
  double s = 0;
  for (const MeshLoad& mesh : cycle.meshes)
    for (const PairLoad& p : mesh.pairs) s += std::exp((p.max_pressure_MPa - m) / temperature_MPa);
  return s > 0 ? m + temperature_MPa * std::log(s) : m;
}

std::vector<CycleDerivative> DifferentiateCycle(const LoadedTca& tca, const CycleResult& cycle,
                                                const std::vector<std::string>& parameters,
                                                double temperature_MPa) {
  const size_t np = parameters.size(), na = cycle.meshes.size();
  std::vector<CycleDerivative> out(np);
  for (size_t j = 0; j < np; ++j) {
    out[j].parameter = parameters[j];
    out[j].rotation_rad.assign(na, 0.0);
    out[j].unloaded_rotation_rad.assign(na, 0.0);
    out[j].max_pressure_per_angle_MPa.assign(na, 0.0);
    out[j].end_distance_per_angle_mm.assign(na, 0.0);
    out[j].pair_load_N.assign(na, {});
    out[j].pair_max_pressure_MPa.assign(na, {});
  }
  // Soft-max weights over (angle, pair) peaks and the active terms of the exact maxima.
  const double smooth = SmoothPeakPressure(cycle, temperature_MPa);
  double peak = -1, load = -1;
  size_t peak_angle = 0, load_angle = 0, load_pair = 0;
  for (size_t k = 0; k < na; ++k) {
    const MeshLoad& m = cycle.meshes[k];
    if (m.max_pressure_MPa > peak) peak = m.max_pressure_MPa, peak_angle = k;
    for (size_t i = 0; i < m.pairs.size(); ++i)
      if (m.pairs[i].load_N > load) load = m.pairs[i].load_N, load_angle = k, load_pair = i;
  }
  size_t lte_hi = 0, lte_lo = 0, end_angle = 0;
  double end = kInf;
  for (size_t k = 0; k < na; ++k) {
    if (cycle.meshes[k].rotation_rad > cycle.meshes[lte_hi].rotation_rad) lte_hi = k;
    if (cycle.meshes[k].rotation_rad < cycle.meshes[lte_lo].rotation_rad) lte_lo = k;
    if (!cycle.meshes[k].pairs.empty() && cycle.meshes[k].end_distance_mm < end)
      end = cycle.meshes[k].end_distance_mm, end_angle = k;
  }
  long iterations = 0;
  // The derivatives of every differentiated mesh, for the copies of it (RunCycle's symmetry).
  std::vector<std::vector<LoadedTca::Derivative>> by_angle(na);
  const int rollers = tca.drive().rollers;
  for (size_t k = 0; k < na; ++k) {
    const MeshLoad& m = cycle.meshes[k];
    const int src = m.symmetric_source;
    const std::optional<std::vector<size_t>> map =
        src >= 0 && size_t(src) < k && !by_angle[src].empty()
            ? SymmetricPairMap(m, cycle.meshes[src], rollers)
            : std::nullopt;
    std::vector<LoadedTca::Derivative> d;
    if (map) {
      d = by_angle[src];  // the same state relabelled: the same derivatives, pairs in this order
      for (LoadedTca::Derivative& x : d) {
        std::vector<double> loads(map->size()), peaks(map->size());
        for (size_t i = 0; i < map->size(); ++i) {
          loads[i] = x.pair_load_N.at((*map)[i]);
          peaks[i] = x.pair_max_pressure_MPa.at((*map)[i]);
        }
        x.pair_load_N = std::move(loads);
        x.pair_max_pressure_MPa = std::move(peaks);
      }
    } else {
      d = tca.Differentiate(m, parameters);
      if (!d.empty()) iterations += d.front().cg_iterations;
      by_angle[k] = d;
    }
    for (size_t j = 0; j < np; ++j) {
      CycleDerivative& c = out[j];
      c.converged = c.converged && d[j].converged;
      c.rotation_rad[k] = d[j].rotation_rad;
      c.unloaded_rotation_rad[k] = d[j].unloaded_rotation_rad;
      c.max_pressure_per_angle_MPa[k] = d[j].max_pressure_MPa;
      c.end_distance_per_angle_mm[k] = d[j].end_distance_mm;
      c.pair_load_N[k] = d[j].pair_load_N;
      c.pair_max_pressure_MPa[k] = d[j].pair_max_pressure_MPa;
      for (size_t i = 0; i < m.pairs.size(); ++i) {
        const double w = temperature_MPa > 0
                             ? std::exp((m.pairs[i].max_pressure_MPa - smooth) / temperature_MPa)
                             : (k == peak_angle && m.pairs[i].max_pressure_MPa == peak ? 1.0 : 0.0);
        c.smooth_peak_MPa += w * d[j].pair_max_pressure_MPa[i];
      }
      if (k == peak_angle) c.max_pressure_MPa = d[j].max_pressure_MPa;
      if (k == load_angle && load_pair < d[j].pair_load_N.size()) c.max_pair_load_N = d[j].pair_load_N[load_pair];
      if (k == end_angle) c.end_distance_mm = d[j].end_distance_mm;
    }
  }
  for (CycleDerivative& c : out) c.cg_iterations = iterations;
  for (CycleDerivative& c : out)
    if (na > 0) c.lte_peak_to_peak_arcsec = (c.rotation_rad[lte_hi] - c.rotation_rad[lte_lo]) * kArcsecPerRad;
  return out;
}

std::vector<double> UniformCrankAngles(int steps, double span_rad) {
  std::vector<double> a(steps);
  for (int k = 0; k < steps; ++k) a[k] = span_rad * k / steps;
  return a;
}

CycleResult RunCycle(const LoadedTca& tca, double torque_Nmm, const std::vector<double>& angles,
                     const std::function<void(double)>& progress) {
  CycleResult r;
  const size_t n = angles.size();
  const Drive& drive = tca.drive();
  const bool reuse = tca.options().reuse_symmetric_angles && drive.rollers == drive.teeth + 1;
  LtcaWarmStart warm;  // local: the cycle depends on its arguments only
  std::vector<size_t> solved;  // the angles solved, in order (each on its own phase when reusing)
  for (size_t k = 0; k < n; ++k) {
    int source = -1, shift = 0;
    if (reuse)
      for (size_t j : solved)
        if ((shift = SymmetricShift(angles[j], angles[k], drive.rollers)) >= 0) {
          source = int(j);
          break;
        }
    if (source >= 0) {
      r.meshes.push_back(SymmetricCopy(r.meshes[source], angles[k], source, shift, drive.rollers));
    } else {
      r.meshes.push_back(tca.Solve(torque_Nmm, angles[k], &warm));
      solved.push_back(k);
    }
    if (progress) progress(double(k + 1) / n);
  }
  return SummariseCycle(drive, std::move(r.meshes), angles);
}

CycleResult SummariseCycle(const Drive& drive, std::vector<MeshLoad> meshes,
                           const std::vector<double>& angles) {
  CycleResult r;
  r.meshes = std::move(meshes);
  const size_t n = angles.size();
  if (r.meshes.size() != n) throw std::invalid_argument("SummariseCycle: one mesh per angle");
  r.lte_arcsec.resize(n);
  for (size_t k = 0; k < n; ++k) r.lte_arcsec[k] = r.meshes[k].rotation_rad * kArcsecPerRad;
  const double n2 = drive.teeth;
  bool slopes = true;
  for (const MeshLoad& m : r.meshes) slopes = slopes && std::isfinite(m.rotation_slope);
  // The disc turns by −φ/n2 − β (clockwise for a counter-clockwise crank): |dφ_out/dφ| =
  // 1/n2 + dβ/dφ, and the ratio is its inverse.
  if (slopes)
    for (size_t k = 0; k < n; ++k) r.gear_ratio.push_back(1.0 / (1.0 / n2 + r.meshes[k].rotation_slope));
  if (n > 0) {
    const auto [lo, hi] = std::minmax_element(r.lte_arcsec.begin(), r.lte_arcsec.end());
    r.lte_peak_to_peak_arcsec = *hi - *lo;
    double s = 0;
    for (double v : r.lte_arcsec) s += std::abs(v);
    r.lte_mean_abs_arcsec = s / n;
    if (slopes) {
      const auto [glo, ghi] = std::minmax_element(r.gear_ratio.begin(), r.gear_ratio.end());
      r.gear_ratio_peak_to_peak = *ghi - *glo;
    } else {
      r.gear_ratio_peak_to_peak = std::numeric_limits<double>::quiet_NaN();
    }
    r.edge_margin_mm = kInf;
    r.end_distance_mm = kInf;
  }
  for (size_t k = 0; k < n; ++k) {
    const MeshLoad& m = r.meshes[k];
    if (m.max_pressure_MPa > r.max_pressure_MPa) {
      r.max_pressure_MPa = m.max_pressure_MPa;
      r.max_pressure_index = int(k);
    }
    r.max_pairs_in_contact = std::max(r.max_pairs_in_contact, m.pairs_in_contact);
    for (const PairLoad& p : m.pairs) r.max_pair_load_N = std::max(r.max_pair_load_N, p.load_N);
    r.contact_solves += m.contact_solves;
    r.solver_iterations += m.solver_iterations;
    r.slope_iterations += m.slope_iterations;
    r.converged = r.converged && m.converged;
    if (!m.pairs.empty()) {
      r.edge_margin_mm = std::min(r.edge_margin_mm, m.edge_margin_mm);
      r.end_distance_mm = std::min(r.end_distance_mm, m.end_distance_mm);
    }
  }
  if (!std::isfinite(r.edge_margin_mm)) r.edge_margin_mm = 0;
  if (!std::isfinite(r.end_distance_mm)) r.end_distance_mm = 0;
  return r;
}

}  // namespace camopt::cycloid

// Dense reference solve of the half-space contact problem (cycloid paper eqs. 20–22 with the
// influence coefficients of eq. 21 in a full matrix), by an active-set method: solve the
// equalities on a trial contact set with a Cholesky factorisation, drop every cell with negative
// pressure, add every cell that overlaps, repeat. When it stops, p ≥ 0 on the set and no cell
// outside overlaps, which are the complementarity conditions: the answer is exact up to
// round-off. Cost O(N³) per change of the set: tests and the speed comparison only.
#include <Eigen/Cholesky>
#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "model/contact/half_space.h"
#include "model/contact/half_space_detail.h"
#include "model/contact/love.h"

namespace camopt::contact {
namespace {

// Full unit-modulus influence matrix, K(i, j) = u_i per unit p_j.
Eigen::MatrixXd InfluenceMatrix(const Grid& grid) {
  const int nx = grid.nx, ny = grid.ny;
  const int wx = 2 * nx - 1;
  std::vector<double> table(static_cast<size_t>(wx) * (2 * ny - 1));
  for (int oy = -(ny - 1); oy <= ny - 1; ++oy)
    for (int ox = -(nx - 1); ox <= nx - 1; ++ox)
      table[static_cast<size_t>(oy + ny - 1) * wx + (ox + nx - 1)] =
          LoveInfluence(ox * grid.dx, oy * grid.dy, 0.5 * grid.dx, 0.5 * grid.dy);
  const int n = grid.cells();
  Eigen::MatrixXd k(n, n);
  for (int i = 0; i < n; ++i) {
    const int ix = i % nx, iy = i / nx;
    for (int j = 0; j < n; ++j) {
      const int jx = j % nx, jy = j / nx;
      k(i, j) = table[static_cast<size_t>(iy - jy + ny - 1) * wx + (ix - jx + nx - 1)];
    }
  }
  return k;
}

// Active-set solve. With load control (load > 0) δ is unknown and Σ p·dx·dy = load; otherwise
// δ = approach is given.
// The full matrix of N² doubles: 4096 cells are 134 MB and a Cholesky of minutes; beyond that
// the reference is refused rather than exhausting the machine.
constexpr int kMaxDenseCells = 4096;

ContactSolution ActiveSet(const Grid& grid, const std::vector<double>& h, bool load_control,
                          double load, double approach, double e_star) {
  const int n = grid.cells();
  if (n > kMaxDenseCells) {
    std::ostringstream os;
    os << "dense contact reference: " << n << " cells exceed its limit of " << kMaxDenseCells
       << " (use HalfSpaceSolver)";
    throw std::invalid_argument(os.str());
  }
  const double area = grid.cell_area_mm2();
  const Eigen::MatrixXd k = InfluenceMatrix(grid);
  const Eigen::Map<const Eigen::VectorXd> hv(h.data(), n);
  const double h_min = hv.minCoeff();

  std::vector<char> active(n, 0);
  for (int i = 0; i < n; ++i) active[i] = load_control ? 1 : (h[i] < approach ? 1 : 0);

  Eigen::VectorXd p = Eigen::VectorXd::Zero(n);
  double delta = approach;
  const int max_iterations = 50 + 2 * n;
  ContactSolution s;
  int it = 0;
  for (it = 1; it <= max_iterations; ++it) {
    std::vector<int> set;
    for (int i = 0; i < n; ++i)
      if (active[i]) set.push_back(i);
    const int m = static_cast<int>(set.size());
    p.setZero();
    if (m > 0) {
      Eigen::MatrixXd ka(m, m);
      Eigen::VectorXd ha(m);
      for (int a = 0; a < m; ++a) {
        ha(a) = h[set[a]];
        for (int b = 0; b < m; ++b) ka(a, b) = k(set[a], set[b]);
      }
      const Eigen::LLT<Eigen::MatrixXd> llt(ka);
      const Eigen::VectorXd x = llt.solve(ha);
      if (load_control) {
        const Eigen::VectorXd y = llt.solve(Eigen::VectorXd::Ones(m));
        delta = (load / (area * e_star) + x.sum()) / y.sum();
        for (int a = 0; a < m; ++a) p(set[a]) = e_star * (delta * y(a) - x(a));
      } else {
        const Eigen::VectorXd y = llt.solve(Eigen::VectorXd::Constant(m, approach));
        for (int a = 0; a < m; ++a) p(set[a]) = e_star * (y(a) - x(a));
      }
    }
    bool changed = false;
    for (int a = 0; a < m; ++a)
      if (p(set[a]) < 0) {
        active[set[a]] = 0;
        p(set[a]) = 0;
        changed = true;
      }
    if (changed) continue;
    // No negative pressure: add every cell outside the set that overlaps.
    const Eigen::VectorXd u = k * p / e_star;
    const double scale = std::max(std::abs(delta - h_min), 1e-300);
    for (int i = 0; i < n; ++i)
      if (!active[i] && u(i) + h[i] < delta - 1e-12 * scale) {
        active[i] = 1;
        changed = true;
      }
    if (!changed) {
      s.converged = true;
      break;
    }
  }
  s.iterations = std::min(it, max_iterations);
  if (!s.converged) s.message = "dense active set did not settle";
  s.pressure_MPa.assign(p.data(), p.data() + n);
  for (double& v : s.pressure_MPa) v = std::max(v, 0.0);
  s.approach_mm = delta;
  detail::Summarise(grid, s);
  return s;
}

}  // namespace

ContactSolution SolveDenseForLoad(const Grid& grid, const std::vector<double>& gap_mm,
                                  double load_N, double e_star_MPa) {
  const char* where = "SolveDenseForLoad";
  detail::CheckGrid(grid, where);
  detail::CheckField(grid, gap_mm, "gap_mm", where);
  detail::CheckModulus(e_star_MPa, where);
  detail::CheckFinite(load_N, "load_N", where);
  if (load_N <= 0) {
    const double h_min = *std::min_element(gap_mm.begin(), gap_mm.end());
    return detail::Unloaded(grid, h_min, load_N < 0 ? "negative load treated as zero" : "");
  }
  return ActiveSet(grid, gap_mm, true, load_N, 0.0, e_star_MPa);
}

ContactSolution SolveDenseForApproach(const Grid& grid, const std::vector<double>& gap_mm,
                                      double approach_mm, double e_star_MPa) {
  const char* where = "SolveDenseForApproach";
  detail::CheckGrid(grid, where);
  detail::CheckField(grid, gap_mm, "gap_mm", where);
  detail::CheckModulus(e_star_MPa, where);
  detail::CheckFinite(approach_mm, "approach_mm", where);
  const double h_min = *std::min_element(gap_mm.begin(), gap_mm.end());
  if (!(approach_mm > h_min)) return detail::Unloaded(grid, approach_mm, "");
  return ActiveSet(grid, gap_mm, false, 0.0, approach_mm, e_star_MPa);
}

std::vector<double> DisplacementDense(const Grid& grid, const std::vector<double>& pressure_MPa,
                                      double e_star_MPa) {
  const char* where = "DisplacementDense";
  detail::CheckGrid(grid, where);
  detail::CheckField(grid, pressure_MPa, "pressure_MPa", where);
  detail::CheckModulus(e_star_MPa, where);
  const int n = grid.cells();
  std::vector<double> u(n, 0.0);
  for (int i = 0; i < n; ++i) {
    const double xi = grid.x_centre_mm(i % grid.nx), yi = grid.y_centre_mm(i / grid.nx);
    double sum = 0;
    for (int j = 0; j < n; ++j) {
      if (pressure_MPa[j] == 0) continue;
      const double xj = grid.x_centre_mm(j % grid.nx), yj = grid.y_centre_mm(j / grid.nx);
      sum += pressure_MPa[j] * LoveInfluence(xi - xj, yi - yj, 0.5 * grid.dx, 0.5 * grid.dy);
    }
    u[i] = sum / e_star_MPa;
  }
  return u;
}

}  // namespace camopt::contact

// Elastic half-space contact of two bodies with a gap field on a rectangular grid: Love's
// influence coefficients (cycloid paper eq. 21), non-negative pressure with a prescribed total
// load (eqs. 20 and 22). Solved by Polonsky–Keer conjugate gradients (preconditioned by default)
// with the convolution done by zero-padded FFT (DC-FFT) through FFTW; a dense active-set solve is
// kept as the reference.
//
// Units: mm, N, MPa (N/mm²). Grid cells are rectangles of size dx × dy (full sizes), cell
// (ix, iy) has centre (x0 + (ix + 0.5) dx, y0 + (iy + 0.5) dy); arrays are row-major, index
// iy * nx + ix. docs/contact.md explains the
// model, the cost and the cell-size dependence of edge peaks.
#pragma once

#include <array>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace camopt::contact {

struct Grid {
  int nx = 0, ny = 0;
  double dx = 0, dy = 0;  // cell sizes [mm]
  double x0 = 0, y0 = 0;  // lower-left corner [mm]

  int cells() const { return nx * ny; }
  double cell_area_mm2() const { return dx * dy; }
  double x_centre_mm(int ix) const { return x0 + (ix + 0.5) * dx; }
  double y_centre_mm(int iy) const { return y0 + (iy + 0.5) * dy; }
};

/// A grid of nx × ny cells covering [−half_x, half_x] × [−half_y, half_y] [mm].
Grid CenteredGrid(int nx, int ny, double half_x_mm, double half_y_mm);

struct SolverOptions {
  double tolerance = 1e-8;  // relative change / complementarity tolerance of the CG iteration
  int max_iterations = 2000;
  /// Added: plan the FFTs with FFTW_MEASURE instead of FFTW_ESTIMATE. Costs a one-off
  /// planning time per grid shape and process (FFTW keeps the wisdom); see docs/contact.md.
  bool measure_fft_plans = false;
  /// Added: precondition the CG by the inverse of the periodically continued kernel's circulant
  /// on the contact set (one more FFT pair per iteration, 2–4× fewer iterations at tolerances
  /// ≤ 1e-4). Off, the plain Polonsky–Keer iteration: cheaper for warm-started solves at a loose
  /// tolerance (1e-2), which stop after 2–3 iterations either way (docs/contact.md).
  bool precondition = true;
};

struct ContactSolution {
  std::vector<double> pressure_MPa;  // per cell, >= 0
  double approach_mm = 0;            // rigid-body approach δ of the two bodies
  double load_N = 0;                 // Σ p·dx·dy
  double max_pressure_MPa = 0;
  int cells_in_contact = 0;
  int iterations = 0;
  bool converged = false;
  std::string message;  // why not converged, or "" (no exception for a lost contact:
                        // zero load or no touching cell gives p = 0, approach from gap)

  // Added by the contact branch (beyond the agreed interface).
  /// The cell sizes every number of this solution was computed with. A peak pressure at a
  /// straight roller's edge depends on dy (it grows as the cells shrink, the exact solution is
  /// singular there): print it together with these.
  double dx_mm = 0, dy_mm = 0;
  double contact_area_mm2 = 0;  // cells_in_contact · dx · dy
  int max_pressure_cell = -1;   // index of the peak cell (iy * nx + ix), −1 when unloaded
  /// A loaded cell lies on the first or last column (x edge) / row (y edge) of the grid: the
  /// contact may be cut by the grid and the grid should be made larger in that direction. For a
  /// roller whose length is the grid's y extent, contact at the y edges is expected.
  bool contact_at_x_edge = false;
  bool contact_at_y_edge = false;
  bool contact_at_grid_edge = false;  // either of the two
};

/// Solves: Σ_j K_ij p_j = δ − h_i where p_i > 0, Σ K_ij p_j ≥ δ − h_i where p_i = 0, p ≥ 0,
/// with K from Love's rectangle influence coefficients (cycloid paper eq. 21), E* composite modulus.
/// Caches FFT plans and kernel spectra per (grid, E*) — construct once, call many times.
/// (The kernel is cached per grid shape and cell size, E* enters as a factor, so changing E*
/// costs nothing.) An instance is not thread-safe (it owns the work arrays): use one per thread;
/// FFTW plan creation is serialised by a process-wide mutex.
/// @throws std::invalid_argument for an empty grid, non-positive or non-finite cell sizes or
///         modulus, a gap of the wrong size or with a non-finite entry, a non-finite load/approach.
class HalfSpaceSolver {
 public:
  explicit HalfSpaceSolver(SolverOptions options = {});
  ~HalfSpaceSolver();
  HalfSpaceSolver(HalfSpaceSolver&&) noexcept;
  HalfSpaceSolver& operator=(HalfSpaceSolver&&) noexcept;
  HalfSpaceSolver(const HalfSpaceSolver&) = delete;
  HalfSpaceSolver& operator=(const HalfSpaceSolver&) = delete;

  /// Load-controlled: total load W given (cycloid paper eqs. 20, 22), approach δ found.
  /// load_N <= 0 gives p = 0 and δ = min(gap) (the bodies just touch).
  ContactSolution SolveForLoad(const Grid& grid, const std::vector<double>& gap_mm,
                               double load_N, double e_star_MPa);
  /// The same, starting the iteration from a previous pressure field on the same grid (any
  /// non-negative field; it is rescaled to the load). Saves iterations in outer loops where the
  /// gap changes little between calls. An unusable start (wrong size, all zero) is ignored.
  ContactSolution SolveForLoad(const Grid& grid, const std::vector<double>& gap_mm,
                               double load_N, double e_star_MPa,
                               const std::vector<double>& initial_pressure_MPa);
  /// Approach-controlled: δ given, the load follows (0 when nothing touches).
  ContactSolution SolveForApproach(const Grid& grid, const std::vector<double>& gap_mm,
                                   double approach_mm, double e_star_MPa);
  /// Surface displacement at every cell centre (the DC-FFT convolution), with the cached plans.
  std::vector<double> Displacement(const Grid& grid, const std::vector<double>& pressure_MPa,
                                   double e_star_MPa);

  /// Forward sensitivity at a converged load-controlled solution (implicit-function theorem): with the
  /// contact set C = {p > 0} of `pressure_MPa` frozen, solves K_CC dp_C − dδ·1 = −dh_C and
  /// cA·Σ dp_C = dW for one parameter s (dgap_mm = ∂h/∂s per cell, dload_N = dW/ds) by conjugate
  /// gradients on the zero-sum subspace of C (the same convolution), preconditioned by the inverse
  /// of the periodically continued kernel; stops at |residual| <= tolerance · |right-hand side|.
  /// Exact away from set changes. `initial_MPa` (optional, one value per cell, off-C values
  /// ignored): a starting guess of dp/ds, e.g. the same pair's sensitivity at a neighbouring state;
  /// brought to the load condition (scaled on C to cA·Σ dp_C = dW, or shifted when it cannot be)
  /// and used when its residual is below that of zero. The stopping test stays |b − A z| <=
  /// tolerance · |b|, so a start changes the cost, not the accuracy.
  struct Sensitivity {
    std::vector<double> pressure_MPa;  ///< dp/ds per cell (0 off C)
    double approach_mm = 0;            ///< dδ/ds
    int iterations = 0;
    bool converged = false;
  };
  Sensitivity SensitivityForLoad(const Grid& grid, const std::vector<double>& pressure_MPa,
                                 const std::vector<double>& dgap_mm, double dload_N,
                                 double e_star_MPa, double tolerance = 1e-10,
                                 const std::vector<double>* initial_MPa = nullptr);
  /// The adjoint of SensitivityForLoad at fixed load: with C frozen, solves K_CC u − μ·1 = g_C,
  /// Σ u_C = 0 (u = M g, M the symmetric solution operator of that bordered system). For every
  /// gap change dh the fixed-load pressure change dp of SensitivityForLoad(dh, dW = 0) has
  /// gᵀdp = −uᵀdh: one solve per linear functional of dp (a peak cell, an end distance) instead
  /// of one per parameter. Returns u in pressure_MPa; approach_mm is not computed (0).
  Sensitivity AdjointOfFunctional(const Grid& grid, const std::vector<double>& pressure_MPa,
                                  const std::vector<double>& functional, double e_star_MPa,
                                  double tolerance = 1e-10);

  const SolverOptions& options() const;

 private:
  Sensitivity FrozenSetSolve(const Grid& grid, const std::vector<double>& pressure_MPa,
                             const std::vector<double>& dgap_mm, double dload_N, double e_star_MPa,
                             double tolerance, const std::vector<double>* initial_MPa, bool approach);
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Dense reference (the same equations solved with an active-set method on the full matrix);
/// for tests and the speed comparison only. @throws std::invalid_argument beyond 4096 cells.
ContactSolution SolveDenseForLoad(const Grid& grid, const std::vector<double>& gap_mm,
                                  double load_N, double e_star_MPa);

/// Dense reference of the approach-controlled problem (tests only).
ContactSolution SolveDenseForApproach(const Grid& grid, const std::vector<double>& gap_mm,
                                      double approach_mm, double e_star_MPa);

/// The lock every FFTW planner call in the process must hold (FFTW's planner is not thread-safe;
/// executing a plan is). The solver takes it for its own planning; other FFTW users should too.
std::mutex& FftwPlannerMutex();

/// The contact convolutions' FFT plans: FFTW_PATIENT plans of the grid shapes a study uses most
/// (model/contact/fft_wisdom.inc, recorded by `camopt_fft_wisdom` on the reference machine) are
/// imported as FFTW wisdom before the first plan, and FFTW_ESTIMATE planning takes them where they
/// apply: the same plans in every run (results byte-identical run to run), 13–20 % less time per
/// cycloid LTCA cycle (docs/performance.md "FFT plans"). Where they do not apply (another CPU or
/// FFTW, another shape) FFTW drops them and plans by its estimate, as without them.
/// True when FFTW accepted the wisdom text.
bool FftWisdomImported();

/// FFTW_PATIENT plans of the convolutions of these grid shapes (cells nx, ny), from no wisdom, as
/// FFTW wisdom text: what model/contact/fft_wisdom.inc holds (`camopt_fft_wisdom`). Minutes for
/// large shapes; the process keeps the plans.
std::string PlanFftWisdom(const std::vector<std::array<int, 2>>& shapes);

/// Surface normal displacement at every cell centre from a pressure field (the convolution).
std::vector<double> Displacement(const Grid& grid, const std::vector<double>& pressure_MPa,
                                 double e_star_MPa);

/// Rate of the surface displacement at every cell centre with respect to the cell height dy at
/// fixed cell pressures [mm per mm]: the grid stretched along y (cell centres at y0 + (iy + ½) dy
/// with y0 = −ny·dy/2, each cell dy high), as when a face width divided into a fixed number of
/// rows changes. Exact: Love's influence coefficient (love.h) differentiated with a ceres::Jet,
/// summed over the loaded cells (O(cells × loaded cells)); the kernel's derivative per offset is
/// computed once per grid shape and cell size (a small per-thread cache).
std::vector<double> DisplacementRateByCellHeight(const Grid& grid, const std::vector<double>& pressure_MPa,
                                                 double e_star_MPa);

/// Dense form of the same displacement (direct double sum over the cells; tests only).
std::vector<double> DisplacementDense(const Grid& grid, const std::vector<double>& pressure_MPa,
                                      double e_star_MPa);

}  // namespace camopt::contact

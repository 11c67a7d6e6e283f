// Half-space contact by Polonsky–Keer conjugate gradients (Polonsky & Keer 1999) with the
// influence-coefficient convolution done by zero-padded FFT (DC-FFT, Liu, Wang & Liu 2000).
// Influence coefficients: Love's rectangle solution, cycloid paper eq. (21) (love.h).
#include "model/contact/half_space.h"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <map>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "model/contact/half_space_detail.h"
#include "model/contact/love.h"

namespace camopt::contact {

// ---------------------------------------------------------------------------------------------
// Shared helpers.

namespace detail {

void CheckGrid(const Grid& grid, const char* where) {
  std::ostringstream os;
  if (grid.nx < 1 || grid.ny < 1) {
    os << where << ": grid must have at least one cell in each direction, got nx = " << grid.nx
       << ", ny = " << grid.ny;
  } else if (!(std::isfinite(grid.dx) && std::isfinite(grid.dy) && grid.dx > 0 && grid.dy > 0)) {
    os << where << ": cell sizes must be positive and finite, got dx = " << grid.dx
       << " mm, dy = " << grid.dy << " mm";
  } else if (!(std::isfinite(grid.x0) && std::isfinite(grid.y0))) {
    os << where << ": grid corner must be finite";
  } else if (static_cast<long long>(grid.nx) * grid.ny > (1LL << 26)) {
    os << where << ": grid of " << grid.nx << " x " << grid.ny << " cells is too large";
  } else {
    return;
  }
  throw std::invalid_argument(os.str());
}

void CheckField(const Grid& grid, const std::vector<double>& field, const char* name,
                const char* where) {
  std::ostringstream os;
  if (field.size() != static_cast<size_t>(grid.cells())) {
    os << where << ": " << name << " has " << field.size() << " entries, the grid has "
       << grid.cells() << " cells";
    throw std::invalid_argument(os.str());
  }
  for (size_t i = 0; i < field.size(); ++i) {
    if (!std::isfinite(field[i])) {
      os << where << ": " << name << "[" << i << "] is not finite";
      throw std::invalid_argument(os.str());
    }
  }
}

void CheckModulus(double e_star_MPa, const char* where) {
  if (!(std::isfinite(e_star_MPa) && e_star_MPa > 0)) {
    std::ostringstream os;
    os << where << ": composite modulus E* must be positive and finite, got " << e_star_MPa
       << " MPa";
    throw std::invalid_argument(os.str());
  }
}

void CheckFinite(double value, const char* name, const char* where) {
  if (!std::isfinite(value)) {
    std::ostringstream os;
    os << where << ": " << name << " must be finite, got " << value;
    throw std::invalid_argument(os.str());
  }
}

void Summarise(const Grid& grid, ContactSolution& s) {
  s.dx_mm = grid.dx;
  s.dy_mm = grid.dy;
  double sum = 0;
  s.max_pressure_MPa = 0;
  s.max_pressure_cell = -1;
  s.cells_in_contact = 0;
  s.contact_at_grid_edge = false;
  for (int iy = 0; iy < grid.ny; ++iy) {
    for (int ix = 0; ix < grid.nx; ++ix) {
      const int i = iy * grid.nx + ix;
      const double p = s.pressure_MPa[i];
      if (p <= 0) continue;
      sum += p;
      ++s.cells_in_contact;
      if (p > s.max_pressure_MPa) {
        s.max_pressure_MPa = p;
        s.max_pressure_cell = i;
      }
      if (ix == 0 || iy == 0 || ix == grid.nx - 1 || iy == grid.ny - 1)
        s.contact_at_grid_edge = true;
    }
  }
  s.load_N = sum * grid.cell_area_mm2();
  s.contact_area_mm2 = s.cells_in_contact * grid.cell_area_mm2();
}

ContactSolution Unloaded(const Grid& grid, double approach_mm, std::string message) {
  ContactSolution s;
  s.pressure_MPa.assign(grid.cells(), 0.0);
  s.approach_mm = approach_mm;
  s.converged = true;
  s.message = std::move(message);
  Summarise(grid, s);
  return s;
}

}  // namespace detail

Grid CenteredGrid(int nx, int ny, double half_x_mm, double half_y_mm) {
  Grid g;
  g.nx = nx;
  g.ny = ny;
  g.dx = nx > 0 ? 2 * half_x_mm / nx : 0;
  g.dy = ny > 0 ? 2 * half_y_mm / ny : 0;
  g.x0 = -half_x_mm;
  g.y0 = -half_y_mm;
  detail::CheckGrid(g, "CenteredGrid");
  return g;
}

// ---------------------------------------------------------------------------------------------
// DC-FFT convolution for one grid shape.

namespace {

// FFTW's planner is not thread-safe; executing a plan is. All planning and plan destruction go
// through this one lock.
std::mutex& PlannerMutex() {
  static std::mutex m;
  return m;
}

using Complex = std::complex<double>;

// Linear (non-periodic) convolution of an nx × ny field with a kernel of offsets
// −(n−1) … (n−1), by FFT on a 2nx × 2ny zero-padded array (DC-FFT). Plans use FFTW_ESTIMATE:
// planning costs microseconds and the transform of these sizes is within a few per cent of a
// FFTW_MEASURE plan (see docs/performance.md), while MEASURE would cost tens of milliseconds per
// new grid shape and overwrite the arrays while planning.
class FftConvolver {
 public:
  FftConvolver(int nx, int ny) : nx_(nx), ny_(ny), mx_(2 * nx), my_(2 * ny), mxc_(nx + 1) {
    real_ = fftw_alloc_real(static_cast<size_t>(mx_) * my_);
    spec_ = fftw_alloc_complex(static_cast<size_t>(mxc_) * my_);
    if (real_ == nullptr || spec_ == nullptr) {
      Free();
      throw std::bad_alloc();
    }
    std::lock_guard<std::mutex> lock(PlannerMutex());
    forward_ = fftw_plan_dft_r2c_2d(my_, mx_, real_, spec_, FFTW_ESTIMATE);
    inverse_ = fftw_plan_dft_c2r_2d(my_, mx_, spec_, real_, FFTW_ESTIMATE);
  }
  ~FftConvolver() { Free(); }
  FftConvolver(const FftConvolver&) = delete;
  FftConvolver& operator=(const FftConvolver&) = delete;

  // Spectrum of the unit-modulus Love kernel for cells dx × dy, divided by the FFT size so
  // that Apply needs no further normalisation.
  std::vector<Complex> KernelSpectrum(double dx, double dy) {
    const double xi = 0.5 * dx, eta = 0.5 * dy;
    for (int jy = 0; jy < my_; ++jy) {
      // Offsets 0 … n−1 in the first half, −(n−1) … −1 in the second; index n is never used.
      const int oy = jy < ny_ ? jy : (jy > ny_ ? jy - my_ : 0);
      for (int jx = 0; jx < mx_; ++jx) {
        const int ox = jx < nx_ ? jx : (jx > nx_ ? jx - mx_ : 0);
        const bool unused = jy == ny_ || jx == nx_;
        real_[static_cast<size_t>(jy) * mx_ + jx] =
            unused ? 0.0 : LoveInfluence(ox * dx, oy * dy, xi, eta);
      }
    }
    fftw_execute(forward_);
    const size_t n = static_cast<size_t>(mxc_) * my_;
    std::vector<Complex> k(n);
    const double scale = 1.0 / (static_cast<double>(mx_) * my_);
    const Complex* s = reinterpret_cast<const Complex*>(spec_);
    for (size_t i = 0; i < n; ++i) k[i] = s[i] * scale;
    return k;
  }

  // out = scale · (kernel ∗ in) on the nx × ny grid.
  void Apply(const std::vector<Complex>& kernel, const double* in, double* out, double scale) {
    std::fill(real_, real_ + static_cast<size_t>(mx_) * my_, 0.0);
    for (int iy = 0; iy < ny_; ++iy)
      std::copy(in + static_cast<size_t>(iy) * nx_, in + static_cast<size_t>(iy + 1) * nx_,
                real_ + static_cast<size_t>(iy) * mx_);
    fftw_execute(forward_);
    Complex* s = reinterpret_cast<Complex*>(spec_);
    const size_t n = static_cast<size_t>(mxc_) * my_;
    for (size_t i = 0; i < n; ++i) s[i] *= kernel[i];
    fftw_execute(inverse_);
    for (int iy = 0; iy < ny_; ++iy)
      for (int ix = 0; ix < nx_; ++ix)
        out[static_cast<size_t>(iy) * nx_ + ix] = scale * real_[static_cast<size_t>(iy) * mx_ + ix];
  }

 private:
  void Free() {
    std::lock_guard<std::mutex> lock(PlannerMutex());
    if (forward_ != nullptr) fftw_destroy_plan(forward_);
    if (inverse_ != nullptr) fftw_destroy_plan(inverse_);
    forward_ = inverse_ = nullptr;
    if (real_ != nullptr) fftw_free(real_);
    if (spec_ != nullptr) fftw_free(spec_);
    real_ = nullptr;
    spec_ = nullptr;
  }

  int nx_, ny_, mx_, my_, mxc_;
  double* real_ = nullptr;
  fftw_complex* spec_ = nullptr;
  fftw_plan forward_ = nullptr, inverse_ = nullptr;
};

// Caches are bounded: beyond these many entries they are cleared (a study uses a few shapes).
constexpr size_t kMaxConvolvers = 8;
constexpr size_t kMaxKernels = 64;

}  // namespace

// ---------------------------------------------------------------------------------------------
// The solver.

struct HalfSpaceSolver::Impl {
  SolverOptions options;
  std::map<std::pair<int, int>, std::unique_ptr<FftConvolver>> convolvers;
  std::map<std::tuple<int, int, double, double>, std::vector<Complex>> kernels;
  std::vector<double> p, p_old, u, g, t, r;  // work arrays

  explicit Impl(SolverOptions o) : options(o) {}

  FftConvolver& Convolver(const Grid& grid) {
    const auto key = std::make_pair(grid.nx, grid.ny);
    auto it = convolvers.find(key);
    if (it == convolvers.end()) {
      if (convolvers.size() >= kMaxConvolvers) {
        convolvers.clear();
        kernels.clear();
      }
      it = convolvers.emplace(key, std::make_unique<FftConvolver>(grid.nx, grid.ny)).first;
    }
    return *it->second;
  }

  const std::vector<Complex>& Kernel(const Grid& grid, FftConvolver& conv) {
    const auto key = std::make_tuple(grid.nx, grid.ny, grid.dx, grid.dy);
    auto it = kernels.find(key);
    if (it == kernels.end()) {
      if (kernels.size() >= kMaxKernels) kernels.clear();
      it = kernels.emplace(key, conv.KernelSpectrum(grid.dx, grid.dy)).first;
    }
    return it->second;
  }

  ContactSolution SolveLoad(const Grid& grid, const std::vector<double>& h, double load,
                            double e_star, const std::vector<double>* start);
  ContactSolution SolveApproach(const Grid& grid, const std::vector<double>& h, double approach,
                                double e_star);
};

HalfSpaceSolver::HalfSpaceSolver(SolverOptions options)
    : impl_(std::make_unique<Impl>(options)) {}
HalfSpaceSolver::~HalfSpaceSolver() = default;
HalfSpaceSolver::HalfSpaceSolver(HalfSpaceSolver&&) noexcept = default;
HalfSpaceSolver& HalfSpaceSolver::operator=(HalfSpaceSolver&&) noexcept = default;
const SolverOptions& HalfSpaceSolver::options() const { return impl_->options; }

namespace {

bool UsableStart(const std::vector<double>* start, size_t n) {
  if (start == nullptr || start->size() != n) return false;
  double sum = 0;
  for (double v : *start) {
    if (!std::isfinite(v) || v < 0) return false;
    sum += v;
  }
  return sum > 0 && std::isfinite(sum);
}

}  // namespace

// Polonsky & Keer (1999), load control. The gap is g = u + h − ḡ, ḡ its mean over the cells in
// contact I_c = {p > 0}; then ḡ is the approach δ. Conjugate directions on I_c, a step τ by exact
// line search, projection onto p ≥ 0, cells with p = 0 and g < 0 (overlap) re-enter with
// p = −τ g (and the conjugacy is reset), and p is rescaled to the load (eq. 22).
ContactSolution HalfSpaceSolver::Impl::SolveLoad(const Grid& grid, const std::vector<double>& h,
                                                 double load, double e_star,
                                                 const std::vector<double>* start) {
  const char* where = "HalfSpaceSolver::SolveForLoad";
  detail::CheckGrid(grid, where);
  detail::CheckField(grid, h, "gap_mm", where);
  detail::CheckModulus(e_star, where);
  detail::CheckFinite(load, "load_N", where);
  const double h_min = *std::min_element(h.begin(), h.end());
  if (load <= 0)
    return detail::Unloaded(grid, h_min, load < 0 ? "negative load treated as zero" : "");

  const size_t n = static_cast<size_t>(grid.cells());
  const double area = grid.cell_area_mm2();
  FftConvolver& conv = Convolver(grid);
  const std::vector<Complex>& kernel = Kernel(grid, conv);
  const double inv_e = 1.0 / e_star;
  auto convolve = [&](const std::vector<double>& in, std::vector<double>& out) {
    conv.Apply(kernel, in.data(), out.data(), inv_e);
  };
  // Fallback step when the line search is degenerate (a single cell in contact gives G = 0):
  // the pressure change that moves one cell's own surface by one unit.
  const double tau_self = e_star / LoveInfluence(0.0, 0.0, 0.5 * grid.dx, 0.5 * grid.dy);

  const double p_mean = load / (area * static_cast<double>(n));
  p.assign(n, p_mean);
  if (UsableStart(start, n)) {
    double sum = 0;
    for (double v : *start) sum += v;
    const double f = load / (area * sum);
    for (size_t i = 0; i < n; ++i) p[i] = (*start)[i] * f;
  }
  p_old.assign(n, 0.0);
  u.assign(n, 0.0);
  g.assign(n, 0.0);
  t.assign(n, 0.0);
  r.assign(n, 0.0);

  ContactSolution s;
  double g_old = 1.0;
  bool conjugate = false;
  int it = 0;
  for (it = 1; it <= options.max_iterations; ++it) {
    convolve(p, u);
    double sum_g = 0;
    size_t nc = 0;
    for (size_t i = 0; i < n; ++i)
      if (p[i] > 0) {
        sum_g += u[i] + h[i];
        ++nc;
      }
    const double g_bar = nc > 0 ? sum_g / static_cast<double>(nc) : h_min;
    double big_g = 0;
    for (size_t i = 0; i < n; ++i) {
      g[i] = u[i] + h[i] - g_bar;
      if (p[i] > 0) big_g += g[i] * g[i];
    }
    const double beta = (conjugate && g_old > 0) ? big_g / g_old : 0.0;
    for (size_t i = 0; i < n; ++i) t[i] = p[i] > 0 ? g[i] + beta * t[i] : 0.0;
    g_old = big_g;

    convolve(t, r);
    double sum_r = 0;
    for (size_t i = 0; i < n; ++i)
      if (p[i] > 0) sum_r += r[i];
    const double r_bar = nc > 0 ? sum_r / static_cast<double>(nc) : 0.0;
    double num = 0, den = 0;
    for (size_t i = 0; i < n; ++i)
      if (p[i] > 0) {
        num += g[i] * t[i];
        den += (r[i] - r_bar) * t[i];
      }
    const double tau = (den > 0 && std::isfinite(num / den)) ? num / den : tau_self;

    p_old = p;
    for (size_t i = 0; i < n; ++i)
      if (p[i] > 0) p[i] = std::max(p[i] - tau * t[i], 0.0);
    bool overlap = false;
    for (size_t i = 0; i < n; ++i)
      if (p[i] == 0 && g[i] < 0) {
        p[i] = -tau * g[i];
        overlap = true;
      }
    conjugate = !overlap;

    double sum_p = 0;
    for (double v : p) sum_p += v;
    if (!(sum_p > 0) || !std::isfinite(sum_p)) {  // cannot happen in exact arithmetic; restart
      p.assign(n, p_mean);
      conjugate = false;
      continue;
    }
    const double f = load / (area * sum_p);
    double change = 0;
    for (size_t i = 0; i < n; ++i) {
      p[i] *= f;
      change += std::abs(p[i] - p_old[i]);
    }
    if (change * area / load < options.tolerance) {
      s.converged = true;
      break;
    }
  }
  s.iterations = std::min(it, options.max_iterations);
  if (!s.converged) {
    std::ostringstream os;
    os << "not converged after " << options.max_iterations << " iterations";
    s.message = os.str();
  }

  // The approach from the final pressure: the mean of u + h over the contact.
  convolve(p, u);
  double sum_g = 0;
  size_t nc = 0;
  for (size_t i = 0; i < n; ++i)
    if (p[i] > 0) {
      sum_g += u[i] + h[i];
      ++nc;
    }
  s.approach_mm = nc > 0 ? sum_g / static_cast<double>(nc) : h_min;
  s.pressure_MPa = p;
  detail::Summarise(grid, s);
  return s;
}

// Polonsky & Keer (1999) for a prescribed approach δ: the same iteration on g = u + h − δ without
// the mean shift and without the load rescaling (it minimises ½pᵀKp + pᵀ(h − δ) over p ≥ 0).
ContactSolution HalfSpaceSolver::Impl::SolveApproach(const Grid& grid,
                                                     const std::vector<double>& h,
                                                     double approach, double e_star) {
  const char* where = "HalfSpaceSolver::SolveForApproach";
  detail::CheckGrid(grid, where);
  detail::CheckField(grid, h, "gap_mm", where);
  detail::CheckModulus(e_star, where);
  detail::CheckFinite(approach, "approach_mm", where);
  const size_t n = static_cast<size_t>(grid.cells());
  // Start from the rigid overlap, scaled by the best single factor (exact line search).
  p.assign(n, 0.0);
  bool any = false;
  for (size_t i = 0; i < n; ++i)
    if (approach - h[i] > 0) {
      p[i] = approach - h[i];
      any = true;
    }
  if (!any) return detail::Unloaded(grid, approach, "");

  FftConvolver& conv = Convolver(grid);
  const std::vector<Complex>& kernel = Kernel(grid, conv);
  const double inv_e = 1.0 / e_star;
  auto convolve = [&](const std::vector<double>& in, std::vector<double>& out) {
    conv.Apply(kernel, in.data(), out.data(), inv_e);
  };
  const double tau_self = e_star / LoveInfluence(0.0, 0.0, 0.5 * grid.dx, 0.5 * grid.dy);
  p_old.assign(n, 0.0);
  u.assign(n, 0.0);
  g.assign(n, 0.0);
  t.assign(n, 0.0);
  r.assign(n, 0.0);
  {
    convolve(p, u);
    double a = 0, b = 0;
    for (size_t i = 0; i < n; ++i) {
      a += p[i] * (approach - h[i]);
      b += p[i] * u[i];
    }
    const double f = (b > 0 && std::isfinite(a / b)) ? a / b : tau_self;
    for (double& v : p) v *= f;
  }

  ContactSolution s;
  double g_old = 1.0;
  bool conjugate = false;
  int it = 0;
  for (it = 1; it <= options.max_iterations; ++it) {
    convolve(p, u);
    double big_g = 0;
    for (size_t i = 0; i < n; ++i) {
      g[i] = u[i] + h[i] - approach;
      if (p[i] > 0) big_g += g[i] * g[i];
    }
    const double beta = (conjugate && g_old > 0) ? big_g / g_old : 0.0;
    for (size_t i = 0; i < n; ++i) t[i] = p[i] > 0 ? g[i] + beta * t[i] : 0.0;
    g_old = big_g;
    convolve(t, r);
    double num = 0, den = 0;
    for (size_t i = 0; i < n; ++i)
      if (p[i] > 0) {
        num += g[i] * t[i];
        den += r[i] * t[i];
      }
    const double tau = (den > 0 && std::isfinite(num / den)) ? num / den : tau_self;
    p_old = p;
    for (size_t i = 0; i < n; ++i)
      if (p[i] > 0) p[i] = std::max(p[i] - tau * t[i], 0.0);
    bool overlap = false;
    for (size_t i = 0; i < n; ++i)
      if (p[i] == 0 && g[i] < 0) {
        p[i] = -tau * g[i];
        overlap = true;
      }
    conjugate = !overlap;
    double change = 0, sum_p = 0;
    for (size_t i = 0; i < n; ++i) {
      change += std::abs(p[i] - p_old[i]);
      sum_p += p[i];
    }
    if (sum_p > 0 && change / sum_p < options.tolerance) {
      s.converged = true;
      break;
    }
  }
  s.iterations = std::min(it, options.max_iterations);
  if (!s.converged) {
    std::ostringstream os;
    os << "not converged after " << options.max_iterations << " iterations";
    s.message = os.str();
  }
  s.approach_mm = approach;
  s.pressure_MPa = p;
  detail::Summarise(grid, s);
  return s;
}

ContactSolution HalfSpaceSolver::SolveForLoad(const Grid& grid, const std::vector<double>& gap_mm,
                                              double load_N, double e_star_MPa) {
  return impl_->SolveLoad(grid, gap_mm, load_N, e_star_MPa, nullptr);
}

ContactSolution HalfSpaceSolver::SolveForLoad(const Grid& grid, const std::vector<double>& gap_mm,
                                              double load_N, double e_star_MPa,
                                              const std::vector<double>& initial_pressure_MPa) {
  return impl_->SolveLoad(grid, gap_mm, load_N, e_star_MPa, &initial_pressure_MPa);
}

ContactSolution HalfSpaceSolver::SolveForApproach(const Grid& grid,
                                                  const std::vector<double>& gap_mm,
                                                  double approach_mm, double e_star_MPa) {
  return impl_->SolveApproach(grid, gap_mm, approach_mm, e_star_MPa);
}

std::vector<double> HalfSpaceSolver::Displacement(const Grid& grid,
                                                  const std::vector<double>& pressure_MPa,
                                                  double e_star_MPa) {
  const char* where = "HalfSpaceSolver::Displacement";
  detail::CheckGrid(grid, where);
  detail::CheckField(grid, pressure_MPa, "pressure_MPa", where);
  detail::CheckModulus(e_star_MPa, where);
  FftConvolver& conv = impl_->Convolver(grid);
  const std::vector<Complex>& kernel = impl_->Kernel(grid, conv);
  std::vector<double> out(grid.cells());
  conv.Apply(kernel, pressure_MPa.data(), out.data(), 1.0 / e_star_MPa);
  return out;
}

std::vector<double> Displacement(const Grid& grid, const std::vector<double>& pressure_MPa,
                                 double e_star_MPa) {
  HalfSpaceSolver solver;
  return solver.Displacement(grid, pressure_MPa, e_star_MPa);
}

}  // namespace camopt::contact

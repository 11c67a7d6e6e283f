// Half-space contact by Polonsky–Keer conjugate gradients (Polonsky & Keer 1999), preconditioned
// by the inverse of the periodically continued kernel's circulant, with the
// influence-coefficient convolution done by zero-padded FFT (DC-FFT, Liu, Wang & Liu 2000).
// Influence coefficients: Love's rectangle solution, cycloid paper eq. (21) (love.h).
#include "model/contact/half_space.h"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstring>
#include <map>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <utility>

#include <ceres/jet.h>

#include "model/contact/half_space_detail.h"
#include "model/contact/love.h"

namespace camopt::contact {

// ---------------------------------------------------------------------------------------------
// The two element-wise loops of the convolution, compiled twice: for the x86-64 baseline (SSE2)
// and with AVX2 where the processor has it (chosen at run time). Both are element-wise products
// and sums without fused multiply-adds (AVX2 does not enable FMA), so both give the same bits.
namespace kernels {

// out[i] += scale · Σ_j c_j K(i − j) over `count` listed cells j of an nx × ny grid, K from the
// offset table (row stride wx = 2nx − 1, offset (0, 0) at (ny − 1, nx − 1)).
template <int kTag>
inline void AddSparseBody(const double* table, int nx, int ny, const std::pair<int, double>* c, size_t count,
                          double* out, double scale) {
  const int wx = 2 * nx - 1;
  for (size_t k = 0; k < count; ++k) {
    const int j = c[k].first, jx = j % nx, jy = j / nx;
    const double w = scale * c[k].second;
    for (int iy = 0; iy < ny; ++iy) {
      const double* trow = table + static_cast<size_t>(iy - jy + ny - 1) * wx + (nx - 1 - jx);
      double* orow = out + static_cast<size_t>(iy) * nx;
      for (int ix = 0; ix < nx; ++ix) orow[ix] += w * trow[ix];
    }
  }
}
// s ← s · k for n complex numbers stored as (re, im) pairs: (a·c − b·d, a·d + b·c).
template <int kTag>
inline void ComplexProductBody(double* s, const double* k, size_t n) {
  for (size_t i = 0; i < n; ++i) {
    const double a = s[2 * i], b = s[2 * i + 1], c = k[2 * i], d = k[2 * i + 1];
    s[2 * i] = a * c - b * d;
    s[2 * i + 1] = a * d + b * c;
  }
}

#if defined(__x86_64__) && defined(__GNUC__)
__attribute__((target("avx2"))) void AddSparseAvx2(const double* table, int nx, int ny,
                                                   const std::pair<int, double>* c, size_t count, double* out,
                                                   double scale) {
  AddSparseBody<1>(table, nx, ny, c, count, out, scale);
}
__attribute__((target("avx2"))) void ComplexProductAvx2(double* s, const double* k, size_t n) {
  ComplexProductBody<1>(s, k, n);
}
bool HasAvx2() {
  static const bool has = __builtin_cpu_supports("avx2");
  return has;
}
#endif

void AddSparse(const double* table, int nx, int ny, const std::pair<int, double>* c, size_t count, double* out,
               double scale) {
#if defined(__x86_64__) && defined(__GNUC__)
  if (HasAvx2()) return AddSparseAvx2(table, nx, ny, c, count, out, scale);
#endif
  AddSparseBody<0>(table, nx, ny, c, count, out, scale);
}

void ComplexProduct(double* s, const double* k, size_t n) {
#if defined(__x86_64__) && defined(__GNUC__)
  if (HasAvx2()) return ComplexProductAvx2(s, k, n);
#endif
  ComplexProductBody<0>(s, k, n);
}

}  // namespace kernels

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
  s.contact_at_x_edge = s.contact_at_y_edge = false;
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
      if (ix == 0 || ix == grid.nx - 1) s.contact_at_x_edge = true;
      if (iy == 0 || iy == grid.ny - 1) s.contact_at_y_edge = true;
    }
  }
  s.contact_at_grid_edge = s.contact_at_x_edge || s.contact_at_y_edge;
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

std::mutex& FftwPlannerMutex() {
  static std::mutex m;
  return m;
}

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
// through one lock (FftwPlannerMutex in the header).
std::mutex& PlannerMutex() { return FftwPlannerMutex(); }

// The recorded plans (FftWisdomImported in the header), generated by camopt_fft_wisdom.
constexpr const char kFftWisdom[] =
#include "model/contact/fft_wisdom.inc"
    ;

// Imports kFftWisdom once per process, before the first plan. Call with PlannerMutex held.
bool ImportWisdomLocked() {
  static const bool imported = kFftWisdom[0] != '\0' && fftw_import_wisdom_from_string(kFftWisdom) != 0;
  return imported;
}

using Complex = std::complex<double>;

// The unit-modulus Love kernel of one grid shape and cell size: its spectrum for the FFT
// product, and its values by offset for cheap sparse updates.
struct Kernel {
  std::vector<Complex> spectrum;  // of the 2nx × 2ny wrapped kernel, divided by the FFT size
  std::vector<double> table;      // offset (ox, oy) at (oy + ny − 1)(2nx − 1) + ox + nx − 1
  double self = 0;                // the cell's own coefficient, offset (0, 0)
};

// Linear (non-periodic) convolution of an nx × ny field with a kernel of offsets
// −(n−1) … (n−1), by FFT on a 2nx × 2ny zero-padded array (DC-FFT). The 2D transform is done
// as 1D transforms that skip the zero half: real rows only for the ny rows that hold data (and,
// backwards, only for the ny rows that are kept), complex columns for all 2ny rows.
class FftConvolver {
 public:
  FftConvolver(int nx, int ny, unsigned planner)
      : nx_(nx), ny_(ny), mx_(2 * nx), my_(2 * ny), mxc_(nx + 1) {
    real_ = fftw_alloc_real(static_cast<size_t>(mx_) * my_);
    spec_ = fftw_alloc_complex(static_cast<size_t>(mxc_) * my_);
    half_ = fftw_alloc_complex(static_cast<size_t>(mxc_) * my_);
    back_ = fftw_alloc_complex(static_cast<size_t>(mxc_) * my_);
    if (real_ == nullptr || spec_ == nullptr || half_ == nullptr || back_ == nullptr) {
      Free();
      throw std::bad_alloc();
    }
    std::lock_guard<std::mutex> lock(PlannerMutex());
    ImportWisdomLocked();
    const int n_row[1] = {mx_}, n_col[1] = {my_};
    // The row transforms write the first ny rows of half_; its last ny rows are the zero
    // padding, set once after planning (FFTW_MEASURE overwrites the arrays while it plans) and
    // never written: the column transform reads half_ out of place into spec_ (no re-zeroing per
    // product; the same codelets as the in-place plan, without its buffer copy).
    rows_forward_ = fftw_plan_many_dft_r2c(1, n_row, ny_, real_, nullptr, 1, mx_, half_, nullptr,
                                           1, mxc_, planner);
    cols_forward_ = fftw_plan_many_dft(1, n_col, mxc_, half_, nullptr, mxc_, 1, spec_, nullptr,
                                       mxc_, 1, FFTW_FORWARD, planner);
    // Backwards out of place too (spec_ → back_): FFTW's in-place strided column plan copied
    // every column batch through a buffer it allocated on each execution (malloc_consolidate,
    // fftw_cpy2d: ~15% of a cycloid cycle's time, docs/performance.md).
    cols_backward_ = fftw_plan_many_dft(1, n_col, mxc_, spec_, nullptr, mxc_, 1, back_, nullptr,
                                        mxc_, 1, FFTW_BACKWARD, planner);
    rows_backward_ = fftw_plan_many_dft_c2r(1, n_row, ny_, back_, nullptr, 1, mxc_, real_,
                                            nullptr, 1, mx_, planner);
    if (!rows_forward_ || !cols_forward_ || !cols_backward_ || !rows_backward_) {
      FreeLocked();
      throw std::runtime_error("FFTW could not plan the contact convolution");
    }
    Complex* h = reinterpret_cast<Complex*>(half_);
    std::fill(h, h + static_cast<size_t>(mxc_) * my_, Complex(0.0, 0.0));
  }
  ~FftConvolver() { Free(); }
  FftConvolver(const FftConvolver&) = delete;
  FftConvolver& operator=(const FftConvolver&) = delete;

  // The unscaled r2c spectrum (mxc × my) of the 2nx × 2ny real field value(jx, jy).
  template <class Value>
  std::vector<Complex> RealSpectrum(const Value& value) const {
    double* wrapped = fftw_alloc_real(static_cast<size_t>(mx_) * my_);
    fftw_complex* spec = fftw_alloc_complex(static_cast<size_t>(mxc_) * my_);
    if (wrapped == nullptr || spec == nullptr) {
      fftw_free(wrapped);
      fftw_free(spec);
      throw std::bad_alloc();
    }
    fftw_plan plan;
    {
      std::lock_guard<std::mutex> lock(PlannerMutex());
      plan = fftw_plan_dft_r2c_2d(my_, mx_, wrapped, spec, FFTW_ESTIMATE);
    }
    for (int jy = 0; jy < my_; ++jy)
      for (int jx = 0; jx < mx_; ++jx) wrapped[static_cast<size_t>(jy) * mx_ + jx] = value(jx, jy);
    fftw_execute(plan);
    const Complex* s = reinterpret_cast<const Complex*>(spec);
    std::vector<Complex> out(s, s + static_cast<size_t>(mxc_) * my_);
    {
      std::lock_guard<std::mutex> lock(PlannerMutex());
      fftw_destroy_plan(plan);
    }
    fftw_free(wrapped);
    fftw_free(spec);
    return out;
  }

  Kernel MakeKernel(double dx, double dy) const {
    Kernel k;
    const double xi = 0.5 * dx, eta = 0.5 * dy;
    const int wx = 2 * nx_ - 1, wy = 2 * ny_ - 1;
    k.table.resize(static_cast<size_t>(wx) * wy);
    // The coefficient is even in both offsets: evaluate one quadrant, mirror the rest.
    for (int oy = 0; oy < ny_; ++oy)
      for (int ox = 0; ox < nx_; ++ox) {
        const double v = LoveInfluence(ox * dx, oy * dy, xi, eta);
        for (int sy : {-1, 1})
          for (int sx : {-1, 1})
            k.table[static_cast<size_t>(sy * oy + ny_ - 1) * wx + (sx * ox + nx_ - 1)] = v;
      }
    k.self = k.table[static_cast<size_t>(ny_ - 1) * wx + (nx_ - 1)];
    // Wrapped kernel: offsets 0 … n−1 in the first half, −(n−1) … −1 in the second; the
    // middle index n is never reached by a product and holds 0.
    const std::vector<Complex> spec = RealSpectrum([&](int jx, int jy) {
      const int oy = jy < ny_ ? jy : jy - my_;
      const int ox = jx < nx_ ? jx : jx - mx_;
      const bool unused = jy == ny_ || jx == nx_;
      return unused ? 0.0 : k.table[static_cast<size_t>(oy + ny_ - 1) * wx + (ox + nx_ - 1)];
    });
    const double scale = 1.0 / (static_cast<double>(mx_) * my_);
    k.spectrum.resize(spec.size());
    for (size_t i = 0; i < spec.size(); ++i) k.spectrum[i] = spec[i] * scale;
    return k;
  }

  // A preconditioner of the convolution: the inverse of the circulant whose kernel is the same
  // influence coefficient continued periodically over the 2nx × 2ny grid (offset min(j, 2n − j),
  // no zero padding). The padded DC-FFT kernel is a principal block of no circulant and its
  // spectrum comes near zero; the periodic one is positive. Applied with Apply to a field on the
  // nx × ny block, it gives that block of the circulant's inverse: symmetric positive definite,
  // an approximation of K⁻¹ up to a positive factor. Empty spectrum when a value is not > 0.
  Kernel MakePeriodicInverse(double dx, double dy) const {
    Kernel k;
    const double xi = 0.5 * dx, eta = 0.5 * dy;
    // Even in both offsets: one quadrant evaluated, mirrored.
    std::vector<double> quadrant(static_cast<size_t>(nx_ + 1) * (ny_ + 1));
    for (int oy = 0; oy <= ny_; ++oy)
      for (int ox = 0; ox <= nx_; ++ox)
        quadrant[static_cast<size_t>(oy) * (nx_ + 1) + ox] = LoveInfluence(ox * dx, oy * dy, xi, eta);
    const std::vector<Complex> s = RealSpectrum([&](int jx, int jy) {
      return quadrant[static_cast<size_t>(std::min(jy, my_ - jy)) * (nx_ + 1) + std::min(jx, mx_ - jx)];
    });
    const double big_n = static_cast<double>(mx_) * my_;
    bool positive = true;
    for (const Complex& c : s) positive = positive && c.real() > 0 && std::isfinite(c.real());
    if (positive) {
      k.spectrum.resize(s.size());
      for (size_t i = 0; i < s.size(); ++i) k.spectrum[i] = Complex(1.0 / (s[i].real() * big_n), 0.0);
    }
    return k;
  }

  // out = scale · (kernel ∗ in) on the nx × ny grid.
  void Apply(const Kernel& kernel, const double* in, double* out, double scale) {
    for (int iy = 0; iy < ny_; ++iy) {
      double* row = real_ + static_cast<size_t>(iy) * mx_;
      std::copy(in + static_cast<size_t>(iy) * nx_, in + static_cast<size_t>(iy + 1) * nx_, row);
      std::fill(row + nx_, row + mx_, 0.0);
    }
    Complex* s = reinterpret_cast<Complex*>(spec_);
    fftw_execute(rows_forward_);
    fftw_execute(cols_forward_);
    // The product written out (a·c − b·d, a·d + b·c: the same operations as std::complex's
    // finite-value path, without its NaN check and library fallback per element).
    kernels::ComplexProduct(reinterpret_cast<double*>(s), reinterpret_cast<const double*>(kernel.spectrum.data()),
                            static_cast<size_t>(mxc_) * my_);
    fftw_execute(cols_backward_);
    fftw_execute(rows_backward_);
    for (int iy = 0; iy < ny_; ++iy)
      for (int ix = 0; ix < nx_; ++ix)
        out[static_cast<size_t>(iy) * nx_ + ix] = scale * real_[static_cast<size_t>(iy) * mx_ + ix];
  }

  // out += scale · Σ_j c_j K(i − j) over the few listed cells j (direct sum).
  void AddSparse(const Kernel& kernel, const std::pair<int, double>* c, size_t count, double* out,
                 double scale) const {
    kernels::AddSparse(kernel.table.data(), nx_, ny_, c, count, out, scale);
  }

  int cells() const { return nx_ * ny_; }

 private:
  void Free() {
    std::lock_guard<std::mutex> lock(PlannerMutex());
    FreeLocked();
  }
  void FreeLocked() {
    for (fftw_plan* p : {&rows_forward_, &cols_forward_, &cols_backward_, &rows_backward_}) {
      if (*p != nullptr) fftw_destroy_plan(*p);
      *p = nullptr;
    }
    if (real_ != nullptr) fftw_free(real_);
    if (spec_ != nullptr) fftw_free(spec_);
    if (half_ != nullptr) fftw_free(half_);
    if (back_ != nullptr) fftw_free(back_);
    real_ = nullptr;
    spec_ = nullptr;
    half_ = nullptr;
    back_ = nullptr;
  }

  int nx_, ny_, mx_, my_, mxc_;
  double* real_ = nullptr;
  fftw_complex* spec_ = nullptr;
  fftw_complex* half_ = nullptr;  // the row transforms' output, its last ny rows always zero
  fftw_complex* back_ = nullptr;  // the backward column transforms' output
  fftw_plan rows_forward_ = nullptr, cols_forward_ = nullptr;
  fftw_plan cols_backward_ = nullptr, rows_backward_ = nullptr;
};

// Caches are bounded: beyond these many entries they are cleared (a study uses a few shapes).
constexpr size_t kMaxConvolvers = 8;
constexpr size_t kMaxKernels = 64;

// The displacement u = K p / E* of the last pressures this thread solved or convolved, so that a
// solve warm-started from a previous solution (or a Displacement of it) skips its first
// convolution. The stored u is the exact output of the same convolution (same kernel values, same
// FFTW_ESTIMATE plan for the shape, same input bits), so reusing it changes no bit of any result,
// only the cost. Per thread (a solver instance is single-threaded; the cycloid LTCA's steering and
// final solvers are two instances that hand pressures to each other). Keyed by the grid shape,
// cell sizes and E*, matched on the pressure's bits.
class DisplacementMemo {
 public:
  static DisplacementMemo& ForThisThread() {
    thread_local DisplacementMemo memo;
    return memo;
  }
  // Copies the stored displacement of `p` into u and returns true when there is one.
  bool Find(const Grid& grid, double e_star, bool measured, const std::vector<double>& p,
            std::vector<double>& u) const {
    for (const Entry& e : entries_) {
      if (e.measured != measured || e.nx != grid.nx || e.ny != grid.ny || e.dx != grid.dx || e.dy != grid.dy || e.e_star != e_star ||
          e.p.size() != p.size())
        continue;
      if (std::memcmp(e.p.data(), p.data(), p.size() * sizeof(double)) != 0) continue;
      u.assign(e.u.begin(), e.u.end());
      return true;
    }
    return false;
  }
  void Store(const Grid& grid, double e_star, bool measured, const std::vector<double>& p,
             const std::vector<double>& u) {
    if (entries_.size() < kSize) entries_.emplace_back();
    Entry& e = entries_[next_];
    next_ = (next_ + 1) % kSize;
    e.nx = grid.nx;
    e.ny = grid.ny;
    e.dx = grid.dx;
    e.dy = grid.dy;
    e.e_star = e_star;
    e.measured = measured;
    e.p.assign(p.begin(), p.end());
    e.u.assign(u.begin(), u.end());
  }

 private:
  static constexpr size_t kSize = 32;  // more than the pairs of a crank angle, twice
  struct Entry {
    int nx = 0, ny = 0;
    double dx = 0, dy = 0, e_star = 0;
    bool measured = false;  // FFTW_MEASURE plans may differ from FFTW_ESTIMATE ones in rounding
    std::vector<double> p, u;
  };
  std::vector<Entry> entries_;
  size_t next_ = 0;
};

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

// ---------------------------------------------------------------------------------------------
// The solver.

bool FftWisdomImported() {
  std::lock_guard<std::mutex> lock(PlannerMutex());
  return ImportWisdomLocked();
}

std::string PlanFftWisdom(const std::vector<std::array<int, 2>>& shapes) {
  {
    std::lock_guard<std::mutex> lock(PlannerMutex());
    ImportWisdomLocked();  // (not again after the forgetting below)
    fftw_forget_wisdom();
  }
  for (const auto& [nx, ny] : shapes) FftConvolver(nx, ny, FFTW_PATIENT);
  std::lock_guard<std::mutex> lock(PlannerMutex());
  char* text = fftw_export_wisdom_to_string();
  if (text == nullptr) throw std::runtime_error("FFTW could not export its wisdom");
  std::string out(text);
  fftw_free(text);
  return out;
}

struct HalfSpaceSolver::Impl {
  SolverOptions options;
  std::map<std::pair<int, int>, std::unique_ptr<FftConvolver>> convolvers;
  std::map<std::tuple<int, int, double, double>, Kernel> kernels;
  std::map<std::tuple<int, int, double, double>, Kernel> inverse_kernels;  // preconditioners
  std::vector<double> h, p, p_old, u, g, t, r, gm, z;  // work arrays (h: the gap above its minimum)
  std::vector<double> sorted;
  std::vector<std::pair<int, double>> corrections;

  explicit Impl(SolverOptions o) : options(o) {}

  FftConvolver& Convolver(const Grid& grid) {
    const auto key = std::make_pair(grid.nx, grid.ny);
    auto it = convolvers.find(key);
    if (it == convolvers.end()) {
      if (convolvers.size() >= kMaxConvolvers) {
        convolvers.clear();
        kernels.clear();
      }
      const unsigned planner = options.measure_fft_plans ? FFTW_MEASURE : FFTW_ESTIMATE;
      it = convolvers.emplace(key, std::make_unique<FftConvolver>(grid.nx, grid.ny, planner))
               .first;
    }
    return *it->second;
  }

  const Kernel& InverseKernelFor(const Grid& grid, const FftConvolver& conv) {
    const auto key = std::make_tuple(grid.nx, grid.ny, grid.dx, grid.dy);
    auto it = inverse_kernels.find(key);
    if (it == inverse_kernels.end()) {
      if (inverse_kernels.size() >= kMaxKernels) inverse_kernels.clear();
      it = inverse_kernels.emplace(key, conv.MakePeriodicInverse(grid.dx, grid.dy)).first;
    }
    return it->second;
  }

  const Kernel& KernelFor(const Grid& grid, const FftConvolver& conv) {
    const auto key = std::make_tuple(grid.nx, grid.ny, grid.dx, grid.dy);
    auto it = kernels.find(key);
    if (it == kernels.end()) {
      if (kernels.size() >= kMaxKernels) kernels.clear();
      it = kernels.emplace(key, conv.MakeKernel(grid.dx, grid.dy)).first;
    }
    return it->second;
  }

  ContactSolution Solve(const Grid& grid, const std::vector<double>& h, bool load_control,
                        double target, double e_star, const std::vector<double>* start);
  // Solve's body, inlined twice: into SolveBaseline (x86-64 baseline) and SolveAvx2 (compiled
  // for AVX2, chosen at run time). Only loops without reductions vectorise (the compiler keeps
  // floating-point sums in order), and AVX2 has no fused multiply-add: both give the same bits.
  template <int kTag>
  [[gnu::always_inline]] inline ContactSolution SolveBody(const Grid& grid, const std::vector<double>& h,
                                                          bool load_control, double target, double e_star,
                                                          const std::vector<double>* start);
  ContactSolution SolveBaseline(const Grid& grid, const std::vector<double>& h, bool load_control, double target,
                                double e_star, const std::vector<double>* start);
#if defined(__x86_64__) && defined(__GNUC__)
  [[gnu::target("avx2")]] ContactSolution SolveAvx2(const Grid& grid, const std::vector<double>& h,
                                                    bool load_control, double target, double e_star,
                                                    const std::vector<double>* start);
#endif
};

HalfSpaceSolver::HalfSpaceSolver(SolverOptions options)
    : impl_(std::make_unique<Impl>(options)) {}
HalfSpaceSolver::~HalfSpaceSolver() = default;
HalfSpaceSolver::HalfSpaceSolver(HalfSpaceSolver&&) noexcept = default;
HalfSpaceSolver& HalfSpaceSolver::operator=(HalfSpaceSolver&&) noexcept = default;
const SolverOptions& HalfSpaceSolver::options() const { return impl_->options; }

// Polonsky & Keer (1999).
// Load control (eqs. 20, 22): the gap is g = u + h − ḡ, ḡ its mean over the cells in contact
// I_c = {p > 0}; at convergence ḡ is the approach δ. Approach control: g = u + h − δ with δ given.
// Each iteration: conjugate direction t on I_c, step τ by exact line search (one convolution
// r = K t), projection onto p ≥ 0, cells with p = 0 and g < 0 (overlap) re-enter with p = −τ g
// (and the conjugacy is reset), and, under load control, p is rescaled to the load.
// Preconditioned (SolverOptions::precondition): the direction is built from z = P M g instead of
// g, M the periodic kernel's inverse (MakePeriodicInverse) on I_c, P the zero-sum projection on
// I_c under load control, β = gᵀz / (gᵀz)_previous: a preconditioned CG on the free set as in
// Vollebregt's BCCG (J. Comput. Phys. 257 (2014) 333–351), one more FFT pair per iteration.
// The displacement of the new pressure is not convolved afresh: u ← f (u − τ r + K c), where c is
// the (usually few-cell) change made by the projection and the re-entry, added by a direct sum;
// only when many cells change, and every kRefresh iterations against drift, is u = K p redone by
// FFT. That halves the FFTs of the textbook algorithm.
ContactSolution HalfSpaceSolver::Impl::Solve(const Grid& grid, const std::vector<double>& gap,
                                             bool load_control, double target, double e_star,
                                             const std::vector<double>* start) {
#if defined(__x86_64__) && defined(__GNUC__)
  if (kernels::HasAvx2()) return SolveAvx2(grid, gap, load_control, target, e_star, start);
#endif
  return SolveBaseline(grid, gap, load_control, target, e_star, start);
}

ContactSolution HalfSpaceSolver::Impl::SolveBaseline(const Grid& grid, const std::vector<double>& gap,
                                                     bool load_control, double target, double e_star,
                                                     const std::vector<double>* start) {
  return SolveBody<0>(grid, gap, load_control, target, e_star, start);
}

#if defined(__x86_64__) && defined(__GNUC__)
ContactSolution HalfSpaceSolver::Impl::SolveAvx2(const Grid& grid, const std::vector<double>& gap,
                                                 bool load_control, double target, double e_star,
                                                 const std::vector<double>* start) {
  return SolveBody<1>(grid, gap, load_control, target, e_star, start);
}
#endif

template <int kTag>
ContactSolution HalfSpaceSolver::Impl::SolveBody(const Grid& grid, const std::vector<double>& gap,
                                                 bool load_control, double target, double e_star,
                                                 const std::vector<double>* start) {
  const char* where =
      load_control ? "HalfSpaceSolver::SolveForLoad" : "HalfSpaceSolver::SolveForApproach";
  detail::CheckGrid(grid, where);
  detail::CheckField(grid, gap, "gap_mm", where);
  detail::CheckModulus(e_star, where);
  detail::CheckFinite(target, load_control ? "load_N" : "approach_mm", where);
  const size_t n = static_cast<size_t>(grid.cells());
  const double area = grid.cell_area_mm2();
  // Work with the gap above its minimum (so a large common offset costs no digits in u + h − δ);
  // δ is shifted back on return.
  const double gap_min = *std::min_element(gap.begin(), gap.end());
  h.resize(n);
  for (size_t i = 0; i < n; ++i) h[i] = gap[i] - gap_min;
  const double h_min = 0.0;
  const double load = target, approach = target - gap_min;

  p.assign(n, 0.0);
  bool from_start = false;
  if (load_control) {
    if (load <= 0)
      return detail::Unloaded(grid, gap_min, load < 0 ? "negative load treated as zero" : "");
    if (UsableStart(start, n)) {
      p = *start;
      from_start = true;
    } else {
      // Hertz-like start: p ∝ sqrt(c − h) where h < c, c the gap at the edge of a contact whose
      // area A gives c = δ/2 with a Hertz approach δ ≈ 3W / (4E* sqrt(A/π)) (exact for a
      // sphere: the contact edge has h = a²/2R = δ/2, and the profile is then exactly Hertz's).
      // 40% fewer iterations than a uniform start on point contacts (docs/performance.md).
      sorted.assign(h.begin(), h.end());
      std::sort(sorted.begin(), sorted.end());
      size_t k = 0;
      for (; k < n; ++k) {
        const double a_c = static_cast<double>(k + 1) * area;
        const double half_delta = 0.375 * load / (e_star * std::sqrt(a_c / kPi));
        if (sorted[k] >= half_delta) break;
      }
      if (k == n) {
        p.assign(n, 1.0);  // the whole grid is expected in contact
      } else {
        for (size_t i = 0; i < n; ++i) p[i] = sorted[k] > h[i] ? std::sqrt(sorted[k] - h[i]) : 0.0;
      }
    }
  } else {
    bool any = false;
    for (size_t i = 0; i < n; ++i)
      if (approach - h[i] > 0) {
        p[i] = approach - h[i];  // the rigid overlap, scaled below
        any = true;
      }
    if (!any) return detail::Unloaded(grid, target, "");
  }

  FftConvolver& conv = Convolver(grid);
  const Kernel& kernel = KernelFor(grid, conv);
  const double inv_e = 1.0 / e_star;
  auto convolve = [&](const std::vector<double>& in, std::vector<double>& out) {
    conv.Apply(kernel, in.data(), out.data(), inv_e);
  };
  // Fallback step when the line search is degenerate (a single cell in contact gives G = 0):
  // the pressure that moves a cell's own surface by a unit gap.
  const double tau_self = e_star / kernel.self;
  const Kernel& inverse = InverseKernelFor(grid, conv);
  const bool precondition = options.precondition && !inverse.spectrum.empty();
  if (precondition) {
    gm.assign(n, 0.0);
    z.assign(n, 0.0);
  }
  // A direct sparse update costs n per changed cell; an FFT convolution about 10 n log2(4n).
  const size_t max_sparse = static_cast<size_t>(10.0 * std::log2(4.0 * static_cast<double>(n)));
  constexpr int kRefresh = 20;

  u.assign(n, 0.0);
  g.assign(n, 0.0);
  t.assign(n, 0.0);
  r.assign(n, 0.0);
  DisplacementMemo& memo = DisplacementMemo::ForThisThread();
  if (!(from_start && memo.Find(grid, e_star, options.measure_fft_plans, p, u))) convolve(p, u);
  // Scale the start: to the load, or by the best single factor (exact line search on the
  // energy ½pᵀKp + pᵀ(h − δ)).
  {
    double f = 1;
    if (load_control) {
      double sum = 0;
      for (double v : p) sum += v;
      f = load / (area * sum);
    } else {
      double a = 0, b = 0;
      for (size_t i = 0; i < n; ++i) {
        a += p[i] * (approach - h[i]);
        b += p[i] * u[i];
      }
      f = (b > 0 && std::isfinite(a / b)) ? a / b : tau_self;
    }
    for (size_t i = 0; i < n; ++i) {
      p[i] *= f;
      u[i] *= f;
    }
  }

  ContactSolution s;
  double g_old = 1.0;
  bool conjugate = false;
  bool u_exact = true;
  int since_refresh = 0;
  int it = 0;
  for (it = 1; it <= options.max_iterations; ++it) {
    if (!u_exact || since_refresh >= kRefresh) {
      convolve(p, u);
      since_refresh = 0;
    }
    ++since_refresh;
    // The arrays through local pointers (the loops below then keep them in registers instead of
    // reloading them from the members after every store; the arithmetic is unchanged).
    double* const pp = p.data();
    double* const uu = u.data();
    double* const gg = g.data();
    double* const tt = t.data();
    const double* const hh = h.data();
    const double* const rr = r.data();
    double shift = approach;
    size_t nc = 0;
    if (load_control) {
      double sum_g = 0;
      for (size_t i = 0; i < n; ++i)
        if (pp[i] > 0) {
          sum_g += uu[i] + hh[i];
          ++nc;
        }
      shift = nc > 0 ? sum_g / static_cast<double>(nc) : h_min;
    }
    double big_g = 0;
    for (size_t i = 0; i < n; ++i) {
      gg[i] = uu[i] + hh[i] - shift;
      if (pp[i] > 0) {
        big_g += gg[i] * gg[i];
        if (!load_control) ++nc;
      }
    }
    if (precondition) {
      // z = M g on the contact set: the periodic kernel's inverse applied to g masked to I_c,
      // taken on I_c and (load control) shifted to zero sum, so that the direction keeps the load.
      double* const gmm = gm.data();
      for (size_t i = 0; i < n; ++i) gmm[i] = pp[i] > 0 ? gg[i] : 0.0;
      conv.Apply(inverse, gmm, z.data(), e_star);
      double* const zz = z.data();
      double z_bar = 0;
      if (load_control && nc > 0) {
        for (size_t i = 0; i < n; ++i)
          if (pp[i] > 0) z_bar += zz[i];
        z_bar /= static_cast<double>(nc);
      }
      big_g = 0;
      for (size_t i = 0; i < n; ++i)
        if (pp[i] > 0) {
          zz[i] -= z_bar;
          big_g += gg[i] * zz[i];
        }
    }
    const double* const dir = precondition ? z.data() : gg;
    const double beta = (conjugate && g_old > 0) ? big_g / g_old : 0.0;
    for (size_t i = 0; i < n; ++i) tt[i] = pp[i] > 0 ? dir[i] + beta * tt[i] : 0.0;
    g_old = big_g;

    convolve(t, r);
    double r_bar = 0;
    if (load_control && nc > 0) {
      double sum_r = 0;
      for (size_t i = 0; i < n; ++i)
        if (pp[i] > 0) sum_r += rr[i];
      r_bar = sum_r / static_cast<double>(nc);
    }
    double num = 0, den = 0;
    for (size_t i = 0; i < n; ++i)
      if (pp[i] > 0) {
        num += gg[i] * tt[i];
        den += (rr[i] - r_bar) * tt[i];
      }
    const double tau = (den > 0 && std::isfinite(num / den)) ? num / den : tau_self;

    // Step, projection, re-entry; c_i = p_new − (p − τ t) on the cells these two touched. The
    // new pressure goes to p_old, which then swaps with p (no copy); its sum is taken on the way
    // (the same order of additions as a separate pass).
    // The corrections go into a buffer of n entries through a pointer (no push_back in the loop:
    // its possible reallocation made the compiler keep the sum and the array in memory).
    bool overlap = false;
    double sum_p = 0;
    p_old.resize(n);
    corrections.resize(n);
    size_t n_corr = 0;
    {
      double* const pn = p_old.data();
      std::pair<int, double>* const cc = corrections.data();
      for (size_t i = 0; i < n; ++i) {
        const double raw = pp[i] - tau * tt[i];  // t = 0 off the contact
        double next = raw > 0 ? raw : 0.0;
        if (next == 0 && gg[i] < 0) {
          next = -tau * gg[i];
          overlap = true;
        }
        if (next != raw) cc[n_corr++] = {static_cast<int>(i), next - raw};
        pn[i] = next;
        sum_p += next;
      }
    }
    p.swap(p_old);
    conjugate = !overlap;

    double f = 1;
    if (load_control) {
      if (!(sum_p > 0) || !std::isfinite(sum_p)) {  // not in exact arithmetic; restart
        p.assign(n, load / (area * static_cast<double>(n)));
        conjugate = false;
        u_exact = false;
        continue;
      }
      f = load / (area * sum_p);
    }
    // Rescale, measure the change, and (when the sparse update is taken) step the displacement
    // in the same pass: u ← u − τ r here, + K c and × f below.
    const bool sparse = n_corr <= max_sparse;
    double change = 0, total = 0;
    {
      double* const pn = p.data();
      const double* const po = p_old.data();
      if (sparse) {
        for (size_t i = 0; i < n; ++i) {
          pn[i] *= f;
          change += std::abs(pn[i] - po[i]);
          total += pn[i];
          uu[i] -= tau * rr[i];
        }
      } else {
        for (size_t i = 0; i < n; ++i) {
          pn[i] *= f;
          change += std::abs(pn[i] - po[i]);
          total += pn[i];
        }
      }
    }
    // The displacement of the new pressure.
    if (sparse) {
      conv.AddSparse(kernel, corrections.data(), n_corr, uu, inv_e);
      if (f != 1)
        for (size_t i = 0; i < n; ++i) uu[i] *= f;
      u_exact = true;
    } else {
      u_exact = false;
    }
    if (total > 0 && change / total < options.tolerance) {
      s.converged = true;
      break;
    }
    if (!load_control && total == 0 && !overlap) {  // everything lifted off: the iteration
      s.converged = true;                            // has left the contact; nothing touches
      break;
    }
  }
  s.iterations = std::min(it, options.max_iterations);
  if (!s.converged) {
    std::ostringstream os;
    os << "not converged after " << options.max_iterations << " iterations";
    s.message = os.str();
  }
  if (load_control) {
    // The approach from the final pressure: the mean of u + h over the contact.
    convolve(p, u);
    memo.Store(grid, e_star, options.measure_fft_plans, p, u);
    double sum_g = 0;
    size_t nc = 0;
    for (size_t i = 0; i < n; ++i)
      if (p[i] > 0) {
        sum_g += u[i] + h[i];
        ++nc;
      }
    s.approach_mm = gap_min + (nc > 0 ? sum_g / static_cast<double>(nc) : h_min);
  } else {
    s.approach_mm = target;
  }
  s.pressure_MPa = p;
  detail::Summarise(grid, s);
  return s;
}

ContactSolution HalfSpaceSolver::SolveForLoad(const Grid& grid, const std::vector<double>& gap_mm,
                                              double load_N, double e_star_MPa) {
  return impl_->Solve(grid, gap_mm, true, load_N, e_star_MPa, nullptr);
}

ContactSolution HalfSpaceSolver::SolveForLoad(const Grid& grid, const std::vector<double>& gap_mm,
                                              double load_N, double e_star_MPa,
                                              const std::vector<double>& initial_pressure_MPa) {
  return impl_->Solve(grid, gap_mm, true, load_N, e_star_MPa, &initial_pressure_MPa);
}

ContactSolution HalfSpaceSolver::SolveForApproach(const Grid& grid,
                                                  const std::vector<double>& gap_mm,
                                                  double approach_mm, double e_star_MPa) {
  return impl_->Solve(grid, gap_mm, false, approach_mm, e_star_MPa, nullptr);
}

HalfSpaceSolver::Sensitivity HalfSpaceSolver::SensitivityForLoad(
    const Grid& grid, const std::vector<double>& pressure, const std::vector<double>& dgap,
    double dload, double e_star, double tolerance, const std::vector<double>* initial) {
  if (pressure.size() != size_t(grid.cells()) || dgap.size() != size_t(grid.cells()))
    throw std::invalid_argument("SensitivityForLoad: pressure and gap derivative need one value per cell");
  return FrozenSetSolve(grid, pressure, dgap, dload, e_star, tolerance, initial, true);
}

HalfSpaceSolver::Sensitivity HalfSpaceSolver::AdjointOfFunctional(const Grid& grid,
                                                                  const std::vector<double>& pressure,
                                                                  const std::vector<double>& functional,
                                                                  double e_star, double tolerance) {
  if (pressure.size() != size_t(grid.cells()) || functional.size() != size_t(grid.cells()))
    throw std::invalid_argument("AdjointOfFunctional: pressure and functional need one value per cell");
  // K u − μ·1 = g is SensitivityForLoad's system with dh = −g and dW = 0.
  std::vector<double> minus_g(functional.size());
  for (size_t k = 0; k < functional.size(); ++k) minus_g[k] = -functional[k];
  return FrozenSetSolve(grid, pressure, minus_g, 0.0, e_star, tolerance, nullptr, false);
}

HalfSpaceSolver::Sensitivity HalfSpaceSolver::FrozenSetSolve(
    const Grid& grid, const std::vector<double>& pressure, const std::vector<double>& dgap,
    double dload, double e_star, double tolerance, const std::vector<double>* initial, bool approach) {
  const size_t n = size_t(grid.nx) * grid.ny;
  Sensitivity out;
  out.pressure_MPa.assign(n, 0.0);
  std::vector<size_t> set;
  for (size_t k = 0; k < n; ++k)
    if (pressure[k] > 0) set.push_back(k);
  if (set.empty()) {
    out.converged = true;
    return out;
  }
  const double m = double(set.size());
  // The part that carries the load change: uniform over C; the rest z sums to zero.
  const double uniform = dload / (grid.cell_area_mm2() * m);
  detail::CheckGrid(grid, "HalfSpaceSolver::SensitivityForLoad");
  detail::CheckModulus(e_star, "HalfSpaceSolver::SensitivityForLoad");
  // The convolution with the cached plan and kernel, on work arrays reused by every product (the
  // same arithmetic as Displacement, without its allocation per product).
  FftConvolver& conv = impl_->Convolver(grid);
  const Kernel& kernel = impl_->KernelFor(grid, conv);
  std::vector<double> full(n, 0.0), u(n);
  auto displacement = [&]() { conv.Apply(kernel, full.data(), u.data(), 1.0 / e_star); };
  std::vector<double> product(set.size());
  auto apply = [&](const std::vector<double>& z_on_set) -> const std::vector<double>& {  // P K z on C
    std::fill(full.begin(), full.end(), 0.0);
    for (size_t i = 0; i < set.size(); ++i) full[set[i]] = z_on_set[i];
    displacement();
    double mean = 0;
    for (size_t i = 0; i < set.size(); ++i) mean += (product[i] = u[set[i]]);
    mean /= m;
    for (double& v : product) v -= mean;
    return product;
  };
  // P K dp0 (a copy: the work array is reused); exactly zero at fixed load.
  const std::vector<double> kb =
      uniform != 0 ? apply(std::vector<double>(set.size(), uniform)) : std::vector<double>(set.size(), 0.0);
  std::vector<double> b(set.size());
  double mean_dh = 0;
  for (size_t i = 0; i < set.size(); ++i) mean_dh += dgap[set[i]];
  mean_dh /= m;
  for (size_t i = 0; i < set.size(); ++i) b[i] = -(dgap[set[i]] - mean_dh) - kb[i];
  std::vector<double> z(set.size(), 0.0), r = b, d = b;
  double rr = 0, bb = 0;
  for (size_t i = 0; i < set.size(); ++i) rr += r[i] * r[i];
  bb = rr;
  if (initial && initial->size() == n && bb > 0) {
    // The guess on C, brought to the load condition cA·Σ dp = dW: scaled when its sum has the
    // sign of dW, else shifted by a constant; z = dp − uniform then sums to zero (up to rounding,
    // removed). Kept only when its residual b − A z is below |b| (that of z = 0).
    std::vector<double> z0(set.size());
    double sum = 0;
    for (size_t i = 0; i < set.size(); ++i) sum += (z0[i] = (*initial)[set[i]]);
    const double target = uniform * m;
    const double scale = target != 0 && sum * target > 0 ? target / sum : 1.0;
    double mean = 0;
    for (double& v : z0) mean += (v = v * scale - uniform);
    mean /= m;
    for (double& v : z0) v -= mean;
    const std::vector<double>& az = apply(z0);
    std::vector<double> r0(set.size());
    double rr0 = 0;
    for (size_t i = 0; i < set.size(); ++i) {
      r0[i] = b[i] - az[i];
      rr0 += r0[i] * r0[i];
    }
    if (rr0 < rr) {  // false for a NaN
      z = std::move(z0);
      r = std::move(r0);
      rr = rr0;
    }
  }
  int it = 0;
  const int max_it = std::max(50, 4 * int(set.size()));
  // Preconditioned CG (M = the block of the periodic kernel's inverse, InverseKernelFor, then
  // the zero-sum projection): 26 → 8.6 iterations per load sensitivity on the cycloid cycle's
  // 40 × 40 grids, each one more FFT pair. The stopping test is the plain CG's: the residual
  // |b − A z| <= tolerance · |b|, the same equations to the same accuracy.
  const Kernel& inverse = impl_->InverseKernelFor(grid, conv);
  const bool precondition = !inverse.spectrum.empty();
  std::vector<double> y_full, y;
  auto precond = [&](const std::vector<double>& rs) -> const std::vector<double>& {
    if (!precondition) return rs;
    y_full.resize(n);
    y.resize(set.size());
    std::fill(full.begin(), full.end(), 0.0);
    for (size_t i = 0; i < set.size(); ++i) full[set[i]] = rs[i];
    conv.Apply(inverse, full.data(), y_full.data(), e_star);
    double mean = 0;
    for (size_t i = 0; i < set.size(); ++i) mean += (y[i] = y_full[set[i]]);
    mean /= m;
    for (double& v : y) v -= mean;
    return y;
  };
  d = precond(r);
  double ry = 0;
  for (size_t i = 0; i < set.size(); ++i) ry += r[i] * d[i];
  while (it < max_it && rr > tolerance * tolerance * bb && bb > 0) {
    const std::vector<double>& ad = apply(d);
    double dad = 0;
    for (size_t i = 0; i < set.size(); ++i) dad += d[i] * ad[i];
    if (!(dad > 0) || !(ry > 0)) break;
    const double alpha = ry / dad;
    double rr_new = 0;
    for (size_t i = 0; i < set.size(); ++i) {
      z[i] += alpha * d[i];
      r[i] -= alpha * ad[i];
      rr_new += r[i] * r[i];
    }
    rr = rr_new;
    ++it;
    if (!(rr > tolerance * tolerance * bb)) break;
    const std::vector<double>& yr = precond(r);
    double ry_new = 0;
    for (size_t i = 0; i < set.size(); ++i) ry_new += r[i] * yr[i];
    const double beta = ry_new / ry;
    ry = ry_new;
    for (size_t i = 0; i < set.size(); ++i) d[i] = yr[i] + beta * d[i];
  }
  out.iterations = it;
  out.converged = bb == 0 || rr <= tolerance * tolerance * bb;
  for (size_t i = 0; i < set.size(); ++i) out.pressure_MPa[set[i]] = uniform + z[i];
  if (!approach) return out;
  // dδ = mean over C of (K dp + dh).
  std::fill(full.begin(), full.end(), 0.0);
  for (size_t i = 0; i < set.size(); ++i) full[set[i]] = out.pressure_MPa[set[i]];
  displacement();
  double da = 0;
  for (size_t i = 0; i < set.size(); ++i) da += u[set[i]] + dgap[set[i]];
  out.approach_mm = da / m;
  return out;
}

std::vector<double> HalfSpaceSolver::Displacement(const Grid& grid,
                                                  const std::vector<double>& pressure_MPa,
                                                  double e_star_MPa) {
  const char* where = "HalfSpaceSolver::Displacement";
  detail::CheckGrid(grid, where);
  detail::CheckField(grid, pressure_MPa, "pressure_MPa", where);
  detail::CheckModulus(e_star_MPa, where);
  std::vector<double> out;
  if (DisplacementMemo::ForThisThread().Find(grid, e_star_MPa, impl_->options.measure_fft_plans,
                                               pressure_MPa, out)) return out;
  FftConvolver& conv = impl_->Convolver(grid);
  const Kernel& kernel = impl_->KernelFor(grid, conv);
  out.resize(grid.cells());
  conv.Apply(kernel, pressure_MPa.data(), out.data(), 1.0 / e_star_MPa);
  return out;
}

std::vector<double> Displacement(const Grid& grid, const std::vector<double>& pressure_MPa,
                                 double e_star_MPa) {
  HalfSpaceSolver solver;
  return solver.Displacement(grid, pressure_MPa, e_star_MPa);
}

std::vector<double> DisplacementRateByCellHeight(const Grid& grid, const std::vector<double>& pressure_MPa,
                                                 double e_star_MPa) {
  const char* where = "DisplacementRateByCellHeight";
  detail::CheckGrid(grid, where);
  detail::CheckField(grid, pressure_MPa, "pressure_MPa", where);
  detail::CheckModulus(e_star_MPa, where);
  // With centres y_i = y0 + (iy + ½) dy and y0 = −ny dy / 2, an offset of o rows is o·dy and the
  // cell's half-height dy/2: d/d(dy) of LoveInfluence(ox dx, oy dy, dx/2, dy/2), even in both
  // offsets, so one table over |ox|, |oy|.
  using J = ceres::Jet<double, 1>;
  using Key = std::tuple<int, int, double, double>;
  thread_local std::map<Key, std::vector<double>> cache;
  const Key key{grid.nx, grid.ny, grid.dx, grid.dy};
  auto it = cache.find(key);
  if (it == cache.end()) {
    if (cache.size() >= 16) cache.clear();
    std::vector<double> table(size_t(grid.nx) * grid.ny);
    const J dy(grid.dy, 0);
    for (int oy = 0; oy < grid.ny; ++oy)
      for (int ox = 0; ox < grid.nx; ++ox)
        table[size_t(oy) * grid.nx + ox] =
            LoveInfluence(J(ox * grid.dx), J(double(oy)) * dy, J(0.5 * grid.dx), 0.5 * dy).v[0];
    it = cache.emplace(key, std::move(table)).first;
  }
  const std::vector<double>& table = it->second;
  std::vector<std::pair<int, double>> loaded;
  for (int j = 0; j < grid.cells(); ++j)
    if (pressure_MPa[j] != 0) loaded.emplace_back(j, pressure_MPa[j]);
  std::vector<double> rate(grid.cells(), 0.0);
  for (int i = 0; i < grid.cells(); ++i) {
    const int ix = i % grid.nx, iy = i / grid.nx;
    double sum = 0;
    for (const auto& [j, p] : loaded)
      sum += p * table[size_t(std::abs(iy - j / grid.nx)) * grid.nx + std::abs(ix - j % grid.nx)];
    rate[i] = sum / e_star_MPa;
  }
  return rate;
}

}  // namespace camopt::contact

// Speed against error of the half-space contact solver (docs/performance.md, "Half-space
// contact solver"). Counters carry the errors against the Hertz closed forms and against a
// tightly converged solve, so one run gives the whole table.
//   build/camopt_bench --benchmark_filter=Contact
#include <algorithm>
#include <cmath>
#include <vector>

#include <benchmark/benchmark.h>
#include <fftw3.h>

#include "model/contact/half_space.h"
#include "model/contact/hertz.h"
#include "model/contact/measures.h"
#include "model/contact/reference_gaps.h"

namespace camopt::contact {
namespace contact_bench {

constexpr double kEStar = 115384.6;  // steel on steel [MPa]
constexpr double kPointRadius = 10.0, kPointLoad = 100.0;  // sphere R [mm], W [N]
constexpr double kRollerRadius = 10.0, kRollerLength = 10.0, kRollerLoad = 1000.0;

Grid PointGrid(int n) {
  const double a = CircularPointContact(kPointLoad, kPointRadius, kEStar).radius;
  return CenteredGrid(n, n, 1.5 * a, 1.5 * a);
}

double Percent(double ours, double ref) { return 100.0 * (ours - ref) / ref; }

void PointCounters(benchmark::State& state, const Grid& g, const ContactSolution& s,
                   const ContactSolution& tight) {
  const auto hz = CircularPointContact(kPointLoad, kPointRadius, kEStar);
  state.counters["iters"] = s.iterations;
  state.counters["p0_err_pct"] = Percent(s.max_pressure_MPa, hz.peak_pressure);
  state.counters["a_count_err_pct"] = Percent(std::sqrt(s.contact_area_mm2 / kPi), hz.radius);
  state.counters["a_fit_err_pct"] = Percent(CircularContactRadius(g, s), hz.radius);
  state.counters["delta_err_pct"] = Percent(s.approach_mm, hz.approach);
  double diff = 0;
  for (int i = 0; i < g.cells(); ++i)
    diff = std::max(diff, std::abs(s.pressure_MPa[i] - tight.pressure_MPa[i]));
  state.counters["vs_tight_pct"] = 100.0 * diff / tight.max_pressure_MPa;
}

// Polonsky–Keer CG with DC-FFT, Hertz point contact; args: n (n × n cells), −log10(tolerance),
// FFTW_MEASURE plans (1) or FFTW_ESTIMATE (0).
void BM_ContactPointCg(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const double tol = std::pow(10.0, -static_cast<double>(state.range(1)));
  const Grid g = PointGrid(n);
  const auto h = SphereGap(g, kPointRadius);
  HalfSpaceSolver tight_solver({1e-13, 20000});
  const auto tight = tight_solver.SolveForLoad(g, h, kPointLoad, kEStar);
  SolverOptions options;
  options.tolerance = tol;
  options.max_iterations = 20000;
  options.measure_fft_plans = state.range(2) != 0;
  HalfSpaceSolver solver(options);
  ContactSolution s = solver.SolveForLoad(g, h, kPointLoad, kEStar);  // plans, kernel cached
  for (auto _ : state) {
    s = solver.SolveForLoad(g, h, kPointLoad, kEStar);
    benchmark::DoNotOptimize(s.pressure_MPa.data());  // (a double lvalue here is miscompiled with benchmark 1.7.1 + GCC)
  }
  PointCounters(state, g, s, tight);
}
BENCHMARK(BM_ContactPointCg)
    ->ArgsProduct({{16, 32, 40, 64, 128, 256}, {4, 6, 8}, {0}})
    ->ArgsProduct({{40, 128}, {8}, {1}})
    ->Unit(benchmark::kMillisecond);

// Dense active-set reference on the same problem; arg: n.
void BM_ContactPointDense(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const Grid g = PointGrid(n);
  const auto h = SphereGap(g, kPointRadius);
  HalfSpaceSolver tight_solver({1e-13, 20000});
  const auto tight = tight_solver.SolveForLoad(g, h, kPointLoad, kEStar);
  ContactSolution s;
  for (auto _ : state) {
    s = SolveDenseForLoad(g, h, kPointLoad, kEStar);
    benchmark::DoNotOptimize(s.pressure_MPa.data());  // (a double lvalue here is miscompiled with benchmark 1.7.1 + GCC)
  }
  PointCounters(state, g, s, tight);
}
BENCHMARK(BM_ContactPointDense)->Arg(16)->Arg(24)->Arg(32)->Arg(40)->Unit(benchmark::kMillisecond);

// First call on a new grid shape: FFTW planning (FFTW_ESTIMATE) + kernel spectrum + solve.
// arg 2: FFTW_MEASURE (1; FFTW keeps the wisdom in the process, so this times the
// measurement only on the first repetition — see the note in docs/performance.md).
void BM_ContactPointFirstCall(benchmark::State& state) {
  const Grid g = PointGrid(static_cast<int>(state.range(0)));
  const auto h = SphereGap(g, kPointRadius);
  SolverOptions options;
  options.measure_fft_plans = state.range(1) != 0;
  for (auto _ : state) {
    HalfSpaceSolver solver(options);
    benchmark::DoNotOptimize(solver.SolveForLoad(g, h, kPointLoad, kEStar).approach_mm);
  }
}
BENCHMARK(BM_ContactPointFirstCall)
    ->Args({40, 0})->Args({128, 0})->Args({40, 1})->Args({128, 1})
    ->Unit(benchmark::kMillisecond);

// The cycloid use: many calls on one grid with a slowly moving contact (the sphere's centre
// moves by a tenth of a cell per call), cold start versus warm start from the previous pressure.
void BM_ContactPointSequence(benchmark::State& state) {
  const Grid g = PointGrid(40);
  const bool warm = state.range(0) != 0;
  HalfSpaceSolver solver;
  std::vector<std::vector<double>> gaps;
  for (int k = 0; k < 20; ++k) gaps.push_back(SphereGap(g, kPointRadius, 0.1 * k * g.dx, 0.0));
  ContactSolution s = solver.SolveForLoad(g, gaps[0], kPointLoad, kEStar);
  double iterations = 0, calls = 0;
  for (auto _ : state) {
    for (const auto& h : gaps) {
      s = warm ? solver.SolveForLoad(g, h, kPointLoad, kEStar, s.pressure_MPa)
               : solver.SolveForLoad(g, h, kPointLoad, kEStar);
      iterations += s.iterations;
      calls += 1;
    }
  }
  state.counters["iters_per_call"] = iterations / calls;
  state.counters["calls"] = benchmark::Counter(calls, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ContactPointSequence)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// The cycloid outer iteration: one straight roller's grid (32 × 64), the load changing by a
// few per cent per call; cold start versus warm start from the previous pressure.
void BM_ContactRollerLoadSequence(benchmark::State& state) {
  const bool warm = state.range(0) != 0;
  const double b = LineContactHalfWidth(kRollerLoad, kRollerLength, kRollerRadius, kEStar);
  const Grid g = CenteredGrid(32, 64, 2.0 * b, 0.5 * kRollerLength);
  const auto h = CylinderGap(g, kRollerRadius);
  HalfSpaceSolver solver;
  ContactSolution s = solver.SolveForLoad(g, h, kRollerLoad, kEStar);
  double iterations = 0, calls = 0;
  for (auto _ : state) {
    for (int k = 0; k < 10; ++k) {
      const double load = kRollerLoad * (1.0 + 0.03 * k);
      s = warm ? solver.SolveForLoad(g, h, load, kEStar, s.pressure_MPa)
               : solver.SolveForLoad(g, h, load, kEStar);
      iterations += s.iterations;
      calls += 1;
    }
  }
  state.counters["iters_per_call"] = iterations / calls;
}
BENCHMARK(BM_ContactRollerLoadSequence)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// Straight roller on a flat (line contact); args: nx (over ±2b), ny (over the length L).
// Mid-face peak and half-width against Hertz line contact, and the edge peak with its dy.
void BM_ContactRollerCg(benchmark::State& state) {
  const int nx = static_cast<int>(state.range(0)), ny = static_cast<int>(state.range(1));
  const double b = LineContactHalfWidth(kRollerLoad, kRollerLength, kRollerRadius, kEStar);
  const double p_hertz = LineContactPeakPressure(kRollerLoad, kRollerLength, kRollerRadius, kEStar);
  const Grid g = CenteredGrid(nx, ny, 2.0 * b, 0.5 * kRollerLength);
  const auto h = CylinderGap(g, kRollerRadius);
  HalfSpaceSolver solver({1e-8, 20000});
  ContactSolution s = solver.SolveForLoad(g, h, kRollerLoad, kEStar);
  for (auto _ : state) {
    s = solver.SolveForLoad(g, h, kRollerLoad, kEStar);
    benchmark::DoNotOptimize(s.pressure_MPa.data());  // (a double lvalue here is miscompiled with benchmark 1.7.1 + GCC)
  }
  const int mid = ny / 2;  // the row just above the mid-plane
  const double w_mid = RowLineLoad(g, s, mid), p_mid = RowPeakPressure(g, s, mid);
  state.counters["iters"] = s.iterations;
  state.counters["wmid_over_FL"] = w_mid / (kRollerLoad / kRollerLength);
  state.counters["pmid_vs_FL_pct"] = Percent(p_mid, p_hertz);
  state.counters["pmid_vs_wmid_pct"] =
      Percent(p_mid, LineContactPeakPressure(w_mid, 1.0, kRollerRadius, kEStar));
  state.counters["bmid_vs_wmid_pct"] =
      Percent(RowHalfWidth(g, s, mid), LineContactHalfWidth(w_mid, 1.0, kRollerRadius, kEStar));
  state.counters["edge_peak_MPa"] = s.max_pressure_MPa;
  state.counters["dy_um"] = 1000.0 * s.dy_mm;
}
BENCHMARK(BM_ContactRollerCg)
    ->Args({16, 64})->Args({32, 64})->Args({64, 64})
    ->Args({32, 32})->Args({32, 128})->Args({32, 256})->Args({32, 512})->Args({32, 1024})
    ->Unit(benchmark::kMillisecond);

// The physical floor of a CG iteration: one forward and one backward 2D real FFT of the padded
// grid (arg: its side, 2 × the cells per side), FFTW_ESTIMATE as the solver plans them. A solve's
// iterations times this is the least its convolutions can cost (docs/performance.md, "Cycloid").
void BM_FftwPair(benchmark::State& state) {
  const int n = int(state.range(0));
  double* real = fftw_alloc_real(size_t(n) * size_t(n));
  fftw_complex* spec = fftw_alloc_complex(size_t(n) * size_t(n / 2 + 1));
  const fftw_plan forward = fftw_plan_dft_r2c_2d(n, n, real, spec, FFTW_ESTIMATE);
  const fftw_plan backward = fftw_plan_dft_c2r_2d(n, n, spec, real, FFTW_ESTIMATE);
  for (int i = 0; i < n * n; ++i) real[i] = std::sin(0.001 * i);
  for (auto _ : state) {
    fftw_execute(forward);
    fftw_execute(backward);
    benchmark::DoNotOptimize(real[0]);
    for (int i = 0; i < n * n; ++i) real[i] *= 1.0 / (double(n) * n);  // keep the values bounded
  }
  fftw_destroy_plan(forward);
  fftw_destroy_plan(backward);
  fftw_free(real);
  fftw_free(spec);
}
BENCHMARK(BM_FftwPair)->Arg(48)->Arg(80)->Arg(128)->Arg(256)->Unit(benchmark::kMicrosecond);

}  // namespace contact_bench
}  // namespace camopt::contact

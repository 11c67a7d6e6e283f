#include "model/common/torsional_dynamics.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>

#include "model/common/cvode.h"
#include "model/common/scalar.h"

namespace camopt::torsion {
namespace {

void Check(const TorsionalModel& m) {
  auto bad = [](const std::string& what) { throw std::invalid_argument("torsional dynamics: " + what); };
  if (!(m.input_inertia_kgm2 > 0) || !std::isfinite(m.input_inertia_kgm2)) bad("the input inertia must be > 0");
  if (!(m.output_inertia_kgm2 > 0) || !std::isfinite(m.output_inertia_kgm2)) bad("the output inertia must be > 0");
  if (!(m.ratio > 0) || !std::isfinite(m.ratio)) bad("the ratio must be > 0");
  if (!(m.input_shaft_stiffness_Nm_per_rad >= 0) || !std::isfinite(m.input_shaft_stiffness_Nm_per_rad))
    bad("the input shaft stiffness must be >= 0");
  if (!(m.damping_ratio >= 0) || !std::isfinite(m.damping_ratio)) bad("the damping ratio must be >= 0");
  if (!(m.mesh_period_rad > 0)) bad("the mesh period must be > 0");
  if (m.mesh_stiffness_Nm_per_rad.empty()) bad("no mesh stiffness");
  for (double k : m.mesh_stiffness_Nm_per_rad)
    if (!(k > 0) || !std::isfinite(k)) bad("the mesh stiffness must be > 0 at every angle");
  if (!m.static_te_rad.empty() && m.static_te_rad.size() != m.mesh_stiffness_Nm_per_rad.size())
    bad("the static transmission error needs one value per stiffness sample");
}

// The model at one speed, its state scaled: y = scale ∘ z (positions by a deflection, rates by it
// times the highest natural angular frequency), so that one absolute tolerance fits every state.
struct Data {
  const TorsionalModel* m = nullptr;
  double omega = 0;      // Ω, crank [rad/s]
  bool reduced = false;  // the free pair as δ alone (2 states), else {u₁, u₂, u̇₁, u̇₂}
  bool forced = true;    // false: the homogeneous system (Φ's columns)
  double motor = 0;      // i T_motor [N·m] (full model without input shaft)
  double j1 = 0, j2 = 0, mu = 0, ks = 0, cm = 0, cs = 0;
  std::array<double, 4> scale{1, 1, 1, 1};
  std::exception_ptr error;

  double Theta(double t) const { return omega * t; }
  // T_m at δ, δ̇ (physical units).
  double Mesh(double t, double d, double dd) const {
    const double th = Theta(t);
    const double k = PeriodicLinear(m->mesh_stiffness_Nm_per_rad, m->mesh_period_rad, th);
    if (!forced) return k * d + cm * dd;
    const double ds = m->static_te_rad.empty() ? 0.0 : PeriodicLinear(m->static_te_rad, m->mesh_period_rad, th);
    return m->reference_torque_Nm + k * (d - ds) + cm * dd;
  }
  int States() const { return reduced ? 2 : 4; }
  // Physical derivative of the physical state y.
  void Derivative(double t, const double* y, double* dy) const {
    const double tl = forced ? m->load_torque_Nm : 0.0;
    if (reduced) {
      // motor balancing the load: δ̈ = (T_L − T_m)/J₁' − (T_m − T_L)/J₂ = −(T_m − T_L)/μ
      dy[0] = y[1];
      dy[1] = -(Mesh(t, y[0], y[1]) - tl) / mu;
      return;
    }
    const double tm = Mesh(t, y[0] - y[1], y[2] - y[3]);
    const double drive = ks > 0 ? -ks * y[0] - cs * y[2] : (forced ? motor : 0.0);
    dy[0] = y[2];
    dy[1] = y[3];
    dy[2] = (drive - tm) / j1;
    dy[3] = (tm - tl) / j2;
  }
};

int Rhs(sunrealtype t, N_Vector zv, N_Vector dzv, void* user) {
  Data& d = *static_cast<Data*>(user);
  try {
    const double* z = N_VGetArrayPointer(zv);
    double* dz = N_VGetArrayPointer(dzv);
    double y[4], dy[4];
    const int n = d.States();
    for (int i = 0; i < n; ++i) y[i] = z[i] * d.scale[i];
    d.Derivative(t, y, dy);
    for (int i = 0; i < n; ++i) {
      dz[i] = dy[i] / d.scale[i];
      if (!std::isfinite(dz[i])) return 1;
    }
    return 0;
  } catch (...) {
    d.error = std::current_exception();
    return -1;
  }
}

void Setup(Data& d, const TorsionalModel& m, double input_speed_rpm, const Modes& modes) {
  d.m = &m;
  d.omega = input_speed_rpm * 2.0 * kPi / 60.0;
  d.j1 = m.input_inertia_kgm2 * m.ratio * m.ratio;
  d.j2 = m.output_inertia_kgm2;
  d.mu = d.j1 * d.j2 / (d.j1 + d.j2);
  d.ks = m.input_shaft_stiffness_Nm_per_rad * m.ratio * m.ratio;
  d.cm = modes.mesh_damping_Nms_per_rad;
  d.cs = modes.shaft_damping_Nms_per_rad;
  double te_max = 0.0;
  for (double x : m.static_te_rad) te_max = std::max(te_max, std::abs(x));
  const double kbar = modes.mean_stiffness_Nm_per_rad;
  double pos = (std::abs(m.reference_torque_Nm) + std::abs(m.load_torque_Nm)) / kbar + te_max;
  if (d.ks > 0) pos += std::abs(m.load_torque_Nm) / d.ks;
  if (!(pos > 0)) pos = 1e-6;
  const double w = 2.0 * kPi * modes.frequencies_Hz.back();
  d.scale = {pos, pos, pos * w, pos * w};
  if (d.reduced) d.scale = {pos, pos * w, 1, 1};
}

// Integrates from z0 (scaled) over [0, t_end]; `at` (ascending in [0, t_end]) the sample times,
// `sample(k, y physical)` called at each. Returns the scaled end state.
template <typename F>
std::vector<double> Integrate(Data& d, const std::vector<double>& z0, double t_end, double h_max,
                              const std::vector<double>& at, const IntegrationOptions& o, long& steps, F sample) {
  const int n = d.States();
  CvodeSolver sv;
  StartBdfDense(sv, z0.data(), n, Rhs, &d, o.relative_tolerance, 1e-3 * o.relative_tolerance, nullptr, 0,
                "torsional dynamics", CV_ADAMS);
  RequireCvode(CVodeSetMaxStep(sv.mem, h_max), "torsional dynamics", "CVodeSetMaxStep");
  RequireCvode(CVodeSetStopTime(sv.mem, t_end), "torsional dynamics", "CVodeSetStopTime");
  RequireCvode(CVodeSetMaxNumSteps(sv.mem, -1), "torsional dynamics", "CVodeSetMaxNumSteps");
  double t = 0.0;
  size_t next = 0;
  auto emit = [&](size_t k, const double* z) {
    double y[4] = {0, 0, 0, 0};
    for (int i = 0; i < n; ++i) y[i] = z[i] * d.scale[i];
    sample(k, y);
  };
  while (next < at.size() && at[next] <= 0.0) emit(next++, z0.data());
  long run_steps = 0;
  while (t < t_end) {
    double t_ret = t;
    const int flag = CVode(sv.mem, t_end, sv.y, &t_ret, CV_ONE_STEP);
    if (d.error) std::rethrow_exception(d.error);
    if (flag < 0)
      throw std::runtime_error("torsional dynamics: the integration failed at t = " + std::to_string(t) +
                               " s (CVODE flag " + std::to_string(flag) + ")");
    CVodeGetNumSteps(sv.mem, &run_steps);
    if (steps + run_steps > o.max_steps)
      throw std::runtime_error("torsional dynamics: more than " + std::to_string(o.max_steps) + " solver steps");
    for (; next < at.size() && at[next] <= t_ret; ++next) {
      RequireCvode(CVodeGetDky(sv.mem, at[next], 0, sv.dense), "torsional dynamics", "CVodeGetDky");
      emit(next, N_VGetArrayPointer(sv.dense));
    }
    t = t_ret;
    if (flag == CV_TSTOP_RETURN) break;
  }
  steps += run_steps;
  const double* z = N_VGetArrayPointer(sv.y);
  return std::vector<double>(z, z + n);
}

}  // namespace

double PeriodicLinear(const std::vector<double>& values, double period, double angle) {
  const size_t n = values.size();
  if (n == 1) return values[0];
  double x = std::fmod(angle / period, 1.0);
  if (x < 0) x += 1.0;
  const double s = x * double(n);
  size_t k = size_t(s);
  if (k >= n) k = n - 1;
  const double f = s - double(k);
  return values[k] + f * (values[(k + 1) % n] - values[k]);
}

double MeanOf(const std::vector<double>& values) {
  double s = 0.0;
  for (double v : values) s += v;
  return values.empty() ? 0.0 : s / double(values.size());
}

Modes LinearModes(const TorsionalModel& m) {
  Check(m);
  Modes out;
  const double kbar = MeanOf(m.mesh_stiffness_Nm_per_rad);
  out.mean_stiffness_Nm_per_rad = kbar;
  const double j1 = m.input_inertia_kgm2 * m.ratio * m.ratio, j2 = m.output_inertia_kgm2;
  const double ks = m.input_shaft_stiffness_Nm_per_rad * m.ratio * m.ratio;
  Eigen::Matrix2d k, mm;
  k << kbar + ks, -kbar, -kbar, kbar;
  mm << j1, 0.0, 0.0, j2;
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> es(k, mm);
  if (es.info() != Eigen::Success) throw std::runtime_error("torsional dynamics: the eigenproblem failed");
  const double lmax = es.eigenvalues().maxCoeff();
  for (int j = 0; j < 2; ++j) {
    const double l = es.eigenvalues()(j);
    if (l <= 1e-10 * lmax) continue;  // the free pair's rigid-body mode
    out.frequencies_Hz.push_back(std::sqrt(l) / (2.0 * kPi));
    Eigen::Vector2d v = es.eigenvectors().col(j);
    const int big = std::abs(v(0)) >= std::abs(v(1)) ? 0 : 1;
    v /= v(big);
    out.shapes.push_back({v(0), v(1)});
  }
  const double mu = j1 * j2 / (j1 + j2);
  out.mesh_damping_Nms_per_rad = 2.0 * m.damping_ratio * std::sqrt(kbar * mu);
  out.shaft_damping_Nms_per_rad = ks > 0 ? 2.0 * m.damping_ratio * std::sqrt(ks * j1) : 0.0;
  return out;
}

SteadyState PeriodicSteadyState(const TorsionalModel& m, double input_speed_rpm, const IntegrationOptions& o) {
  if (!(input_speed_rpm > 0) || !std::isfinite(input_speed_rpm))
    throw std::invalid_argument("torsional dynamics: the input speed must be > 0");
  const Modes modes = LinearModes(m);
  Data d;
  d.reduced = !(m.input_shaft_stiffness_Nm_per_rad > 0);
  Setup(d, m, input_speed_rpm, modes);
  const int n = d.States();
  SteadyState out;
  out.input_speed_rpm = input_speed_rpm;
  const double period = m.mesh_period_rad / d.omega;  // [s]
  out.mesh_frequency_Hz = 1.0 / period;
  const double f_max = modes.frequencies_Hz.back();
  const double table_step = period / double(m.mesh_stiffness_Nm_per_rad.size());
  const double h_max = std::min(table_step, 1.0 / (20.0 * f_max));

  // Φ (homogeneous, unit scaled states) and p (forced, from rest).
  Eigen::MatrixXd phi(n, n);
  d.forced = false;
  for (int j = 0; j < n; ++j) {
    std::vector<double> z0(n, 0.0);
    z0[j] = 1.0;
    const std::vector<double> z = Integrate(d, z0, period, h_max, {}, o, out.steps, [](size_t, const double*) {});
    for (int i = 0; i < n; ++i) phi(i, j) = z[i];
  }
  d.forced = true;
  const std::vector<double> pz = Integrate(d, std::vector<double>(n, 0.0), period, h_max, {}, o, out.steps,
                                           [](size_t, const double*) {});
  Eigen::VectorXd p(n);
  for (int i = 0; i < n; ++i) p(i) = pz[i];
  const Eigen::VectorXcd lambda = phi.eigenvalues();
  out.max_floquet_multiplier = lambda.cwiseAbs().maxCoeff();
  out.stable = out.max_floquet_multiplier < 1.0;
  if (!out.stable) return out;
  const Eigen::VectorXd x0 = (Eigen::MatrixXd::Identity(n, n) - phi).partialPivLu().solve(p);

  // The periodic solution once more, sampled: enough samples for the highest mode.
  int samples = std::max(o.samples_per_period, int(std::ceil(16.0 * f_max * period)));
  samples = std::min(samples, 2000000);
  samples += samples % 2;  // even: every other sample is the coarse set
  std::vector<double> at(size_t(samples) + 1);
  for (int k = 0; k <= samples; ++k) at[size_t(k)] = period * double(k) / double(samples);
  at.back() = period;
  std::vector<double> te(at.size()), tm(at.size());
  std::vector<double> z0(x0.data(), x0.data() + n);
  const std::vector<double> z_end = Integrate(d, z0, period, h_max, at, o, out.steps, [&](size_t k, const double* y) {
    const double del = d.reduced ? y[0] : y[0] - y[1];
    const double ddel = d.reduced ? y[1] : y[2] - y[3];
    te[k] = del;
    tm[k] = d.Mesh(at[k], del, ddel);
  });
  double res = 0.0, big = 0.0;
  for (int i = 0; i < n; ++i) res = std::max(res, std::abs(z_end[size_t(i)] - z0[size_t(i)])), big = std::max(big, std::abs(z0[size_t(i)]));
  out.periodicity_residual = res / std::max(big, 1e-300);
  auto span = [&](const std::vector<double>& v, int stride, double& lo, double& hi) {
    lo = hi = v[0];
    for (size_t k = 0; k < v.size(); k += size_t(stride)) lo = std::min(lo, v[k]), hi = std::max(hi, v[k]);
  };
  double lo, hi, lo2, hi2;
  span(te, 1, lo, hi);
  span(te, 2, lo2, hi2);
  out.te_peak_to_peak_rad = hi - lo;
  out.te_sampling_error_rad = std::abs((hi - lo) - (hi2 - lo2));
  double s = 0.0;
  for (size_t k = 0; k + 1 < te.size(); ++k) s += te[k];
  out.te_mean_rad = s / double(te.size() - 1);
  span(tm, 1, lo, hi);
  span(tm, 2, lo2, hi2);
  out.max_mesh_torque_Nm = hi;
  out.min_mesh_torque_Nm = lo;
  const double ref = m.reference_torque_Nm;
  out.overload_factor = ref != 0.0 ? hi / ref : 0.0;
  out.overload_sampling_error = ref != 0.0 ? std::abs(hi - hi2) / std::abs(ref) : 0.0;
  return out;
}

std::vector<TransientSample> Transient(const TorsionalModel& m, double input_speed_rpm, std::array<double, 4> y0,
                                       double motor_torque_Nm, const std::vector<double>& times,
                                       const IntegrationOptions& o) {
  if (!(input_speed_rpm >= 0) || !std::isfinite(input_speed_rpm))
    throw std::invalid_argument("torsional dynamics: the input speed must be >= 0");
  if (times.empty()) return {};
  for (size_t k = 1; k < times.size(); ++k)
    if (!(times[k] >= times[k - 1])) throw std::invalid_argument("torsional dynamics: times must ascend");
  const Modes modes = LinearModes(m);
  Data d;
  d.reduced = false;
  d.motor = motor_torque_Nm;
  Setup(d, m, input_speed_rpm, modes);
  std::vector<double> z0(4);
  for (int i = 0; i < 4; ++i) z0[size_t(i)] = y0[size_t(i)] / d.scale[size_t(i)];
  const double h_max = std::min(1.0 / (20.0 * modes.frequencies_Hz.back()),
                                d.omega > 0 ? m.mesh_period_rad / d.omega / double(m.mesh_stiffness_Nm_per_rad.size())
                                            : 1e300);
  std::vector<TransientSample> out(times.size());
  long steps = 0;
  Integrate(d, z0, times.back(), h_max, times, o, steps, [&](size_t k, const double* y) {
    out[k].t = times[k];
    for (int i = 0; i < 4; ++i) out[k].y[size_t(i)] = y[i];
    out[k].mesh_torque_Nm = d.Mesh(times[k], y[0] - y[1], y[2] - y[3]);
  });
  return out;
}

std::vector<ResonanceSpeed> ResonanceSpeeds(const Modes& modes, double mesh_period_rad, int harmonics, double lo_rpm,
                                            double hi_rpm) {
  std::vector<ResonanceSpeed> out;
  const double per_rev = 2.0 * kPi / mesh_period_rad;  // mesh periods per crank revolution
  for (size_t j = 0; j < modes.frequencies_Hz.size(); ++j)
    for (int h = 1; h <= harmonics; ++h) {
      const double rpm = 60.0 * modes.frequencies_Hz[j] / (double(h) * per_rev);
      if (!(rpm >= lo_rpm && rpm <= hi_rpm)) continue;
      ResonanceSpeed x;
      x.rpm = rpm;
      x.order = h;
      x.mode = int(j);
      x.frequency_Hz = modes.frequencies_Hz[j];
      out.push_back(x);
    }
  std::sort(out.begin(), out.end(), [](const ResonanceSpeed& a, const ResonanceSpeed& b) { return a.rpm < b.rpm; });
  return out;
}

}  // namespace camopt::torsion
